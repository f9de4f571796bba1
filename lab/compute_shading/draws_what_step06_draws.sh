#!/usr/bin/env bash
# draws_what_step06_draws.sh STEP06 LAB IMAGE_COMPARE OUT: the shading pass as a compute shader
# (lab_compute_shading) draws the picture step06 draws with its fragment shader: the same shading at
# the same pixels. They differ only by the texture levels (a fragment shader takes them from its
# 2 x 2 quads, the compute shader from each pixel's footprint): RMSE 0.5 of 255 measured. A compute
# pass that shaded the sky too, missed pixels or read the G-buffer wrong differs by far more (a
# picture shifted by one pixel: RMSE 10.6). Three frames: both programs are still timing step05's
# two transforms on the same schedule (backend auto), so both draw the same sea.
set -u
step06=$1 lab=$2 compare=$3 out=$4
mkdir -p "$out"
run() {  # run NAME PROGRAM
  "$2" --headless --frames 3 --time 5 --size 320x180 --set tonemapper=none --set exposure=0.7 \
    --screenshot "$out/$1.png" > "$out/$1.log" 2>&1 ||
    { cat "$out/$1.log"; echo "FAIL: $2 did not run"; exit 1; }
}
run fragment "$step06"
run compute "$lab"
# One pixel in 500 may differ by more than 24 of 255: where a quad straddles a crest, the
# fragment shader's level is its neighbour's.
"$compare" "$out/compute.png" "$out/fragment.png" --rmse 1.0 --bad-fraction 0.002 --diff "$out/diff.png" ||
  { echo "FAIL: the compute shading pass draws another picture than step06's fragment shader"; exit 1; }
