#!/usr/bin/env bash
# whitecaps.sh STEP_EXE PICTURE_CHECK OUT_DIR [WIND...]: the foam a camera records, against what is measured at
# sea. Each sea is photographed after 10 s of foam (41 frames of 0.25 s), 256 x 256, in linear light
# with no sun glint and no sky reflection (a whitecap census counts white water, not glitter); then
# the same frame without foam and with every texel foamed, the two references picture_check
# measures the foam between.
#   - Whitecap coverage, straight down from 150 m (pitch 89, an 80-degree lens: a 250 m square of
#     sea), at U = WIND... (3, 10, 15, 20 m/s), against Monahan's and Callaghan's laws (picture_check
#     whitecaps), and its split into active whitecaps and residual foam against Monahan and Lu's
#     (picture_check stages).
#   - Streaks along the wind, straight down from 40 m (a 67 m square: streaks are tens of
#     centimetres wide), at U = 10 (Beaufort 5: none) and 20 m/s (Beaufort 8: well-marked)
#     (picture_check streaks), and the foam's edges there, soft as foam's are (picture_check edges).
#   - The same foam from the deck: the 40 m seas again from a camera 15 m above the sea (pitch 30,
#     30 m from the same target, a 60-degree lens), at the same clock; the whitecap share both
#     cameras record on the ground both see, 5 to 60 m from each eye (picture_check agree). A bridge
#     rather than a 5 m deck: at 60 m a 15 m eye's pixels stretch 4 times along the view, a 5 m
#     eye's 12 times, and the 20 m/s sea's crests (up to 3 m) hide much of what a 5 m eye looks at.
set -u
exe=$1 check=$2 out=$3
shift 3
winds=${*:-3 10 15 20}
mkdir -p "$out"

# photograph NAME WIND CAMERA...: leaves $out/NAME_wind_WIND (the export) and its .foam, .water,
# .white.png, the sea at wind WIND through the camera CAMERA (--set camera_... options).
photograph() {
  local dir="$out/${1}_wind_$2" wind=$2
  shift 2
  local sea=(--headless --size 256x256 --set tonemapper=none --set exposure=0.5
             --set show_specular_term=false --set show_reflection_term=false --set show_fog=false --set show_bloom=false
             --set camera_target_y=0 "$@" --set "wind_speed=$wind")
  rm -rf "$dir" "$dir".*.png
  "$exe" "${sea[@]}" --frames 41 --time 0 --dt 0.25 --export "$dir" --screenshot "$dir.foam.png" > /dev/null &&
  "$exe" "${sea[@]}" --frames 1 --time 10 --set show_foam=false --screenshot "$dir.water.png" > /dev/null &&
  "$exe" "${sea[@]}" --frames 1 --time 10 --set foam_threshold=2 --screenshot "$dir.white.png" > /dev/null ||
    { echo "FAIL: the step did not run at wind $wind for $dir"; exit 1; }
  pictures+=("$dir" "$dir.foam.png" "$dir.water.png" "$dir.white.png")
}
above() { echo --set camera_pitch=89 --set "camera_distance=$1" --set camera_fov=80; }
deck=(--set camera_pitch=30 --set camera_distance=30 --set camera_fov=60)

failed=0
pictures=()
for wind in $winds; do photograph 150m "$wind" $(above 150); done
"$check" whitecaps "${pictures[@]}" || failed=1
"$check" stages "${pictures[@]}" || failed=1
pictures=()
for wind in 10 20; do photograph 40m "$wind" $(above 40); done
"$check" streaks "${pictures[@]}" || failed=1
"$check" edges "${pictures[@]}" || failed=1
from_above=("${pictures[@]}")
pictures=()
for wind in 10 20; do photograph deck "$wind" "${deck[@]}"; done
"$check" agree "${from_above[@]:0:4}" "${pictures[@]:0:4}" "${from_above[@]:4:4}" "${pictures[@]:4:4}" || failed=1
[ "$failed" -eq 0 ]
