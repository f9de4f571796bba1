#!/usr/bin/env bash
# exercise_catalogue.sh EXERCISE_EXE OUT_DIR: every kind of bad command line we know of, against the
# exercise tool, from one table (as catalogue.sh does for the steps). Each row: the case, a text the
# message must hold, the arguments. Every row must exit non-zero without a crash or a hang, print
# exactly one line on stderr, "exercise: error: " and that text, nothing on stdout, and write no
# file: it runs in an empty folder three levels down in OUT_DIR (so that '../../x' lands inside
# OUT_DIR too), and OUT_DIR must be as it was afterwards (no CANARY from the quote, no work folder).
set -u
exe=$(realpath "$1") out=$2
rm -rf "$out"
here="$out/a/b/sandbox"
mkdir -p "$here"
work="$here/work"  # a work folder no row may create
printf 'a file, not a folder\n' > "$out/a_file"

names=() patterns=() argvs=()
row() {
  names+=("$1") patterns+=("$2")
  shift 2
  if [ $# -gt 0 ]; then argvs+=("$(printf '%q ' "$@")"); else argvs+=(""); fi
}
row n_letters "N must be a whole number" check step01_sine2d 2abc "$work"
row n_zero "N must be a whole number" check step01_sine2d 0 "$work"
row n_negative "N must be a whole number" check step01_sine2d -1 "$work"
row n_plus "N must be a whole number" check step01_sine2d +2 "$work"
row n_space "N must be a whole number" check step01_sine2d " 2" "$work"
row n_leading_zero "N must be a whole number" prepare step01_sine2d 02 "$work"
row n_exponent "N must be a whole number" check step01_sine2d 1e1 "$work"
row n_huge "N must be a whole number" check step01_sine2d 99999999999999999999 "$work"
row n_quote "N must be a whole number" prepare step07_buoyancy "2'; touch CANARY; '" "$work"
row n_path "N must be a whole number" prepare step01_sine2d ../../step01_sine2d "$work"
row n_empty "N must be a whole number" check step01_sine2d "" "$work"
row n_newline "N must be a whole number" hint step01_sine2d $'1\n2'
row n_unknown "step01_sine2d has no exercise 7; it has 1, 2" check step01_sine2d 7 "$work"
row hint_letters "N must be a whole number" hint step01_sine2d 2abc
row flags_letters "N must be a whole number" flags step05_fft 3x
row step_unknown "no step 'nope' has exercises" check nope 1 "$work"
row step_pattern "no step 'step0.*' has exercises" check 'step0.*' 1 "$work"
row step_path "no step 'step01_sine2d/../step02_sine3d'" prepare step01_sine2d/../step02_sine3d 1 "$work"
row step_empty "no step '' has exercises" hint "" 1
row step_quote "no step" prepare "step01_sine2d'; touch CANARY; '" 1 "$work"
row work_empty "WORK_DIR is empty" prepare step01_sine2d 1 ""
row work_under_a_file "cannot make the folder" prepare step01_sine2d 1 "$out/a_file/work"
row missing_work "check takes STEP N WORK_DIR; given 2" check step01_sine2d 1
row missing_number "hint takes STEP N; given 1" hint step01_sine2d
row missing_verb "no verb"
row extra_argument "prepare takes STEP N WORK_DIR; given 4" prepare step01_sine2d 1 "$work" extra
row extra_after_list "list takes no arguments; given 1" list step01_sine2d
row unknown_verb "unknown verb 'run'" run step01_sine2d 1
row check_before_prepare "sine_sum.glsl does not exist: start with ./ocean exercise step01_sine2d 1" check step01_sine2d 1 "$work"

before=$(cd "$out" && find . | sort)
failures=0
for i in "${!names[@]}"; do
  name=${names[$i]} pattern=${patterns[$i]}
  eval "argv=(${argvs[$i]})"
  # A hang is a failure too (exit 124), not a test that runs into ctest's timeout.
  (cd "$here" && timeout 60 "$exe" "${argv[@]}") > "$out/$name.stdout" 2> "$out/$name.stderr"
  status=$?
  lines=$(grep -c '' "$out/$name.stderr")
  message=$(head -c 300 "$out/$name.stderr" | head -n 1)
  after=$(cd "$out" && find . ! -name '*.stdout' ! -name '*.stderr' | sort)
  verdict=ok why=""
  if [ "$status" -eq 0 ] || [ "$status" -ge 124 ]; then verdict=FAIL why="exit $status"
  elif [ "$lines" -ne 1 ]; then verdict=FAIL why="$lines lines on stderr"
  elif [[ $message != "exercise: error: "* ]]; then verdict=FAIL why="not an 'exercise: error: ' line"
  elif ! grep -qF -- "$pattern" "$out/$name.stderr"; then verdict=FAIL why="no '$pattern'"
  elif [ -s "$out/$name.stdout" ]; then verdict=FAIL why="it printed on stdout"
  elif [ "$after" != "$before" ]; then verdict=FAIL why="it wrote: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
  fi
  printf '%-4s %-22s exit %3d, %d line(s): %s%s\n' "$verdict" "$name" "$status" "$lines" "${message:0:120}" \
    "${why:+   <- $why}"
  [ "$verdict" = ok ] || failures=$((failures + 1))
  rm -rf "$work" "$here/CANARY"  # so that one row's leftovers do not fail the next
done
echo "exercise catalogue: $failures of ${#names[@]} cases failed"
[ "$failures" -eq 0 ]
