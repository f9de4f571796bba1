#!/usr/bin/env bash
# figures.sh REPO BUILD_DIR OUT IMAGE_COMPARE: ./ocean figures on what ctest built draws every
# figure whose script the chapters' figure programs (STEP_figures) wrote (at least the nine the
# READMEs show), each a PNG that is not blank (image_compare refuses a blank picture, even compared
# with itself), in OUT/FOLDER as BUILD_DIR/figures/FOLDER holds its script (the chapter that shows
# it).
set -u
repo=$1 build=$2 out=$3 compare=$4
cd "$repo" || exit 1
export OCEAN_NO_BUILD=1 OCEAN_BUILD_DIR=$build
rm -rf "$out"
./ocean figures --out "$out" || { echo "FAIL: ./ocean figures"; exit 1; }
status=0 count=0
while IFS= read -r script; do
  png=${script#"$build/figures/"}
  png=$out/${png%.gp}.png
  count=$((count + 1))
  if [ ! -s "$png" ]; then echo "FAIL: no $png"; status=1; continue; fi
  "$compare" "$png" "$png" > "${png%.png}.check" 2>&1 || { echo "FAIL: $png"; cat "${png%.png}.check"; status=1; }
done < <(find "$build/figures" -name '*.gp' | sort)
for png in docs/figures/wave_profiles step04_fbm/domain_warp step05_fft/spectrum_lattice step05_fft/jacobian_fold \
           step05_fft/spectra step06_foam_sky/cascade_bands step06_foam_sky/fresnel step05_fft/butterfly \
           step03_lighting/lighting_vectors; do
  [ -s "$out/$png.png" ] || { echo "FAIL: $png.png missing"; status=1; }
done
[ "$status" = 0 ] && echo "figures: $count drawn, none blank"
exit $status
