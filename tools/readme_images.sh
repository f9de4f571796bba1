#!/usr/bin/env bash
# tools/readme_images.sh [BUILD_DIR]: redraws every picture the steps' READMEs show, each with the
# one command written here beside it, so a README's image can be reproduced and cannot quietly
# drift from the code. Headless, on a fixed clock (t = 5 s reached by 0.1 s steps, so foam has
# grown), 640x360 (step05's map views 480x300, room for their legends; the spectrum 300x300).
# Takes about a minute on llvmpipe. A failure ends with one line "readme_images: error: ...".
set -euo pipefail
die() { printf 'readme_images: error: %s\n' "$*" >&2; exit 1; }
[ $# -le 1 ] || die "give at most one argument, the build folder"
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
for program in step01_sine2d/step01_sine2d step02_sine3d/step02_sine3d step03_lighting/step03_lighting \
               step04_fbm/step04_fbm step05_fft/step05_fft step06_foam_sky/step06_foam_sky step07_buoyancy/step07_buoyancy step08_wakes/step08_wakes \
               step09_radiation/step09_radiation step10_underwater/step10_underwater tools/image_panel; do
  [ -x "$build/$program" ] || die "$build/$program is not built"
done
# The intermediate pictures, removed however the script ends.
scratch=$(mktemp -d -t readme_images.XXXXXX) || die "cannot make a temporary folder in ${TMPDIR:-/tmp}"
trap 'rm -rf -- "$scratch"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# shot STEP OUT.png [flags...]: one headless picture; the step's own error line, then ours.
shot() {
  local step=$1 png=$2
  shift 2
  "$build/$step/$step" --headless --screenshot "$png" "$@" > /dev/null || die "$step failed drawing ${png##*/}"
}
# panel OUT.png CELL COLUMNS TILE...: tools/image_panel's figure.
panel() { "$build/tools/image_panel" "$@" || die "image_panel failed drawing ${1#"$root"/}"; }
run() {  # run STEP IMAGE [flags...]
  local step=$1 image=$2
  shift 2
  shot "$step" "$root/$step/$image" --size 640x360 --frames 11 --time 4 --dt 0.1 "$@"
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
run step04_fbm warp_on.png --set warp=8 --camera low
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

# The foam from 40 m straight down at Beaufort 5 and 8 after 10 s of foam (the census's clock,
# tests/whitecaps.sh): whitecaps and their lace, then streaks.
for wind in 10 20; do
  shot step06_foam_sky "$scratch/beaufort$wind.png" --size 400x400 --frames 41 --time 0 --dt 0.25 \
    --set camera_pitch=89 --set camera_distance=40 --set camera_target_y=0 --set camera_fov=80 \
    --set "wind_speed=$wind"
done
panel "$root/step06_foam_sky/streaks_beaufort.png" 400x400 2 \
  "10 m/s (Beaufort 5): whitecaps and their lace|$scratch/beaufort10.png" \
  "20 m/s (Beaufort 8): streaks along the wind|$scratch/beaufort20.png"
echo step06_foam_sky/streaks_beaufort.png
run step06_foam_sky tessellation.png --set wireframe=true --camera overview
# The same patches cut on the CPU where there are no tessellation shaders (patch_lod.hpp): from the
# ES build (OCEAN_ES_BUILD, default build/es), beside the tessellator's, from 3 m above the water.
es_build=${OCEAN_ES_BUILD:-$root/build/es}
if [ -x "$es_build/step06_foam_sky/step06_foam_sky" ]; then
  lod_flags=(--size 480x270 --frames 11 --time 4 --dt 0.1 --set wireframe=true --set camera_pitch=30 --set camera_distance=6)
  shot step06_foam_sky "$scratch/tessellated.png" "${lod_flags[@]}"
  "$es_build/step06_foam_sky/step06_foam_sky" --headless --screenshot "$scratch/cut_on_cpu.png" "${lod_flags[@]}" > /dev/null \
    || die "the ES build's step06_foam_sky failed drawing patch_lod.png"
  panel "$root/step06_foam_sky/patch_lod.png" 480x270 2 \
    "GL 4.5: the tessellator's levels, edge by edge|$scratch/tessellated.png" \
    "ES 3.0: a power of two a patch, edges snapped|$scratch/cut_on_cpu.png"
  echo step06_foam_sky/patch_lod.png
else
  echo "step06_foam_sky/patch_lod.png: kept (it needs the ES build: OCEAN_PRESET=es ./ocean test)"
fi

# The combed streaks and what removed them: the same mid-distance strip (no bloom) filtered four
# ways, the last rendered at 4 x 4 the pixels and box-averaged down (what a pixel should show).
strip() {  # strip NAME [flags...]
  local name=$1
  shift
  shot step06_foam_sky "$scratch/$name.png" --size 640x360 --frames 11 --time 4 --dt 0.1 --set show_bloom=false "$@"
}
strip isotropic --set anisotropy=1
strip two --set anisotropy=2
strip four --set anisotropy=4
strip reference --set anisotropy=16 --size 2560x1440
crop=0,0.3,0.625,0.6
panel "$root/step06_foam_sky/streaks.png" 600x162 2 \
  "before: one trilinear fetch|$scratch/isotropic.png|$crop" "2 pieces|$scratch/two.png|$crop" \
  "4 pieces (the default)|$scratch/four.png|$crop" "reference: 16x supersampled|$scratch/reference.png|$crop"
echo step06_foam_sky/streaks.png

# Build it yourself (step06's README): the picture after each piece of the chapter, made with its
# own switches (every piece is on in the last); then close-ups of the two pieces whose change is
# small at that size, each the same view without and with the effect, cropped alike and scaled
# alike in x and y (fog made thicker so that it shows; the bloom around the glitter at 2x); and
# the sky's reflection: the whole frame with it, then without it.
piece() {  # piece NAME [flags...]
  local name=$1
  shift
  shot step06_foam_sky "$scratch/$name.png" --size 640x360 --frames 11 --time 4 --dt 0.1 "$@"
}
piece cascades --camera overview --set view=jacobian
piece mesh --set wireframe=true
piece lit --set show_specular_term=false --set show_reflection_term=false --set show_foam=false \
  --set show_fog=false --set show_bloom=false
piece sky --set show_foam=false --set show_fog=false --set show_bloom=false
piece foam --set show_fog=false --set show_bloom=false
piece fog --set show_bloom=false
piece bloom
piece thick_fog_off --set fog_density=0.006 --set show_fog=false --set show_bloom=false
piece thick_fog_on --set fog_density=0.006 --set show_bloom=false
piece no_reflection --set show_reflection_term=false
panel "$root/step06_foam_sky/build_it_yourself.png" 320x180 4 \
  "1. cascades (view=jacobian)|$scratch/cascades.png" "2. the mesh (wireframe=true)|$scratch/mesh.png" \
  "3. lit: ambient and scatter|$scratch/lit.png" "4. + sky reflection, sun|$scratch/sky.png" \
  "5. + foam|$scratch/foam.png" "6. + fog|$scratch/fog.png" "7. + bloom: the final picture|$scratch/bloom.png"
echo step06_foam_sky/build_it_yourself.png
panel "$root/step06_foam_sky/build_it_yourself_closeup.png" 320x180 2 \
  "6. fog off (density 0.006)|$scratch/thick_fog_off.png|0,0.2,0.5,0.7" \
  "6. fog on (density 0.006)|$scratch/thick_fog_on.png|0,0.2,0.5,0.7" \
  "7. bloom off (2x)|$scratch/fog.png|0.7,0.33,0.95,0.58" "7. bloom on (2x)|$scratch/bloom.png|0.7,0.33,0.95,0.58"
echo step06_foam_sky/build_it_yourself_closeup.png
panel "$root/step06_foam_sky/reflection_on_off.png" 320x180 2 \
  "the sky's reflection on|$scratch/bloom.png" "off (show_reflection_term=false)|$scratch/no_reflection.png"
echo step06_foam_sky/reflection_on_off.png

# step07's bodies 6 s after they were dropped (0.1 s steps from t = 0): afloat, in the part of the
# view the panel leaves free.
shot step07_buoyancy "$root/step07_buoyancy/screenshot.png" --size 640x360 --frames 61 --time 0 --dt 0.1
echo step07_buoyancy/screenshot.png

# step08's wake on step06's sea, 0.1 s after the bodies are dropped (the boat's 20 s warm-up made
# the wake already), with the wake off and on; then the wake alone from above (plan=true): the
# default boat (4 m/s, 6 m: Fr 0.52) and the same boat at 9 m/s (Fr 1.17), Kelvin's edges drawn.
shot step08_wakes "$root/step08_wakes/screenshot.png" --size 640x360 --frames 2 --time 0 --dt 0.1
echo step08_wakes/screenshot.png
shot step08_wakes "$scratch/sea_alone.png" --size 640x360 --frames 2 --time 0 --dt 0.1 --set show_wake=false
panel "$root/step08_wakes/wake_on_the_sea.png" 480x270 2 \
  "show_wake=false: step07's sea|$scratch/sea_alone.png" "show_wake=true: the boat's wake in it|$root/step08_wakes/screenshot.png"
echo step08_wakes/wake_on_the_sea.png
shot step08_wakes "$scratch/wake_slow.png" --size 640x360 --frames 2 --dt 0.1 --set plan=true --set kelvin_lines=true
shot step08_wakes "$scratch/wake_fast.png" --size 640x360 --frames 2 --dt 0.1 --set plan=true --set kelvin_lines=true --set boat_speed=9
# Each tile crops 16:9 out of the 16:9 shot (x and y alike), so the panel keeps the plan's angles.
panel "$root/step08_wakes/wake_speeds.png" 480x270 2 \
  "4 m/s, Fr 0.52: the edge at 19.47 degrees|$scratch/wake_slow.png|0.1,0.1,0.9,0.9" \
  "9 m/s, Fr 1.17: the largest waves inside it|$scratch/wake_fast.png|0.1,0.1,0.9,0.9"
echo step08_wakes/wake_speeds.png

# step09's bodies in step08's scene 0.1 s after the drop (as step08's shot): nothing has rung yet.
shot step09_radiation "$root/step09_radiation/screenshot.png" --size 640x360 --frames 2 --time 0 --dt 0.1
echo step09_radiation/screenshot.png
# The buoy pushed up and down at 1 Hz (forced_heave) on a flat sea (wind_speed=0), 8 s on (160 steps
# of 0.05 s), the camera held (follow_boat=false) and looking down on it: its rings, the boat's wake,
# the raft in contact.
shot step09_radiation "$root/step09_radiation/rings.png" --size 640x360 --frames 160 --time 0 --dt 0.05 \
  --set wind_speed=0 --set forced_heave=0.3 --set follow_boat=false --set camera_pitch=45 --set camera_distance=30
echo step09_radiation/rings.png
run step10_underwater screenshot.png
# Snell's window on a flat sea, the sun overhead, the camera 5 m down looking up 41.4 degrees: the
# window's edge across the middle of the picture.
run step10_underwater window.png --set wind_speed=0 --set sun_elevation=90 --set camera_pitch=-41.4
run step10_underwater seabed.png --set camera_pitch=35 --set camera_target_y=-6 --set seabed_depth=8
run step10_underwater coastal.png --set water_type=coastal
# The waterline: a level camera whose lens a wave (8 m/s wind) half covers at t = 5 s.
run step10_underwater waterline.png --set wind_speed=8 --set camera_target_y=0.58 --set camera_distance=0.5 --set camera_pitch=6

# step05's one Gerstner wave at three steepnesses Q k A (sea=gerstner), crests across the view.
gerstner() {  # gerstner STEEPNESS
  shot step05_fft "$scratch/gerstner$1.png" --size 480x270 --frames 2 --time 3 --set sea=gerstner \
    --set wind_direction=120 --set gerstner_steepness="$1"
}
gerstner 0
gerstner 0.8
gerstner 1.3
panel "$root/step05_fft/gerstner.png" 480x270 3 "Q k A = 0: a sine|$scratch/gerstner0.png" \
  "0.8|$scratch/gerstner0.8.png" "1.3: folded crests|$scratch/gerstner1.3.png"
echo step05_fft/gerstner.png
