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
  > "$out/run.log" 2>&1 &
pid=$!
# Break it only once the step is drawing: its context line is printed before its programs build;
# then a few seconds for the first frames (a loaded machine is slow to start a step).
for _ in $(seq 60); do grep -q "OpenGL [0-9]" "$out/run.log" 2> /dev/null && break; sleep 0.5; done
sleep 3
printf '#version 450 core\nthis is not GLSL;\n' > "$victim"   # break it while the step runs
sleep 2
cp "$out/good.frag" "$victim" && touch "$victim"             # and mend it
sleep 2
kill -INT "$pid" 2> /dev/null  # ends the run loop like a closed window
wait "$pid"
status=$?
cat "$out/run.log"
grep -q "shader reload failed, keeping the last good" "$out/run.log" || { echo "FAIL: no reload failure reported"; exit 1; }
grep -q "$(basename "$victim"):2:" "$out/run.log" || { echo "FAIL: the error is not given as file:line"; exit 1; }
grep -q "reloaded" "$out/run.log" || { echo "FAIL: the mended shader was not reloaded"; exit 1; }
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status (the step should have kept running)"; exit 1; }
echo "ok: the step kept running through a broken shader and reloaded the mended one"
