#!/usr/bin/env bash
# full_disk.sh BUILD_DIR REPO OUT_DIR: every kind of file the programs write, written onto a full
# disk. Each writer runs twice, each time in a fresh folder:
#   as it is: it must succeed, print its success line and write TARGET, larger than LIMIT KiB;
#   under `ulimit -f LIMIT` with SIGXFSZ ignored (an ignored signal stays ignored across exec): the
#   write that takes TARGET past LIMIT KiB fails with EFBIG, a real failed write through the kernel
#   as on a full disk, with no test hook in the code. The run must exit non-zero without a crash,
#   print exactly one line on stderr (the program's prefix, "cannot write", TARGET and the
#   reason), print no success line for the operation, and leave no TARGET (or, where TARGET was
#   there before, leave it as it was) and no .partial- file behind.
set -u
rm -rf "$3" && mkdir -p "$3"
# Absolute: each run starts in its own folder.
build=$(cd "$1" && pwd) repo=$(cd "$2" && pwd) out=$(cd "$3" && pwd)
failures=0 cases=0

# writer NAME LIMIT_KB TARGET PREFIX SUCCESS [keep] -- COMMAND...: one writer, as above. TARGET is
# relative to the run's folder; SUCCESS, an extended regular expression for the operation's line on
# stdout (empty: the program prints none). "keep": TARGET is there before the failing run (the
# good run's file) and must be byte for byte the same after it.
writer() {
  local name=$1 limit=$2 target=$3 prefix=$4 success=$5 keep=no
  shift 5
  [ "$1" = keep ] && { keep=yes; shift; }
  shift  # --
  local dir="$out/$name" problems=()
  cases=$((cases + 1))
  mkdir -p "$dir/good" "$dir/full"
  (cd "$dir/good" && exec timeout 120 "$@") > "$dir/good.stdout" 2> "$dir/good.stderr"
  local status=$? size
  size=$(stat -c %s "$dir/good/$target" 2> /dev/null || echo 0)
  [ "$status" -eq 0 ] || problems+=("without a limit it failed (exit $status): $(head -n 1 "$dir/good.stderr")")
  [ "$size" -gt $((limit * 1024)) ] || problems+=("without a limit $target is $size bytes, not over the limit of $limit KiB")
  [ -z "$success" ] || grep -Eq "$success" "$dir/good.stdout" || problems+=("without a limit no line matches '$success'")
  if [ ${#problems[@]} -eq 0 ]; then
    [ "$keep" = yes ] && mkdir -p "$(dirname "$dir/full/$target")" && cp "$dir/good/$target" "$dir/full/$target"
    full_disk_run "$@"
  fi
  report
}

# The run under the limit, and what it must (not) leave; adds to `problems`. It and report() see
# writer's locals (bash scopes them dynamically).
full_disk_run() {
  (cd "$dir/full" && trap '' XFSZ && ulimit -f "$limit" && exec timeout 120 "$@") > "$dir/full.stdout" 2> "$dir/full.stderr"
  status=$?
  local lines message
  lines=$(grep -c '' "$dir/full.stderr")
  message=$(head -c 300 "$dir/full.stderr" | head -n 1)
  { [ "$status" -ne 0 ] && [ "$status" -lt 124 ]; } || problems+=("exit $status, not a failure (1..123)")
  [ "$lines" -eq 1 ] || problems+=("$lines lines on stderr, not 1")
  [[ $message == "$prefix"* ]] || problems+=("stderr does not start with '$prefix'")
  [[ $message == *"cannot write"*"$target"*"File too large"* ]] ||
    problems+=("the message does not say 'cannot write', $target and why (File too large)")
  if [ -n "$success" ] && grep -Eq "$success" "$dir/full.stdout"; then
    problems+=("a success line: $(grep -E "$success" "$dir/full.stdout" | head -n 1)")
  fi
  if [ "$keep" = yes ]; then
    cmp -s "$dir/good/$target" "$dir/full/$target" || problems+=("$target was there before and is not as it was")
  elif [ -e "$dir/full/$target" ]; then
    problems+=("$target left behind ($(stat -c %s "$dir/full/$target") bytes)")
  fi
  local partial
  partial=$(find "$dir/full" -name '*.partial-*' | head -n 1)
  [ -z "$partial" ] || problems+=("a temporary file left behind: ${partial#"$dir/full/"}")
}

report() {
  local message
  message=$(head -c 300 "$dir/full.stderr" 2> /dev/null | head -n 1)
  if [ ${#problems[@]} -eq 0 ]; then
    printf 'ok   %-22s %s\n' "$name" "$message"
  else
    failures=$((failures + 1))
    printf 'FAIL %-22s %s\n' "$name" "$message"
    printf '       %s\n' "${problems[@]}"
  fi
}

step01=$build/step01_sine2d/step01_sine2d
step02_figures=$build/step02_sine3d/step02_sine3d_figures
step05=$build/step05_fft/step05_fft
step06=$build/step06_foam_sky/step06_foam_sky
step07=$build/step07_buoyancy/step07_buoyancy
tools=$build/tools
small=(--headless --frames 2 --size 16x16 --set resolution=64)  # the exports' maps: 16 KiB each
picture=$repo/step01_sine2d/golden.png
other=$repo/step02_sine3d/golden.png  # the same size: two frames of an animation
printf 'step,size,fps,total_ms,passes\nstep01_sine2d,64x36,60,16.6,plot=10;ocean=6.6\n' > "$out/bench.csv"

# The steps. The screenshot of 64x36 is about 4 KiB, a recorded frame too, a preset over 2 KiB.
writer screenshot 1 shot.png "error: " '^screenshot: ' -- "$step01" --headless --frames 2 --size 64x36 --screenshot shot.png
writer record 1 rec/frame_0000.png "error: " '^screenshot: ' -- "$step01" --headless --frames 2 --size 64x36 --record rec
writer save_preset 1 sea.preset "error: " '^preset: ' -- "$step01" --save-preset sea.preset
writer save_preset_over_old 1 sea.preset "error: " '^preset: ' keep -- "$step01" --save-preset sea.preset
# The exports: the first map cannot be written (export.txt comes last, so there is none either).
writer step05_export 1 maps/height.pfm "error: " '^export: ' -- "$step05" "${small[@]}" --screenshot s.png --export maps
writer step06_export 1 maps/height.pfm "error: " '^export: ' -- "$step06" "${small[@]}" --screenshot s.png --export maps
# step07: 100 frames of three bodies make trajectories.csv (about 30 KiB) the only file over
# 20 KiB; step06's maps and export.txt before it are written. Four patches a side: the bodies read
# the maps, not the mesh, and llvmpipe's tessellator is slow under ASan (tests/floats.sh).
writer step07_trajectories 20 maps/trajectories.csv "error: " '^export: ' -- \
  "$step07" --headless --frames 100 --size 16x16 --set resolution=64 --set patch_count=4 --screenshot s.png --export maps
# The tools: they print their own name, and image_panel, contact_sheet and bench_chart no success line.
writer animate 1 out.webp "animate: " 'out.webp: [0-9]+ frames' -- "$tools/animate" out.webp 10 60 "$picture" "$other"
writer image_panel 1 panel.png "image_panel: " '' -- "$tools/image_panel" panel.png 160x90 1 "a|$picture"
writer contact_sheet 1 sheet.png "contact_sheet: " '' -- "$tools/contact_sheet" sheet.png 32x18 "step01|$picture|$other"
writer bench_chart 1 bench.png "bench_chart: " '' -- "$tools/bench_chart" "$out/bench.csv" bench.png
# A chapter's figure program, step02's: directional_wave.dat (3 MB) is the only file over 100 KiB.
writer step02_figures 100 figures/step02_sine3d/directional_wave.dat "step02_sine3d_figures: " 'figures.* in ' -- \
  "$step02_figures" figures

echo "full_disk: $failures of $cases writers failed"
[ "$failures" -eq 0 ]
