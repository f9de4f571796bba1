#!/usr/bin/env bash
# wake_behind.sh STEP_EXE WAKE_CHECK OUT_DIR: the wake in the picture, as a camera following the
# boat records it (wake_check.cpp beside this script): the same frame drawn with the wake off and
# on (the smoke test's clock and size) must differ behind the boat, not ahead of it.
set -u
exe=$1 check=$2 out=$3
mkdir -p "$out"
for wake in false true; do
  "$exe" --headless --frames 6 --time 0.5 --dt 0.2 --size 320x180 --set show_wake=$wake \
    --screenshot "$out/wake_$wake.png" > "$out/wake_$wake.log" 2>&1 || { cat "$out/wake_$wake.log"; echo "FAIL: show_wake=$wake"; exit 1; }
done
"$check" "$out/wake_false.png" "$out/wake_true.png"
