#!/usr/bin/env bash
# frame_passes.sh BUILD_DIR STEP [--set ...]: the passes STEP's --bench times, in the order they
# first run, are the timed passes of its pass table (frame_passes.hpp, printed by the chapter's
# figure program: STEP_figures --timers), which draws the lesson's data-path figure. A pass added to the frame, removed or
# reordered without the table fails here, so the figure cannot drift from the code.
set -u
build=$1 step=$2
shift 2
expected=$("$build/$step/${step}_figures" --timers) || { echo "FAIL: no pass table for $step"; exit 1; }
log=$("$build/$step/$step" --headless --bench --frames 3 --size 160x90 "$@" 2>&1) || { echo "$log"; echo "FAIL: $step did not run"; exit 1; }
measured=$(echo "$log" | sed -n '/^bench: pass /,/^bench: all passes/p' | sed '1d;$d' | awk '{print $2}')
if [ "$measured" != "$expected" ]; then
  echo "FAIL: $step's --bench passes are not its pass table's"
  echo "--bench:"; echo "$measured" | sed 's/^/  /'
  echo "frame_passes.hpp:"; echo "$expected" | sed 's/^/  /'
  exit 1
fi
echo "$step: --bench times the passes of frame_passes.hpp, in order:" $measured
