#!/usr/bin/env bash
# combined_surface.sh STEP_EXE PICTURE_CHECK OUT_DIR: surface=combined keeps the look (README, "The
# cascades combined around the camera"). On the mid-distance strip of the README's anisotropy
# figure (640 x 360, t = 4 s, no bloom), the detail across the view (picture_check detail, rows
# 0.3 to 0.6):
#   1. the default combine (the three longest cascades in levels of 512^2, the finest read per
#      pixel) keeps it within 5 % of the cascades read per pixel (measured 3.07 against 3.14);
#   2. all four cascades in levels of 256^2 lose more than a sixth of it: the levels' texels are
#      coarser than a pixel across the view, which is why the finest cascade stays out of them
#      (so the measure can tell a combine that smears the ripples).
set -u
exe=$1 check=$2 out=$3
mkdir -p "$out"
source "$(dirname "$0")/strip_detail.sh"
cascades=$(detail cascades) && combined=$(detail combined --set surface=combined) &&
  all_four=$(detail all_four_256 --set surface=combined --set combined_cascades=4 --set combined_size=256) || exit 1
echo "detail across the view: the cascades per pixel $cascades, combined (default) $combined, all four in 256^2 levels $all_four"
failures=0
awk -v a="$cascades" -v c="$combined" 'BEGIN { exit !(c >= 0.95 * a) }' ||
  { echo "FAIL: the default combine should keep the detail within 5 %"; failures=$((failures + 1)); }
awk -v a="$cascades" -v s="$all_four" 'BEGIN { exit !(s < a * 5 / 6) }' ||
  { echo "FAIL: all four cascades in 256^2 levels should lose more than a sixth of the detail"; failures=$((failures + 1)); }
[ "$failures" -eq 0 ]
