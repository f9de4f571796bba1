#!/usr/bin/env bash
# smoke.sh STEP_EXE IMAGE_COMPARE GOLDEN.png OUT_DIR [EXTRA FLAGS...]
# Runs a step headless at 320x180 on a real fixed time step: 6 frames of 0.2 s from t = 0.5 s, so
# that the last frame is at t = 1.5 s and time evolution and foam accumulation (step06: warm start,
# then five steps of growth and decay) are exercised. It must exit 0 with no GL error,
# and its screenshot must not be blank and must match GOLDEN.png within image_compare's stated
# tolerance (RMSE <= 2.5/255, at most 0.5% of pixels off by more than 24/255; a test may set
# SMOKE_RMSE to another RMSE limit and SMOKE_BAD_FRACTION to another share, saying why where it does).
# OCEAN_RUNNER, when set, runs the program (./ocean windows --smoke: wine, for a Windows .exe).
# OCEAN_UPDATE_GOLDEN=1 copies the new screenshot over the golden instead: only after looking at
# both and understanding why the picture changed.
set -u
exe=$1 compare=$2 golden=$3 out=$4
shift 4  # the rest: extra flags (a preset, say)
name=$(basename "$golden" .png)
mkdir -p "$out"
shot="$out/$name.png"
rm -f "$shot" "$out/$name.diff.png"

${OCEAN_RUNNER:-} "$exe" --headless --frames 6 --time 0.5 --dt 0.2 --size 320x180 --screenshot "$shot" "$@" > "$out/$name.log" 2>&1
status=$?
cat "$out/$name.log"
[ "$status" -eq 0 ] || { echo "FAIL: $name exited with status $status"; exit 1; }
if grep -q '^GL ' "$out/$name.log"; then echo "FAIL: the GL reported errors or warnings"; exit 1; fi
[ -s "$shot" ] || { echo "FAIL: no screenshot at $shot"; exit 1; }

if [ "${OCEAN_UPDATE_GOLDEN:-0}" = 1 ]; then
  cp "$shot" "$golden" && echo "golden updated: $golden"
  exit 0
fi
[ -f "$golden" ] || { echo "FAIL: no golden image $golden (see tests/README.md)"; exit 1; }
"$compare" "$shot" "$golden" ${SMOKE_RMSE:+--rmse "$SMOKE_RMSE"} ${SMOKE_BAD_FRACTION:+--bad-fraction "$SMOKE_BAD_FRACTION"} \
  --diff "$out/$name.diff.png"
