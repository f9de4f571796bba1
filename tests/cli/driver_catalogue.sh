#!/usr/bin/env bash
# driver_catalogue.sh OCEAN BUILD_DIR OUT_DIR: every kind of bad input we know of, against the
# ./ocean driver (OCEAN, run on BUILD_DIR's programs, never building), from one table: what
# tests/cli/catalogue.sh does for each step's program. A row is one call of the driver:
#   fail NAME PATTERN ARGS...     a non-zero exit below 126 (no crash, no "command not found"),
#                                 exactly one line on stderr, "ocean: error: " with PATTERN (fixed
#                                 text) in it, and no message of bash's own
#   fail_env VAR=VALUE NAME PATTERN ARGS...   the same with VAR set
#   ok NAME ARGS...               exit 0: valid input, cheap to run for real
#   dry NAME ARGS...              exit 0 and a "dry run" line under OCEAN_DRY_RUN=1: valid input
#                                 whose real run would be long (the boundaries of each range)
#   dry_says NAME REGEX ARGS...   the same, the line matching REGEX (./ocean test's tiers)
# compare, bench, figures, animations and gallery are tools/ocean_tools.py's: argparse's messages,
# still one line each, "ocean: error: COMMAND: argument --flag: ..." (--help: exit 0, no build).
# After every row: the canary file that the hostile strings try to create does not exist, the
# row's own TMPDIR (an empty folder) is empty again, and `git status` of the repository (build/,
# screenshots/ and __pycache__/ aside: other tests write there) is what it was before the row.
# Last, Ctrl-C while the driver waits on a program: exit 130 and nothing left behind.
set -u
ocean=$1 build=$2 out=$3
repo=$(cd "$(dirname "$ocean")" && pwd)
rm -rf "$out" && mkdir -p "$out/tmp" || exit 1
out=$(cd "$out" && pwd)
canary="$out/CANARY"
export OCEAN_NO_BUILD=1 OCEAN_BUILD_DIR=$build
unset OCEAN_DRY_RUN OCEAN_PRESET CI
step01="$build/step01_sine2d/step01_sine2d"
huge=$(head -c 5000 /dev/zero | tr '\0' '9')
# What bash prints when a script lets it speak: these never reach a user.
bash_messages='unbound variable|parameter null or not set|command not found|cannot stat|syntax error|bad substitution|integer expression expected|value too great for base|invalid arithmetic|ambiguous redirect|line [0-9]+: '

repo_state() {
  git -C "$repo" status --porcelain --ignored=traditional -uall 2> /dev/null |
    grep -v -E '^.. "?(build/|screenshots/)|__pycache__/' | sort
}

failures=0 rows=0
# call NAME ENV...: runs the driver on the arguments in "${argv[@]}" with ENV, in a private TMPDIR;
# leaves its status, stdout and stderr, and whether it left anything behind (the shared checks).
call() {
  local name=$1
  shift
  tmp="$out/tmp/$name"
  mkdir -p "$tmp"
  local before
  before=$(repo_state)
  (cd "$out" && env "$@" TMPDIR="$tmp" timeout 60 "$ocean" "${argv[@]}" > "$out/$name.stdout" 2> "$out/$name.stderr")
  status=$?
  lines=$(grep -c '' "$out/$name.stderr")
  message=$(head -c 300 "$out/$name.stderr" | head -n 1)
  problems=()
  [ ! -e "$canary" ] || { problems+=("the canary was created"); rm -f "$canary"; }
  [ -z "$(ls -A "$tmp")" ] || problems+=("left in TMPDIR: $(ls -A "$tmp" | head -n 3 | tr '\n' ' ')")
  [ "$(repo_state)" = "$before" ] || problems+=("the repository changed: $(diff <(echo "$before") <(repo_state) | grep '^[<>]' | head -n 3 | tr '\n' ' ')")
  ! grep -Eq -- "$bash_messages" "$out/$name.stderr" || problems+=("a message of bash's own")
}

verdict() {  # verdict NAME: prints the row's line and counts it
  rows=$((rows + 1))
  local shown=ok
  if [ ${#problems[@]} -gt 0 ]; then shown=FAIL; failures=$((failures + 1)); fi
  printf '%-4s %-32s exit %3d, %d line(s): %s\n' "$shown" "$1" "$status" "$lines" "${message:0:110}"
  local problem
  for problem in "${problems[@]}"; do echo "       $problem"; done
}

fail_env() {
  local env_setting=$1 name=$2 pattern=$3
  shift 3
  argv=("$@")
  call "$name" "$env_setting"
  { [ "$status" -ne 0 ] && [ "$status" -lt 126 ]; } || problems+=("exit $status: not a refusal")
  [ "$lines" -eq 1 ] || problems+=("$lines lines on stderr, not 1")
  [[ $message == "ocean: error: "* ]] || problems+=("the line does not start with 'ocean: error: '")
  grep -qF -- "$pattern" "$out/$name.stderr" || problems+=("no '$pattern' in the message")
  verdict "$name"
}
fail() { fail_env OCEAN_DRY_RUN=0 "$@"; }  # a real run: refused before anything happens

ok() {
  local name=$1
  shift
  argv=("$@")
  call "$name" OCEAN_DRY_RUN=0
  [ "$status" -eq 0 ] || problems+=("exit $status, not 0")
  verdict "$name"
}

dry() {
  local name=$1
  shift
  argv=("$@")
  call "$name" OCEAN_DRY_RUN=1
  [ "$status" -eq 0 ] || problems+=("exit $status, not 0")
  grep -q '^ocean: dry run: ' "$out/$name.stdout" || problems+=("no 'ocean: dry run:' line")
  verdict "$name"
}

dry_says() {  # dry_says NAME REGEX ARGS...: a dry run whose line ends as REGEX (grep -E) says
  local name=$1 regex=$2
  shift 2
  argv=("$@")
  call "$name" OCEAN_DRY_RUN=1
  [ "$status" -eq 0 ] || problems+=("exit $status, not 0")
  grep -Eq -- "^ocean: dry run: .*$regex" "$out/$name.stdout" || problems+=("no dry run line with '$regex': $(head -c 200 "$out/$name.stdout")")
  verdict "$name"
}

# Hostile text: regular expressions, globs, quotes, command substitution, paths out of the tree.
sub="\$(touch $canary)" tick="\`touch $canary\`" semi="x; touch $canary" quote="1'; touch $canary; '"

# --- the command ---
fail unknown_command                 "unknown command 'nope'"        nope
fail empty_command                   "unknown command ''"            ''
fail command_substitution            "unknown command"               "$sub"
fail_env OCEAN_PRESET=../x bad_preset_env "OCEAN_PRESET is '../x'"  list
fail_env OCEAN_DRY_RUN=yes bad_dry_run_env "OCEAN_DRY_RUN is 'yes'" list
fail_env OCEAN_NO_BUILD=2 bad_no_build_env "OCEAN_NO_BUILD is '2'"  list
ok   list                            list
ok   help                            help
ok   dash_help                       --help
fail list_extra                      "list: takes no arguments"      list extra
fail help_extra                      "help: takes no arguments"      help "$sub"
# --- run ---
fail run_regex                       "run: unknown step 'step0.*'"   run 'step0.*'
fail run_glob                        "run: unknown step"             run 'step0?_sine2d'
fail run_path                        "run: unknown step '../step01_sine2d'" run ../step01_sine2d
fail run_substitution                "run: unknown step"             run "$sub"
fail run_newline                     "run: unknown step 'step01_sine2d?x'" run $'step01_sine2d\nx'
fail run_huge                        "run: unknown step '999"        run "$huge"
ok   run_list_params                 run step01_sine2d --list-params
dry  run_newest                      run --headless --frames 2
# --- test (its arguments are ctest's, passed on as words; the core tier unless --all or a selection) ---
dry  test_arguments                  test -R "x;$semi" -L "$sub"
dry_says test_core "-L core"         test
dry_says test_core_flags "-L core --output-on-failure" test --output-on-failure
dry_says test_all "-j $(nproc)\$"    test --all
dry_says test_all_flags "-j $(nproc) -j 1\$" test --all -j 1
dry_says test_selection "-j $(nproc) -R step01\$" test -R step01
dry_says test_selection_joined "-j $(nproc) --label-regex=gpu\$" test --label-regex=gpu
dry_says test_exclusion "-j $(nproc) -LE long\$" test -LE long
# --- compare (tools/ocean_tools.py: argparse's messages, one line, after "ocean: error: compare: ") ---
fail compare_bracket                 "compare: argument STEP: unknown step 'step0[1]_sine2d'" compare 'step0[1]_sine2d'
fail compare_glob                    "compare: argument STEP: unknown step" compare 'step[0-9][0-9]_*'
fail compare_not_utf8                "compare: argument STEP: unknown step" compare $'\xff'
fail compare_time_missing            "compare: argument --time: expected one argument" compare --time
fail compare_size_missing            "compare: argument --size: expected one argument" compare --size
fail compare_camera_missing          "compare: argument --camera: expected one argument" compare --camera
fail compare_set_missing             "compare: argument --set: expected one argument" compare --set
fail compare_out_missing             "compare: argument --out: expected one argument" compare --out
fail compare_time_word               "compare: argument --time: expects a decimal number in [0, 1000000000], got 'abc'" compare --time abc
fail compare_time_nan                "--time: expects a decimal"     compare --time nan
fail compare_time_inf                "--time: expects a decimal"     compare --time inf
fail compare_time_exponent           "--time: expects a decimal"     compare --time 1e999
fail compare_time_negative           "--time: expects a decimal"     compare --time -1
fail compare_time_huge               "--time: expects a decimal"     compare --time 99999999999999999999
fail compare_time_two_points         "--time: expects a decimal"     compare --time 1.5.2
fail compare_time_empty              "--time: expects a decimal"     compare --time ''
fail compare_time_substitution       "--time: expects a decimal"     compare --time "$sub"
fail compare_size_zero               "compare: argument --size: expects WxH, each side in [1, 16384], got '0x0'" compare --size 0x0
fail compare_size_negative           "argument --size: expected one argument" compare --size -5x10
fail compare_size_negative_joined    "--size: expects WxH"           compare --size=-5x10
fail compare_size_enormous           "--size: expects WxH"           compare --size 100000x100000
fail compare_size_over               "--size: expects WxH"           compare --size 16385x10
fail compare_size_garbage            "--size: expects WxH"           compare --size 12by9
fail compare_size_half               "--size: expects WxH"           compare --size 320x
fail compare_camera_unknown          "compare: argument --camera: invalid choice: 'sideways'" compare --camera sideways
fail compare_camera_pattern          "--camera: invalid choice"      compare --camera 'd*'
fail compare_set_no_equals           "compare: argument --set: expects name=value" compare --set amplitude
fail compare_set_no_name             "--set: expects name=value"     compare --set =1
fail compare_set_substitution        "--set: expects name=value"     compare --set "$sub=1"
fail compare_out_empty               "compare: argument --out: needs a folder, not an empty name" compare --out ''
fail compare_out_flag                "compare: argument --out: '-x' looks like a flag" compare --out=-x
fail compare_out_bar                 "a folder name with '|'"        compare --out 'a|b'
fail compare_out_unwritable          "compare: cannot make the folder '/proc/ocean'" compare step01_sine2d --size 64x36 --out /proc/ocean
fail compare_unknown_flag            "compare: unrecognized arguments: --nope" compare --nope
fail compare_abbreviation            "compare: unrecognized arguments: --si" compare --si
ok   compare_help                    compare --help
ok   compare_one_step_hostile_folder compare step01_sine2d --size 64x36 --out "$out/compare $sub $quote"
dry  compare_boundaries              compare step01_sine2d step07_buoyancy --time 0 --size 16384x1 --camera top --set wind_speed=3 --set "view=$sub"
dry  compare_steps_between_flags     compare step01_sine2d --size 64x36 step02_sine3d
dry  compare_longest_time            compare --time 1000000000 --size 1x16384
fail compare_time_over               "--time: expects a decimal"     compare --time 1000000000.5
# --- bench ---
fail bench_pairs_missing             "bench: argument --pairs: expected one argument" bench --pairs
fail bench_frames_missing            "bench: argument --frames: expected one argument" bench --frames
fail bench_size_missing              "bench: argument --size: expected one argument" bench --size
fail bench_out_missing               "bench: argument --out: expected one argument" bench --out
fail bench_step_missing              "bench: argument --step: expected one argument" bench --step
fail bench_lab_missing               "bench: argument --lab: expected one argument" bench --lab
fail bench_against_missing           "bench: argument --against: expected one argument" bench --against
fail bench_baseline_bin_missing      "bench: argument --baseline-bin: expected one argument" bench --baseline-bin
fail bench_baseline_args_missing     "bench: argument --baseline-args: expected one argument" bench --baseline-args
fail bench_current_args_missing      "bench: argument --current-args: expected one argument" bench --current-args
fail bench_resolutions_missing       "bench: argument --resolutions: expected one argument" bench --sweep --resolutions
fail bench_windows_missing           "bench: argument --windows: expected one argument" bench --sweep --windows
fail bench_frames_zero               "bench: argument --frames: expects a whole number in [1, 100000], got '0'" bench --frames 0
fail bench_frames_word               "--frames: expects a whole number" bench --frames abc
fail bench_frames_negative           "--frames: expects a whole number" bench --frames -1
fail bench_frames_exponent           "--frames: expects a whole number" bench --frames 1e3
fail bench_frames_decimal            "--frames: expects a whole number" bench --frames 2.5
fail bench_frames_huge               "--frames: expects a whole number" bench --frames 99999999999999999999
fail bench_frames_nan                "--frames: expects a whole number" bench --frames nan
fail bench_pairs_zero                "bench: argument --pairs: expects a whole number in [1, 1000]" bench --baseline-bin "$step01" --pairs 0
fail bench_pairs_over                "--pairs: expects a whole number" bench --baseline-bin "$step01" --pairs 1001
fail bench_size_bad                  "bench: argument --size: expects WxH" bench --size 0x720
fail bench_lab_regex                 "bench: argument --lab: no lab program 'x.*' (lab/CMakeLists.txt: compute_shading" bench --lab 'x.*'
fail bench_lab_sed                   "bench: argument --lab: no lab program" bench --lab 's/x/y/;e touch CANARY'
fail bench_lab_sed_command           "no lab program 'x/y/?1e touch" bench --lab $'x/y/\n1e touch '"$canary"$'\n#'
fail bench_lab_empty                 "bench: argument --lab: no lab program ''" bench --lab ''
fail bench_step_regex                "bench: argument --step: unknown step 'step0.*'" bench --baseline-bin "$step01" --step 'step0.*'
fail bench_step_regex_alone          "bench: argument --step: unknown step 'step0.*'" bench --step 'step0.*'
fail bench_step_alone                "bench: --step goes with --against or --baseline-bin" bench --step step01_sine2d
fail bench_pairs_alone               "bench: --pairs goes with"      bench --pairs 2
fail bench_flags_alone               "bench: --current-args goes with" bench --sweep --current-args '--time 1'
fail bench_resolutions_alone         "bench: --resolutions goes with --sweep" bench --resolutions 64
fail bench_windows_alone             "bench: --windows goes with --sweep" bench --lab compute_shading --windows 64x64
fail bench_against_flag              "bench: argument --against: expected one argument" bench --against -x
fail bench_against_flag_joined       "bench: argument --against: '-x' is not a revision" bench --against=-x
fail bench_against_substitution      "bench: argument --against: '\$(touch" bench --against "$sub"
fail bench_against_unknown           "is not a revision of this repository" bench --against no_such_branch_anywhere
fail bench_baseline_missing          "bench: argument --baseline-bin: '/no/such/program' is not a program" bench --baseline-bin /no/such/program
fail bench_baseline_folder           "is not a program"              bench --baseline-bin "$out"
fail bench_two_baselines             "bench: argument --baseline-bin: not allowed with argument --against" bench --against HEAD --baseline-bin "$step01"
fail bench_two_measurements          "bench: argument --lab: not allowed with argument --sweep" bench --sweep --lab compute_shading
fail bench_resolution_odd            "bench: argument --resolutions: '100' is not 64, 128, 256 or 512" bench --sweep --resolutions 100
fail bench_resolution_glob           "is not 64, 128, 256 or 512"    bench --sweep --resolutions '*'
fail bench_resolutions_empty         "--resolutions: needs at least one" bench --sweep --resolutions ' '
fail bench_window_bad                "bench: argument --windows: expects WxH" bench --sweep --windows '320x180 0x0'
fail bench_unknown                   "bench: unrecognized arguments: --nope" bench --nope
fail bench_stray_word                "bench: unrecognized arguments: step01_sine2d" bench step01_sine2d
ok   bench_help                      bench --help
dry  bench_table                     bench --frames 100000 --size 16384x16384
dry  bench_against_flags             bench --baseline-bin "$step01" --step step01_sine2d --pairs 1000 --baseline-args "--time 1 $sub" --current-args "$quote"
dry  bench_one_flag                  bench --baseline-bin "$step01" --current-args=--nope
dry  bench_lab                       bench --lab compute_shading --pairs 1
dry  bench_sweep                     bench --sweep --resolutions '64 512' --windows '1x1 16384x16384'
dry  bench_against_revision          bench --against HEAD --pairs 2
# --- new ---
fail new_nothing                     "new: give one name"            new
fail new_two                         "new: give one name"            new step08_a step09_b
fail new_regex                       "new: 'step0.*' is not stepNN_lowercase_name" new 'step0.*'
fail new_path                        "is not stepNN_lowercase_name"  new ../step08_out
fail new_upper                       "is not stepNN_lowercase_name"  new step08_Spray
fail new_substitution                "is not stepNN_lowercase_name"  new "step08_$sub"
fail new_existing                    "new: 'step01_sine2d' exists already" new step01_sine2d
fail new_same_number                 "new: another step01 step exists (step01_sine2d)" new step01_again
dry  new_valid                       new step98_catalogue_probe
# --- diff ---
fail diff_regex                      "diff: unknown step 'step0.*'"  diff 'step0.*' step02_sine3d
fail diff_words                      "diff: unknown step 'a'"        diff a b
fail diff_glob                       "diff: unknown step"            diff step04_fbm 'step0[5]_*'
fail diff_quote                      "diff: unknown step"            diff step04_fbm "'"
fail diff_substitution               "diff: unknown step"            diff "$sub" step02_sine3d
fail diff_backticks                  "diff: unknown step"            diff step01_sine2d "$tick"
fail diff_semicolon                  "diff: unknown step"            diff "$semi" step01_sine2d
fail diff_one                        "diff: give two steps"          diff step04_fbm
fail diff_three                      "diff: give two steps"          diff step04_fbm step05_fft step06_foam_sky
ok   diff_valid                      diff step04_fbm step05_fft
ok   diff_itself                     diff step01_sine2d step01_sine2d
# --- web ---
fail web_unknown_flag                "web: unknown flag '--bogus'"   web --bogus
fail web_port_missing                "web: --port needs a value"     web --port
fail web_port_low                    "--port expects a whole number in [1024, 65535], got '80'" web --port 80
fail web_port_over                   "--port expects a whole number" web --port 65536
fail web_port_text                   "--port expects a whole number" web --port '8080; rm -rf /'
dry  web                             web
dry  web_port_edges                  web --port 1024 --no-serve
dry  web_port_top                    web --port 65535
# --- gallery, figures, animations ---
fail gallery_extra                   "gallery: unrecognized arguments: --out x" gallery --out x
ok   gallery_help                    gallery --help
dry  gallery                         gallery
fail figures_out_missing             "figures: argument --out: expected one argument" figures --out
fail figures_out_empty               "figures: argument --out: needs a folder" figures --out ''
fail figures_unknown                 "figures: unrecognized arguments: x" figures x
dry  figures_hostile_folder          figures --out "$out/figures $sub"
fail animations_glob                 "animations: argument STEP: unknown step 'step*'" animations 'step*'
fail animations_seconds_missing      "animations: argument --seconds: expected one argument" animations --seconds
fail animations_size_missing         "animations: argument --size: expected one argument" animations --size
fail animations_out_missing          "animations: argument --out: expected one argument" animations --out
fail animations_seconds_zero         "animations: argument --seconds: expects a whole number in [1, 20], got '0'" animations --seconds 0
fail animations_seconds_over         "--seconds: expects a whole number" animations --seconds 21
fail animations_seconds_decimal      "--seconds: expects a whole number" animations --seconds 1.5
fail animations_seconds_nan          "--seconds: expects a whole number" animations --seconds nan
fail animations_seconds_negative     "--seconds: expects a whole number" animations --seconds -1
fail animations_size_bad             "animations: argument --size: expects WxH" animations --size 480x0
fail animations_unknown              "animations: unrecognized arguments: --fps" animations --fps
dry  animations_boundaries           animations step01_sine2d --seconds 20 --size 1x1
dry  animations_octal_looking        animations --seconds 08
# --- exercise and check ---
fail exercise_one_argument           "exercise: give a step and a number" exercise step06_foam_sky
fail exercise_letters                "exercise: the exercise number must be 1 to 999, got '2abc'" exercise step06_foam_sky 2abc
fail exercise_quote                  "the exercise number must be 1 to 999" exercise step06_foam_sky "$quote"
fail exercise_path                   "the exercise number must be 1 to 999, got '../../x'" exercise step06_foam_sky ../../x
fail exercise_zero                   "the exercise number must be 1 to 999" exercise step06_foam_sky 0
fail exercise_leading_zero           "the exercise number must be 1 to 999" exercise step06_foam_sky 01
fail exercise_thousand               "the exercise number must be 1 to 999" exercise step06_foam_sky 1000
fail exercise_negative               "the exercise number must be 1 to 999" exercise step06_foam_sky -1
fail exercise_step_regex             "exercise: unknown step 'step0.*'" exercise 'step0.*' 1
fail exercise_step_path              "exercise: unknown step"        exercise ../../step06_foam_sky 1
fail exercise_missing                "no exercise 99"                exercise step06_foam_sky 99
fail exercise_hint_extra             "exercise: --hint takes nothing after it" exercise step06_foam_sky 1 --hint x
ok   exercise_list                   exercise
ok   exercise_hint                   exercise step06_foam_sky 1 --hint
dry  exercise_with_flags             exercise step06_foam_sky 1 --camera low --set "view=$sub"
fail check_missing_exercise          "no exercise 99"                check step06_foam_sky 99
fail check_unknown_step              "check: unknown step 'nope'"    check nope 1
fail check_nothing                   "check: give a step and a number" check
fail check_three                     "check: give a step and a number" check step06_foam_sky 1 x
fail check_number                    "check: the exercise number must be 1 to 999" check step06_foam_sky "$sub"
dry  check_valid                     check step06_foam_sky 1
# No work folder yet: refused in one line (unless someone is doing that exercise in this tree).
if [ -e "$repo/exercises/work/step01_sine2d-2" ]; then
  echo "SKIP (printed, not silent): check_no_work_folder: exercises/work/step01_sine2d-2 exists in this tree"
else
  fail check_no_work_folder          "check: exercises/work/step01_sine2d-2 does not exist: start with ./ocean exercise step01_sine2d 2" check step01_sine2d 2
fi

# Ctrl-C while the driver waits on a program (the exercise tool, whose messages it holds until it
# ends): a build folder whose exercise tool says it started, then sleeps; SIGINT to the driver's
# process group, as a terminal sends it; then exit 130 and an empty TMPDIR (the driver writes no
# temporary file at all). Job control (set -m) gives the driver its own process group, and without
# it bash would start it with SIGINT ignored, as for any `&` job.
interrupted() {
  local fake="$out/interrupt_build" tmp="$out/tmp/interrupt" started="$out/interrupt.started" pid i
  mkdir -p "$fake/exercises" "$tmp"
  rm -f "$started"
  printf '#!/bin/sh
touch "%s"
sleep 30
' "$started" > "$fake/exercises/exercise"
  chmod +x "$fake/exercises/exercise"
  set -m
  OCEAN_BUILD_DIR=$fake TMPDIR=$tmp "$ocean" exercise > "$out/interrupt.stdout" 2> "$out/interrupt.stderr" &
  pid=$!
  set +m
  for ((i = 0; i < 100; i++)); do [ -e "$started" ] && break; sleep 0.1; done
  problems=()
  [ -e "$started" ] || problems+=("the exercise tool did not start within 10 s")
  kill -INT -- "-$pid" 2> /dev/null
  wait "$pid"
  status=$?
  lines=$(grep -c '' "$out/interrupt.stderr")
  message=$(head -n 1 "$out/interrupt.stderr")
  [ "$status" -eq 130 ] || problems+=("exit $status, not 130")
  [ -z "$(ls -A "$tmp")" ] || problems+=("left in TMPDIR after Ctrl-C: $(ls -A "$tmp" | tr '\n' ' ')")
  verdict interrupt_exits_130_and_leaves_nothing
}
interrupted

echo "driver_catalogue: $failures of $rows cases failed"
[ "$failures" -eq 0 ]
