#!/usr/bin/env bash
# far_sea.sh STEP_EXE SEA_CHECK IMAGE_COMPARE OUT_DIR: the sea 1000 km out is the sea at the
# origin. A sailor crosses an ocean; float's steps there are 6 cm, and a tile's phase p / L computed
# in float is off by as much, so the renderer works relative to a world origin near the camera
# (step06_foam_sky/cascades.hpp) and the camera is kept in double.
#   1. The same statistics (sea_check same_sea): the export 1000 km out (x = 1000123.4,
#      z = -987654.3) against four stretches within 2.5 km of the origin.
#   2. No jitter: two frames 1/60 s apart differ only by the waves' motion, and a camera moved by
#      1 cm moves the picture by 1 cm; out there as at the origin (picture RMSE within 1.5 times the
#      origin's, plus half a level).
set -u
exe=$1 sea_check=$2 compare=$3 out=$4
mkdir -p "$out"
far=(--set camera_target_x=1000123.4 --set camera_target_z=-987654.3)
run() { "$exe" --headless --frames 1 --size 320x180 "$@" > /dev/null || { echo "FAIL: the step did not run: $*"; exit 1; }; }

near_dirs=()
for place in "0 0" "700 -300" "-1500 900" "2300 1700"; do
  set -- $place
  dir="$out/near_${1}_$2"
  rm -rf "$dir"
  run --time 5 --set "camera_target_x=$1" --set "camera_target_z=$2" --export "$dir"
  near_dirs+=("$dir")
done
rm -rf "$out/far"
run --time 5 "${far[@]}" --export "$out/far"
"$sea_check" same_sea "$out/far" "${near_dirs[@]}"
statistics=$?

rmse() { "$compare" "$1" "$2" 2>&1 | sed -n 's/.*rmse \([0-9.]*\).*/\1/p' | head -1; }
failures=0
# check NAME NEAR_RMSE FAR_RMSE
check() {
  if awk -v n="$2" -v f="$3" 'BEGIN { exit !(f <= 1.5 * n + 0.5 && f >= n / 1.5 - 0.5) }'; then
    echo "$1: RMSE at the origin $2, 1000 km out $3 (within 1.5 times, plus 0.5)"
  else
    echo "$1: RMSE at the origin $2, 1000 km out $3: FAIL"; failures=$((failures + 1))
  fi
}
for where in near far; do
  place=(); [ "$where" = far ] && place=("${far[@]}")
  run --time 5 "${place[@]}" --screenshot "$out/$where.png"
  run --time 5.0166666666666666 "${place[@]}" --screenshot "$out/$where.next_frame.png"
  x=0; [ "$where" = far ] && x=1000123.4
  run --time 5 "${place[@]}" --set "camera_target_x=$(awk -v x=$x 'BEGIN { printf "%.2f", x + 0.01 }')" --screenshot "$out/$where.moved.png"
done
check "two frames 1/60 s apart" "$(rmse "$out/near.png" "$out/near.next_frame.png")" "$(rmse "$out/far.png" "$out/far.next_frame.png")"
check "the camera 1 cm along x" "$(rmse "$out/near.png" "$out/near.moved.png")" "$(rmse "$out/far.png" "$out/far.moved.png")"
[ "$statistics" -eq 0 ] && [ "$failures" -eq 0 ]
