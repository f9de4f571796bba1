#!/usr/bin/env bash
# hot_reload.sh STEP_EXE STEP_DIR OUT_DIR: runs the step on a copy of its shaders, breaks one while
# it runs, and checks that it kept running on the last good program (exit 0, a picture that is not
# blank), printed the compiler's error as file:line, and reloaded again once the file was fixed.
set -u
exe=$1 step_dir=$2 out=$3
rm -rf "$out" && mkdir -p "$out" && cp -r "$step_dir/shaders" "$out/shaders"
victim="$out/shaders/ocean.frag"
[ -f "$victim" ] || victim=$(ls "$out"/shaders/*.frag | head -n 1)
cp "$victim" "$out/good.frag"
"$exe" --headless --frames 100000000 --size 96x54 --shader-dir "$out/shaders" --screenshot "$out/last.png" \
  --resource-log 1 > "$out/run.log" 2>&1 &
pid=$!
# Each step waits for what the step prints (a frame drawn, the failure seen, the reload), not for
# a fixed time: under ASan on a loaded machine a frame can take longer than any fixed sleep.
wait_for() { for _ in $(seq 240); do grep -q "$1" "$out/run.log" 2> /dev/null && return; sleep 0.25; done; }
wait_for "resources: frame 2 "                                 # the step is drawing
printf '#version 450 core\nthis is not GLSL;\n' > "$victim"   # break it while the step runs
wait_for "shader reload failed"
cp "$out/good.frag" "$victim" && touch "$victim"             # and mend it
wait_for "reloaded"
kill -INT "$pid" 2> /dev/null  # ends the run loop like a closed window
wait "$pid"
status=$?
cat "$out/run.log"
grep -q "shader reload failed, keeping the last good" "$out/run.log" || { echo "FAIL: no reload failure reported"; exit 1; }
grep -q "$(basename "$victim"):2:" "$out/run.log" || { echo "FAIL: the error is not given as file:line"; exit 1; }
grep -q "reloaded" "$out/run.log" || { echo "FAIL: the mended shader was not reloaded"; exit 1; }
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status (the step should have kept running)"; exit 1; }
echo "ok: the step kept running through a broken shader and reloaded the mended one"
