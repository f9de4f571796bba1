#!/usr/bin/env bash
# animations.sh REPO BUILD_DIR OUT IMAGE_COMPARE: ./ocean animations on what ctest built records a
# step on a steady clock (--record, --dt) and makes one animated WebP of it that decodes to the
# right number of frames at the right size; the recorded frames move (the first and the last
# differ); and the pieces refuse bad input with one line and a non-zero exit.
set -u
repo=$1 build=$2 out=$3 compare=$4
cd "$repo" || exit 1
export OCEAN_NO_BUILD=1 OCEAN_BUILD_DIR=$build
rm -rf "$out" && mkdir -p "$out"
status=0
./ocean animations step02_sine3d --seconds 1 --size 160x90 --out "$out" > "$out/log" 2>&1 || { echo "FAIL: ./ocean animations"; cat "$out/log"; exit 1; }
"$build/tools/animate" --verify "$out/step02_sine3d.webp" > "$out/verify" 2>&1 || { echo "FAIL: the WebP does not decode"; cat "$out/verify"; status=1; }
grep -q ": 15 frames, 160x90," "$out/verify" || { echo "FAIL: expected 15 frames of 160x90"; cat "$out/verify"; status=1; }
frames="$build/animations/step02_sine3d"
[ "$(ls "$frames"/frame_*.png | wc -l)" -eq 15 ] || { echo "FAIL: --record wrote $(ls "$frames" | wc -l) frames, not 15"; status=1; }
if "$compare" "$frames/frame_0000.png" "$frames/frame_0014.png" > /dev/null 2>&1; then
  echo "FAIL: the first and last recorded frames are the same picture: nothing moves"; status=1
fi
# Bad input: frames of two sizes, a missing frame, a bad rate, an unwritable --record folder.
cp "$repo/step02_sine3d/screenshot.png" "$out/other_size.png"
for args in "$out/x.webp 15 60 $frames/frame_0000.png $out/other_size.png" "$out/x.webp 15 60 $out/missing.png" \
            "$out/x.webp 0 60 $frames/frame_0000.png"; do
  # shellcheck disable=SC2086
  "$build/tools/animate" $args > "$out/bad" 2>&1 && { echo "FAIL: animate $args succeeded"; status=1; }
  [ "$(wc -l < "$out/bad")" -eq 1 ] && grep -q '^animate: ' "$out/bad" || { echo "FAIL: animate $args: not one line"; cat "$out/bad"; status=1; }
done
"$build/step02_sine3d/step02_sine3d" --headless --frames 2 --size 64x36 --record /proc/cannot-write > "$out/bad" 2>&1 &&
  { echo "FAIL: --record into /proc succeeded"; status=1; }
grep -q "^error: cannot write '/proc/cannot-write/frame_0000.png'" "$out/bad" || { echo "FAIL: --record's error"; cat "$out/bad"; status=1; }
[ "$status" -eq 0 ] && echo "animations: 15 frames recorded and encoded, and the bad inputs refused"
exit $status
