#!/usr/bin/env bash
# windowed.sh STEP_EXE: runs the step in a real GLFW window on a virtual X server (Xvfb) for a
# few frames, minimising the window at frame 2 and restoring it at frame 3 (--simulate-minimise:
# the frames in between see a 0 x 0 framebuffer). No GL error allowed. Exit 77 (ctest: skipped)
# with the reason printed when xvfb-run is missing.
set -u
exe=$1
if ! command -v xvfb-run > /dev/null; then
  echo "SKIP: xvfb-run not found, the windowed run was not tested (apt-get install xvfb xauth)"
  exit 77
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
xvfb-run -a -s "-screen 0 1024x768x24" "$exe" --frames 6 --size 320x180 --time 1.5 --simulate-minimise \
  --screenshot "$out/window.png" > "$out/log" 2>&1
status=$?
cat "$out/log"
[ "$status" -eq 0 ] || { echo "FAIL: exited with status $status"; exit 1; }
grep -q "(GLFW window[;)]" "$out/log" || { echo "FAIL: did not run in a window"; exit 1; }
if grep -q '^GL ' "$out/log"; then echo "FAIL: the GL reported errors or warnings"; exit 1; fi
[ -s "$out/window.png" ] || { echo "FAIL: no screenshot from the window"; exit 1; }
echo "ok: windowed run"
