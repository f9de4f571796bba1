#!/usr/bin/env bash
# exercise_programs.sh EXERCISE_EXE REPO OUT_DIR CASE: a learner's code that misbehaves gets its own
# one-line verdict from `exercise check`, and the check ends. Each case prepares an exercise, puts
# its misbehaving body in place of the starter's, and runs the check, which must exit 1 and print
# exactly one line on stdout: "fail: exercise N of STEP (title): " and the case's pattern (an
# extended regex). A case stopped at a time limit must have run at least that limit (read from the
# verdict: the limit was applied, not a crash) and ended within `slack` seconds of it (a C++
# exercise's slack is its compile). Two cases are not the learner's doing: quote_in_work_folder (the
# solution, in a folder whose name would run a command through a shell: it passes, no CANARY) and
# unwritable_check_file (a file the check cannot write: the tool's one error line).
set -u
exe=$(realpath "$1") repo=$2 out=$3 case=$4
rm -rf "$out"
mkdir -p "$out"
cd "$out" || exit 1  # the tool's folder: a command that a quote let through would write here
ulimit -f 65536      # 64 MiB: a checker that lost its own cap fails this test instead of filling the disk

# step07's C++ exercise 2: the starter's body is this line alone.
step=step07_buoyancy number=2 file=hull_forces.cpp stub='    return {};' slack=30  # slack: the compile
includes=$'#include <cmath>\n#include <cstdio>\n#include <cstdlib>\n'
timed=no work="$out/work"
case "$case" in
  endless_loop)
    body='    for (volatile unsigned long i = 0;; i = i + 1) {}'
    pattern="hull_forces.cpp ran longer than ([0-9.]+) s and was stopped: an endless loop\\?$" timed=yes ;;
  nan)
    body='    Wrench w; w.force.y = std::nan(""); return w;'
    pattern='case 0, value 1 is not a number: -?nan$' ;;
  infinite)
    body='    Wrench w; w.torque.x = HUGE_VAL; return w;'
    pattern='case 0, value 3 is infinite: inf$' ;;
  too_few_values)
    body='    static const bool once = std::printf("1 2 3\n") > 0; (void)once; return {};'
    pattern='case 0 has 3 values, not 6$' ;;
  too_many_values)
    body='    std::printf("7 "); return {};'
    pattern='case 0 has 7 values, not 6$' ;;
  too_few_lines)
    body='    static int calls = 0; if (++calls == 3) std::exit(0); return {};'
    pattern='the program printed 2 lines, not 200 \(one a case\)$' ;;
  extra_line)
    body='    static const int once = std::atexit([] { std::printf("0 0 0 0 0 0\n"); }); (void)once; return {};'
    pattern="the program printed a line after its 200 cases: '0 0 0 0 0 0'$" ;;
  garbage)
    body='    static const bool once = std::printf("1 2 abc 4 5 6\n") > 0; (void)once; return {};'
    pattern="case 0, value 2: 'abc' is not a number$" ;;
  abort)
    body='    std::abort();'
    pattern='hull_forces.cpp crashed: signal 6 \(Aborted\)$' ;;
  exit_status)
    body='    std::exit(3);'
    pattern='the check.s program exited with status 3' ;;
  print_forever)
    body='    for (;;) std::fputs("0 0 0 0 0 0\n", stdout);'
    pattern='hull_forces.cpp printed more than ([0-9]+) KiB and was stopped: does it print forever\?$' ;;
  unwritable_check_file)
    # Not the learner's fault: the shader the check writes cannot be written (a folder holds its
    # name). The GLSL check runs in a child process; its error must come back as the tool's one
    # error line, exit 1, and no verdict.
    step=step01_sine2d number=1 file=sine_sum.glsl ;;
  quote_in_work_folder)
    # Not a failure: the solution, in a folder whose name would end a quoted shell word and run a
    # command. It must pass, and no CANARY may appear.
    work="$out/it's; touch CANARY; '" body="" pattern="" ;;
  glsl_endless_loop)
    # step01's GLSL exercise 1, with a loop that never ends on a GPU. llvmpipe stops a shader's loops
    # after 65535 turns in all, so each turn does a thousand sines, on one thread (LP_NUM_THREADS):
    # about 6 minutes on this repository's CI machine, far past the limit on any CPU.
    step=step01_sine2d number=1 file=sine_sum.glsl stub='    return 0.0;' slack=10 includes="" timed=yes
    export LP_NUM_THREADS=1
    body='#define TEN h = sin(h + x); h = sin(h + x); h = sin(h + x); h = sin(h + x); h = sin(h + x); \
            h = sin(h + x); h = sin(h + x); h = sin(h + x); h = sin(h + x); h = sin(h + x);
#define HUNDRED TEN TEN TEN TEN TEN TEN TEN TEN TEN TEN
    float h = x;
    while (u_wave_count > 0) {
        HUNDRED HUNDRED HUNDRED HUNDRED HUNDRED HUNDRED HUNDRED HUNDRED HUNDRED HUNDRED
        if (h > 2.0) break;
    }
    return h;'
    pattern="the check of your shader ran longer than ([0-9.]+) s and was stopped: an endless loop\\?$" ;;
  *) echo "FAIL: no case '$case'"; exit 1 ;;
esac

"$exe" prepare "$step" "$number" "$work" > /dev/null || { echo "FAIL: prepare $step $number"; exit 1; }
source_text=$(< "$work/$file")
if [ "$case" = quote_in_work_folder ]; then
  cp "$repo/$step/$file" "$work/$file"
elif [ "$case" = unwritable_check_file ]; then
  mkdir -p "$work/.check.comp/a folder"
else
  [[ $source_text == *"$stub"* ]] || { echo "FAIL: the starter of $step $number has no line '$stub'"; exit 1; }
  printf '%s%s\n' "$includes" "${source_text/"$stub"/"$body"}" > "$work/$file"
fi

started=$(date +%s.%N)
timeout 120 "$exe" check "$step" "$number" "$work" > "$out/check.stdout" 2> "$out/check.stderr"
status=$?
elapsed=$(echo "$(date +%s.%N) - $started" | bc)
echo "exercise check $step $number ($case): exit $status after $elapsed s"
cat "$out/check.stdout"
head -c 2000 "$out/check.stderr"

if [ "$case" = quote_in_work_folder ]; then
  [ "$status" -eq 0 ] || { echo "FAIL: the solution does not pass in a folder named $work"; exit 1; }
  canaries=$(find "$out" "$repo" -maxdepth 1 -name CANARY)
  [ -z "$canaries" ] || { echo "FAIL: a quote in the work folder's name ran a command: $canaries"; exit 1; }
  echo "ok: the check ran no command from the folder's name"
  exit 0
fi
if [ "$case" = unwritable_check_file ]; then
  message=$(head -n 1 "$out/check.stderr")
  [ "$status" -eq 1 ] || { echo "FAIL: exit $status, not 1"; exit 1; }
  [ "$(grep -c '' "$out/check.stderr")" -eq 1 ] || { echo "FAIL: not one line on stderr"; exit 1; }
  [[ $message == "exercise: error: cannot write "*".check.comp"* ]] || { echo "FAIL: not the error line"; exit 1; }
  [ ! -s "$out/check.stdout" ] || { echo "FAIL: a verdict on stdout"; exit 1; }
  echo "ok: the file the check could not write is one error line"
  exit 0
fi
[ "$status" -eq 1 ] || { echo "FAIL: exit $status, not 1 (a failed check)"; exit 1; }
lines=$(grep -c '' "$out/check.stdout")
[ "$lines" -eq 1 ] || { echo "FAIL: $lines lines on stdout, not the one verdict"; exit 1; }
verdict=$(head -n 1 "$out/check.stdout")
prefix="fail: exercise $number of $step ("
[[ $verdict == "$prefix"* ]] || { echo "FAIL: the verdict does not start with '$prefix'"; exit 1; }
[[ $verdict =~ $pattern ]] || { echo "FAIL: the verdict does not match: $pattern"; exit 1; }
if [ "$timed" = yes ]; then
  limit=${BASH_REMATCH[1]}
  if [ "$(echo "$elapsed < $limit || $elapsed > $limit + $slack" | bc)" -eq 1 ]; then
    echo "FAIL: a limit of $limit s ended the check after $elapsed s (expected $limit to $limit + $slack s)"; exit 1
  fi
fi
if [ "$case" = print_forever ]; then
  size=$(stat -c %s "$work/check_output.txt") cap=$((BASH_REMATCH[1] * 1024))
  [ "$size" -le "$cap" ] || { echo "FAIL: the program wrote $size bytes, past the cap of $cap"; exit 1; }
fi
echo "ok: $case"
