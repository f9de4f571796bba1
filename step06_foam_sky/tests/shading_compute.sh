#!/usr/bin/env bash
# shading_compute.sh EXE IMAGE_COMPARE OUT: the shading pass as a compute shader (ocean_shade.comp)
# draws the picture the fragment shader draws (ocean_shade.frag), the same shading at the same
# pixels; they differ only by the texture levels (a fragment shader takes them from its 2 x 2
# quads, the compute shader from each pixel's footprint): RMSE 0.5 of 255 on llvmpipe and on an
# H100. A compute pass that shaded the sky too, or missed pixels, or read the G-buffer wrong
# differs by far more. And shading=auto times both and says which it kept.
set -u
exe=$1 compare=$2 out=$3
mkdir -p "$out"
run() {  # run NAME SETTING
  "$exe" --headless --frames 3 --time 5 --size 320x180 --set backend=fftw --set dither=false --set "$2" \
    --screenshot "$out/$1.png" > "$out/$1.log" 2>&1 ||
    { cat "$out/$1.log"; echo "FAIL: the run with $2 failed"; exit 1; }
}
run fragment shading=fragment
run compute shading=compute
# One pixel in 500 may differ by more than 24 of 255: where a quad straddles a crest, the
# fragment shader's level is its neighbour's.
"$compare" "$out/compute.png" "$out/fragment.png" --rmse 1.0 --bad-fraction 0.002 --diff "$out/diff.png" ||
  { echo "FAIL: the compute shading pass draws another picture than the fragment one"; exit 1; }
"$exe" --headless --frames 8 --size 96x64 --set backend=fftw > "$out/auto.log" 2>&1 ||
  { cat "$out/auto.log"; echo "FAIL: the run with shading=auto failed"; exit 1; }
grep -E '^shading auto: fragment shader [0-9.]+ ms, compute shader [0-9.]+ ms a frame \(median of 3\): (fragment|compute) shader$' \
  "$out/auto.log" || { cat "$out/auto.log"; echo "FAIL: shading=auto did not say what it kept"; exit 1; }
