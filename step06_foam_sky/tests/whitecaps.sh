#!/usr/bin/env bash
# whitecaps.sh STEP_EXE PICTURE_CHECK OUT_DIR [WIND...]: the foam a camera records, against what is measured at
# sea. Each sea is photographed straight down (pitch 89, an 80-degree lens, 256 x 256) after 10 s of
# foam (41 frames of 0.25 s), in linear light with no sun glint and no sky reflection (a whitecap
# census counts white water, not glitter); then the same frame without foam and with every texel
# foamed, the two references picture_check measures the foam between.
#   - Whitecap coverage, from 150 m (a 250 m square of sea), at U = WIND... (3, 10, 15, 20 m/s), against
#     Monahan's and Callaghan's laws (picture_check whitecaps).
#   - Streaks along the wind, from 40 m (a 67 m square: streaks are tens of centimetres wide), at
#     U = 10 (Beaufort 5: none) and 20 m/s (Beaufort 8: well-marked) (picture_check streaks).
set -u
exe=$1 check=$2 out=$3
shift 3
winds=${*:-3 10 15 20}
mkdir -p "$out"

# photograph HEIGHT WIND: leaves $out/HEIGHT_WIND (the export) and its .foam, .water, .white.png
photograph() {
  local dir="$out/${1}m_wind_$2"
  local sea=(--headless --size 256x256 --set tonemapper=none --set exposure=0.5
             --set show_specular_term=false --set show_reflection_term=false --set show_fog=false --set show_bloom=false
             --set camera_pitch=89 --set "camera_distance=$1" --set camera_target_y=0 --set camera_fov=80
             --set "wind_speed=$2")
  rm -rf "$dir" "$dir".*.png
  "$exe" "${sea[@]}" --frames 41 --time 0 --dt 0.25 --export "$dir" --screenshot "$dir.foam.png" > /dev/null &&
  "$exe" "${sea[@]}" --frames 1 --time 10 --set show_foam=false --screenshot "$dir.water.png" > /dev/null &&
  "$exe" "${sea[@]}" --frames 1 --time 10 --set foam_threshold=2 --screenshot "$dir.white.png" > /dev/null ||
    { echo "FAIL: the step did not run at wind $2 from $1 m"; exit 1; }
  pictures+=("$dir" "$dir.foam.png" "$dir.water.png" "$dir.white.png")
}

pictures=()
for wind in $winds; do photograph 150 "$wind"; done
"$check" whitecaps "${pictures[@]}"
coverage=$?
pictures=()
for wind in 10 20; do photograph 40 "$wind"; done
"$check" streaks "${pictures[@]}"
streaks=$?
[ "$coverage" -eq 0 ] && [ "$streaks" -eq 0 ]
