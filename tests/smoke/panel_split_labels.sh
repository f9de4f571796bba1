#!/usr/bin/env bash
# panel_split_labels.sh STEP05_EXE: step05's split view names what each half shows. At the default
# resolution (256) the naive DFT does not run (above 64 the step falls back to the GPU FFT), so the
# left half is labelled as such; at 64 it is the DFT. The labels are the ones the panel draws on
# the picture, told on stdout by the split view (common/split_view.cpp).
set -u
exe=$1
run() { "$exe" --headless --split --frames 1 --size 64x36 "$@" 2>&1; }
fail=0
out=$(run) || { echo "$out"; echo "FAIL: the split run failed"; exit 1; }
want='split view: left naive DFT (off above 64: GPU FFT) | right GPU FFT'
if ! grep -qxF "$want" <<< "$out"; then
  echo "$out"; echo "FAIL: at resolution 256, expected the line: $want"; fail=1
fi
out=$(run --set resolution=64) || { echo "$out"; echo "FAIL: the split run at 64 failed"; exit 1; }
want='split view: left naive DFT | right GPU FFT'
if ! grep -qxF "$want" <<< "$out"; then
  echo "$out"; echo "FAIL: at resolution 64, expected the line: $want"; fail=1
fi
[ "$fail" -eq 0 ] && echo "ok: step05's split labels name what each half shows"
exit "$fail"
