#!/usr/bin/env bash
# catalogue.sh STEP_EXE OUT_DIR: every kind of bad input we know of, against one step, from one
# table. Each row: the case, what must happen, a pattern the message must match, the arguments.
#   fail: a non-zero exit that is not a crash, exactly one line on stderr, "error: " + pattern
#   warn: exit 0, and a "warning: " line matching the pattern (a safe fallback)
#   ok:   exit 0 (input that looks odd but is valid)
set -u
exe=$1 out=$2
mkdir -p "$out"
step=$(basename "$exe")
params=$("$exe" --list-params)
# A number parameter with a range starting at 0 or above, and an int and a choice when the step has them.
number=$(echo "$params" | awk 'NR > 1 && $3 ~ /^\[[0-9]/ && $2 ~ /\./ { print $1; exit }')
[ -n "$number" ] || number=$(echo "$params" | awk 'NR > 1 && $3 ~ /^\[[0-9]/ { print $1; exit }')
choice=$(echo "$params" | awk 'NR > 1 && $3 ~ /\|/ && $3 !~ /true\|false/ { print $1; exit }')

printf '' > "$out/empty.preset"
printf '%s = ' "$number" > "$out/truncated.preset"      # cut off mid-line
printf '%s = 1\n\x00\x01\x02garbage' "$number" > "$out/binary.preset"
mkdir -p "$out/a_directory.preset"
default=$(echo "$params" | awk -v n="$number" '$1 == n { print $2; exit }')
printf '\xEF\xBB\xBF%s = %s\n' "$number" "$default" > "$out/bom.preset"  # saved by an editor with a BOM
rm -f "$out/a.fifo"; mkfifo "$out/a.fifo"                                   # a preset that never ends
head -c 2000000 /dev/zero | tr '\0' '#' > "$out/huge.preset"               # 2 MB of comment
huge=$(head -c 20000 /dev/zero | tr '\0' '9')

rows=(
  "unknown_flag|fail|unknown flag|--nope"
  "short_flag|fail|unknown flag|-x"
  "positional|fail|unknown flag|stray"
  "flag_without_value|fail|--frames needs a value|--frames"
  "flag_with_stray_value|fail|--headless takes no value|--headless=1"
  "paused_with_a_value|fail|--paused takes no value|--paused=yes"
  "unknown_param|fail|unknown parameter 'nope'|--set nope=1"
  "no_equals|fail|--set expects name=value|--set $number"
  "not_a_number|fail|expects a number|--set $number=abc"
  "nan|fail|must be a finite number|--set $number=nan"
  "infinity|fail|must be a finite number|--set $number=inf"
  "minus_infinity|fail|must be a finite number|--set $number=-inf"
  "negative|fail|is outside its range|--set $number=-1e-3"
  "enormous|fail|is outside its range|--set $number=1e300"
  "huge_string|fail|parameter '$number'|--set $number=$huge"
  "huge_name|fail|unknown parameter|--set $huge=1"
  "size_zero|fail|--size expects each side|--size 0x0"
  "size_negative|fail|--size expects each side|--size -5x10"
  "size_enormous|fail|--size expects each side|--size 100000x100000"
  "size_garbage|fail|--size expects WIDTHxHEIGHT|--size 12by9"
  "size_half|fail|--size expects WIDTHxHEIGHT|--size 320x"
  "frames_zero|fail|--frames expects|--frames 0"
  "time_negative|fail|--time expects|--time -4"
  "dt_nan|fail|--dt expects|--dt nan"
  "screenshot_not_png|fail|--screenshot expects a path ending in .png|--screenshot out.jpg"
  "screenshot_unwritable|fail|cannot write|--frames 1 --size 32x18 --screenshot /proc/no/such.png"
  "camera_unknown|fail|--camera|--camera sideways"
  "preset_missing|fail|cannot read preset|--preset $out/missing.preset"
  "preset_directory|fail|is a directory|--preset $out/a_directory.preset"
  "preset_truncated|fail|truncated.preset:1: parameter|--preset $out/truncated.preset"
  "preset_binary|fail|not a text file|--preset $out/binary.preset"
  "preset_empty|ok||--preset $out/empty.preset --frames 1 --size 32x18"
  "preset_with_bom|ok||--preset $out/bom.preset --frames 1 --size 32x18"
  "preset_urandom|fail|not a regular file|--preset /dev/urandom"
  "preset_fifo|fail|not a regular file|--preset $out/a.fifo"
  "preset_too_large|fail|larger than 1024 KiB|--preset $out/huge.preset"
  "save_preset_unwritable|fail|cannot write preset|--save-preset /proc/no/such.preset"
  "shader_dir_missing|fail|shader directory|--shader-dir $out/no-such-dir --frames 1"
)
if [ -n "$choice" ]; then rows+=("choice_unknown|fail|expects one of|--set $choice=nonsense"); fi
if echo "$params" | grep -q '^sky_image '; then
  printf '' > "$out/empty.png"
  rows+=("sky_image_empty|warn|sky_image|--set sky_image=$out/empty.png --frames 1 --size 32x18"
         "sky_image_directory|warn|is a directory|--set sky_image=$out --frames 1 --size 32x18"
         "sky_image_missing|warn|No such file|--set sky_image=$out/none.hdr --frames 1 --size 32x18")
fi
if [ "$(id -u)" -eq 0 ]; then
  echo "SKIP (printed, not silent): an unreadable preset cannot be tested as root, who reads everything"
else
  printf '%s = 1\n' "$number" > "$out/unreadable.preset"; chmod 000 "$out/unreadable.preset"
  rows+=("preset_unreadable|fail|Permission denied|--preset $out/unreadable.preset")
fi

failures=0
for row in "${rows[@]}"; do
  IFS='|' read -r name expect pattern args <<< "$row"
  read -r -a argv <<< "$args"
  # A hang is a failure too (exit 124), not a test that runs into ctest's timeout.
  timeout 60 "$exe" --headless "${argv[@]}" > "$out/$name.stdout" 2> "$out/$name.stderr"
  status=$?
  lines=$(grep -c '' "$out/$name.stderr")
  message=$(head -c 300 "$out/$name.stderr" | head -n 1)
  verdict=ok
  case "$expect" in
    fail)
      if [ "$status" -eq 0 ] || [ "$status" -ge 128 ] || [ "$lines" -ne 1 ] ||
         [[ $message != "error: "* ]] || ! grep -qF -- "$pattern" "$out/$name.stderr"; then verdict=FAIL; fi ;;
    warn)
      if [ "$status" -ne 0 ] || ! grep -q "^warning: .*$pattern" "$out/$name.stderr"; then verdict=FAIL; fi ;;
    ok)
      [ "$status" -eq 0 ] || verdict=FAIL ;;
  esac
  printf '%-4s %-24s exit %3d, %d line(s): %s\n' "$verdict" "$name" "$status" "$lines" "${message:0:110}"
  [ "$verdict" = ok ] || failures=$((failures + 1))
done
echo "catalogue: $step: $failures of ${#rows[@]} cases failed"
[ "$failures" -eq 0 ]
