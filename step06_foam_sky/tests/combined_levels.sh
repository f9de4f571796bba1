#!/usr/bin/env bash
# combined_levels.sh STEP_EXE PICTURE_CHECK OUT_DIR: what the cascades combined around the camera
# (Crest's design) would cost the picture, which is why step06 samples each cascade per pixel
# (README, "The cascades combined around the camera"). The setting combined_texels=N
# resolves the slopes no finer than levels of N x N texels could (shaders/combined_levels.glsl).
# On the mid-distance strip of the README's anisotropy figure (640 x 360, t = 5 s, no bloom), the
# detail across the view (picture_check detail, rows 0.3 to 0.6):
#   1. levels of 256^2 lose more than a sixth of it (measured 2.26 against 3.14; one trilinear
#      fetch a cascade, the combed look, is 1.88);
#   2. levels of 4096^2 keep it to 1 % (measured equal): the setting takes away only what the
#      levels could not hold.
set -u
exe=$1 check=$2 out=$3
mkdir -p "$out"
source "$(dirname "$0")/strip_detail.sh"
per_pixel=$(detail per_pixel) && small=$(detail combined_256 --set combined_texels=256) &&
  large=$(detail combined_4096 --set combined_texels=4096) || exit 1
echo "detail across the view: the cascades per pixel $per_pixel, combined into 256^2 levels $small, into 4096^2 levels $large"
failures=0
awk -v a="$per_pixel" -v s="$small" 'BEGIN { exit !(s < a * 5 / 6) }' ||
  { echo "FAIL: 256^2 levels should lose more than a sixth of the detail"; failures=$((failures + 1)); }
awk -v a="$per_pixel" -v l="$large" 'BEGIN { d = l - a; if (d < 0) d = -d; exit !(d <= 0.01 * a) }' ||
  { echo "FAIL: 4096^2 levels should keep the detail within 1 %"; failures=$((failures + 1)); }
[ "$failures" -eq 0 ]
