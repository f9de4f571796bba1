#!/usr/bin/env bash
# tools/readme_images.sh [BUILD_DIR]: redraws every picture the steps' READMEs show, each with the
# one command written here beside it, so a README's image can be reproduced and cannot quietly
# drift from the code. Headless, on a fixed clock (t = 5 s reached by 0.1 s steps, so foam has
# grown), 640x360 (step05's map views 480x300, room for their legends; the spectrum 300x300).
# Takes about a minute on llvmpipe.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
run() {  # run STEP IMAGE [flags...]
  local step=$1 image=$2
  shift 2
  "$build/$step/$step" --headless --size 640x360 --frames 11 --time 4 --dt 0.1 \
    --screenshot "$root/$step/$image" "$@" > /dev/null
  echo "$step/$image"
}
run step01_sine2d screenshot.png
run step02_sine3d screenshot.png
run step02_sine3d wireframe.png --set wireframe=true --camera low
run step03_lighting screenshot.png
run step03_lighting normal_difference.png --set view=normal_difference
run step03_lighting per_vertex.png --set lighting=per_vertex --set x_quads=24 --set z_quads=24
run step03_lighting per_pixel.png --set lighting=per_pixel --set x_quads=24 --set z_quads=24
run step04_fbm screenshot.png
run step04_fbm warp_off.png --set warp=0 --camera low
run step04_fbm warp_on.png --set warp=6 --camera low
run step04_fbm sine.png --set shape=sine --set warp=0 --camera low
run step05_fft screenshot.png
run step05_fft height.png --size 480x300 --set view=height
run step05_fft jacobian.png --size 480x300 --set view=jacobian --set choppiness=2.5
run step05_fft spectrum.png --size 300x300 --set view=spectrum
run step06_foam_sky screenshot.png
for preset in calm breezy stormy crossing; do
  run step06_foam_sky "$preset.png" --preset "$root/step06_foam_sky/presets/$preset.preset"
done
run step06_foam_sky foam.png --set view=foam --camera overview
run step06_foam_sky tessellation.png --set wireframe=true --camera overview

# The combed streaks and what removed them: the same mid-distance strip (no bloom) filtered four
# ways, the last rendered at 4 x 4 the pixels and box-averaged down (what a pixel should show).
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
strip() {  # strip NAME [flags...]
  local name=$1
  shift
  "$build/step06_foam_sky/step06_foam_sky" --headless --size 640x360 --frames 11 --time 4 --dt 0.1 \
    --set show_bloom=false --set dither=false --screenshot "$scratch/$name.png" "$@" > /dev/null
}
strip isotropic --set anisotropy=1
strip two --set anisotropy=2
strip four --set anisotropy=4
strip reference --set anisotropy=16 --size 2560x1440
crop=0,0.3,0.625,0.6
"$build/tools/image_panel" "$root/step06_foam_sky/streaks.png" 600x162 2 \
  "before: one trilinear fetch|$scratch/isotropic.png|$crop" "2 pieces|$scratch/two.png|$crop" \
  "4 pieces (the default)|$scratch/four.png|$crop" "reference: 16x supersampled|$scratch/reference.png|$crop"
echo step06_foam_sky/streaks.png
# What the cascades combined around the camera would keep (README, "Why the cascades are not
# combined around the camera"): the same strip, closer, with combined_texels.
strip combined_256 --set combined_texels=256
strip combined_512 --set combined_texels=512
near=0.1,0.34,0.45,0.5
"$build/tools/image_panel" "$root/step06_foam_sky/combined_levels.png" 560x128 2 \
  "the cascades sampled per pixel (what step06 does)|$scratch/four.png|$near" \
  "reference: 16x supersampled|$scratch/reference.png|$near" \
  "combined around the camera, 256 x 256 a level|$scratch/combined_256.png|$near" \
  "combined, 512 x 512 a level|$scratch/combined_512.png|$near"
echo step06_foam_sky/combined_levels.png
