#!/usr/bin/env bash
# glitter.sh STEP_EXE PICTURE_CHECK OUT_DIR [WIND...]: the sun's glitter as Cox and Munk measured it.
# Each sea is photographed from 800 m straight up (pitch 89, a 100-degree lens), the sun overhead,
# with only the sun's specular reflection drawn (Beckmann, linear light: tonemapper none, no bloom,
# fog, foam, sky reflection or scatter), and picture_check reads its mean square slope back. First
# a flat sea (wind 0) with a set roughness of 0.2, which the read-back must recover (its own check),
# then a sea at each WIND (m/s, default 3 7 10 15 20) against Cox and Munk.
set -u
exe=$1 check=$2 out=$3
shift 3
winds=${*:-3 7 10 15 20}
mkdir -p "$out"
view=(--headless --size 256x256 --frames 1 --time 5
      --set microfacet=beckmann --set sun_elevation=90 --set sun_intensity=3 --set exposure=1 --set tonemapper=none
      --set show_ambient_term=false --set show_scatter_term=false --set show_reflection_term=false
      --set show_foam=false --set show_fog=false --set show_bloom=false
      --set camera_pitch=89 --set camera_distance=800 --set camera_target_y=0 --set camera_fov=100
      --set tess_patch_size=100)
pairs=()
for wind in 0 $winds; do
  roughness=0.02
  [ "$wind" = 0 ] && roughness=0.2
  dir="$out/wind_$wind"
  rm -rf "$dir" "$dir.png"
  "$exe" "${view[@]}" --set "wind_speed=$wind" --set "roughness=$roughness" --export "$dir" --screenshot "$dir.png" \
    > /dev/null || { echo "FAIL: the step did not run at wind $wind"; exit 1; }
  pairs+=("$dir" "$dir.png")
done
"$check" glitter "${pairs[@]}"
