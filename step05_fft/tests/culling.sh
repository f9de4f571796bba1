#!/usr/bin/env bash
# culling.sh STEP_EXE IMAGE_COMPARE: frustum culling may only leave out what cannot be seen, so
# from every shared camera (and a storm, whose waves move furthest) the picture with culling is
# the picture without it, pixel for pixel. Both runs use the FFTW backend, so they are the same
# sea to the bit. The last two views look straight down on a 30 m/s choppy sea with a chunk's edge
# just outside the picture: there the margin matters (culling the chunks by their flat rest boxes,
# margin 0, changes up to 1 % of the pixels: the displaced waves reach into view).
set -u
exe="$1" compare="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
status=0
views=()
for camera in overview deck low top; do
  views+=("--camera $camera --set wind_speed=14" "--camera $camera --set wind_speed=25")
done
views+=("--camera top --set wind_speed=30 --set choppiness=2 --set camera_distance=33"
        "--camera top --set wind_speed=30 --set choppiness=2 --set camera_distance=34")
for view in "${views[@]}"; do
    for cull in true false; do
      # shellcheck disable=SC2086 # the view is a list of flags
      "$exe" --headless --size 240x135 --frames 2 --time 4 $view --set backend=fftw \
        --set "frustum_culling=$cull" --screenshot "$out/$cull.png" > "$out/log" 2>&1 ||
        { echo "$view culling=$cull: FAILED"; cat "$out/log"; exit 1; }
    done
    if "$compare" "$out/true.png" "$out/false.png" --rmse 0.0001 --threshold 0 --bad-fraction 0 > "$out/cmp" 2>&1; then
      echo "$view: the same picture"
    else
      echo "$view: culling changed the picture"; cat "$out/cmp"; status=1
    fi
done
exit $status
