#!/usr/bin/env bash
# driver_fuzz.sh OCEAN BUILD_DIR OUT_DIR [RUNS] [SEED]: random command lines for the ./ocean driver
# (OCEAN, on BUILD_DIR's programs, never building), drawn with a fixed seed, so the same RUNS lines
# (default 500) every time, from a pool of commands, flags, step names, numbers and hostile words
# (quotes, $(...), backticks, ';', ../, .*, *, -1, 1e999, nan, empty, 5000 characters, newlines).
# Every line runs under OCEAN_DRY_RUN=1: the driver checks its arguments (compare, bench, figures,
# animations and gallery through tools/ocean_tools.py's argparse), prints what would run and stops,
# so nothing builds, renders or writes and a run takes milliseconds; diff, list and help only read,
# and half of their lines also run for real. Each run must:
#   exit 0, 1 or 2: never 124 (a hang), 126 and over (a command not found, a signal);
#   when it fails, print exactly one line on stderr, starting "ocean: error: " (every failure here
#   is the driver refusing its arguments);
#   print no message of bash's own, never create the canary the hostile words try to create, and
#   leave its TMPDIR empty.
# At the end the repository's `git status` (build/, screenshots/, __pycache__/ aside) is unchanged.
# A failing line is printed as the driver got it (%q; a long word cut short), to be replayed by hand.
set -u
ocean=$1 build=$2 out=$3 runs=${4:-500} seed=${5:-20240611}
repo=$(cd "$(dirname "$ocean")" && pwd)
rm -rf "$out" && mkdir -p "$out/tmp" || exit 1
out=$(cd "$out" && pwd)
tmp="$out/tmp"
canary="$out/CANARY"
export OCEAN_NO_BUILD=1 OCEAN_BUILD_DIR=$build
unset OCEAN_PRESET CI
bash_messages='unbound variable|parameter null or not set|command not found|cannot stat|syntax error|bad substitution|integer expression expected|value too great for base|invalid arithmetic|ambiguous redirect|line [0-9]+: '

repo_state() {
  git -C "$repo" status --porcelain --ignored=traditional -uall 2> /dev/null |
    grep -v -E '^.. "?(build/|screenshots/)|__pycache__/' | sort
}

mapfile -t steps < <(cd "$repo" && for f in step[0-9][0-9]_*/CMakeLists.txt; do dirname "$f"; done)
commands=(run test list compare bench new diff gallery figures animations exercise check web help --help nope '')
flags=(--time --size --camera --set --out --frames --sweep --resolutions --windows --against --baseline-bin --step
       --pairs --baseline-args --current-args --lab --seconds --hint --headless --list-params --nope -x --
       --all --help -h --out=-x --size=1x1 --current-args=--nope -L -R --port --no-serve)
names=("${steps[@]}" 'step0.*' 'step*' ../step01_sine2d 'step0[1]_sine2d' step99_none step08_new step_template)
values=(0 1 01 08 1.5 20 21 64 100 512 1000 -1 +1 1e999 1e3 nan inf -inf 0x0 480x270 16384x16384 16385x1 12by9 x
        99999999999999999999 overview deck sideways compute_shading HEAD HEAD~1 wind_speed=3 "=1" name=value
        "64 128" "320x180 0x0" "--time 1" "$build/step01_sine2d/step01_sine2d" "$out")
hostile=("'" '"' "\$(touch $canary)" "\`touch $canary\`" "; touch $canary" "1'; touch $canary; '" '$(touch CANARY)'
         ../ ../../x '.*' '*' '?' '[a]' '' ' ' "$(head -c 5000 /dev/zero | tr '\0' 'a')" $'a\nb' $'step01_sine2d\n'
         '|' '-' 'a b' $'\t' '\' '%s%n' '$HOME' '~' '!!' '{a,b}' 's/x/y/;e touch CANARY' $'\x01')

RANDOM=$seed
# draw: one word into $word from a pool chosen by weight (no subshell: $RANDOM must advance here).
draw() {
  local roll=$((RANDOM % 100))
  if [ "$roll" -lt 35 ]; then word=${flags[RANDOM % ${#flags[@]}]}
  elif [ "$roll" -lt 55 ]; then word=${names[RANDOM % ${#names[@]}]}
  elif [ "$roll" -lt 80 ]; then word=${values[RANDOM % ${#values[@]}]}
  else word=${hostile[RANDOM % ${#hostile[@]}]}
  fi
}

before=$(repo_state)
failures=0 refused=0 word=""
for ((run = 1; run <= runs; run++)); do
  argv=("${commands[RANDOM % ${#commands[@]}]}")
  for ((i = RANDOM % 6; i > 0; i--)); do draw; argv+=("$word"); done
  dry=1
  command=${argv[0]}
  if { [ "$command" = diff ] || [ "$command" = list ] || [ "$command" = help ]; } && [ $((RANDOM % 2)) = 0 ]; then dry=0; fi
  (cd "$out" && OCEAN_DRY_RUN=$dry TMPDIR=$tmp timeout 20 "$ocean" "${argv[@]}" > "$out/stdout" 2> "$out/stderr")
  status=$?
  problems=()
  case "$status" in
    0) ;;
    1|2) refused=$((refused + 1))
         [ "$(grep -c '' "$out/stderr")" -eq 1 ] || problems+=("$(grep -c '' "$out/stderr") lines on stderr, not 1")
         [[ $(tail -n 1 "$out/stderr") == "ocean: error: "* ]] || problems+=("the last line is not 'ocean: error: ...'") ;;
    *) problems+=("exit $status") ;;
  esac
  ! grep -Eq -- "$bash_messages" "$out/stderr" || problems+=("a message of bash's own")
  [ ! -e "$canary" ] && [ ! -e "$repo/CANARY" ] || { problems+=("the canary was created"); rm -f "$canary" "$repo/CANARY"; }
  [ -z "$(find "$tmp" -mindepth 1 -print -quit)" ] || { problems+=("left in TMPDIR"); rm -rf "${tmp:?}"/* "$tmp"/.[!.]*; }
  if [ ${#problems[@]} -gt 0 ]; then
    failures=$((failures + 1))
    printf 'FAIL run %d (OCEAN_DRY_RUN=%d):' "$run" "$dry"
    for word in "${argv[@]}"; do  # long words cut short: the seed replays them whole
      if [ ${#word} -le 60 ]; then printf ' %q' "$word"; else printf ' %q...(%d characters)' "${word:0:20}" ${#word}; fi
    done
    printf '\n'
    printf '     %s\n' "${problems[@]}"
    head -c 600 "$out/stderr" | sed 's/^/     stderr: /'
  fi
done
after=$(repo_state)
if [ "$after" != "$before" ]; then
  failures=$((failures + 1))
  echo "FAIL the repository changed:"; diff <(echo "$before") <(echo "$after") | grep '^[<>]' | head -n 10
fi
echo "driver_fuzz: $runs command lines (seed $seed), $refused refused, $failures failed"
[ "$failures" -eq 0 ]
