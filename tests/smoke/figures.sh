#!/usr/bin/env bash
# figures.sh REPO BUILD_DIR OUT IMAGE_COMPARE: ./ocean figures on what ctest built draws every
# figure whose script figure_data wrote (at least the nine the READMEs show), each a PNG that is
# not blank (image_compare refuses a blank picture, even compared with itself).
set -u
repo=$1 build=$2 out=$3 compare=$4
cd "$repo" || exit 1
export OCEAN_NO_BUILD=1 OCEAN_BUILD_DIR=$build
rm -rf "$out"
./ocean figures --out "$out" || { echo "FAIL: ./ocean figures"; exit 1; }
status=0 count=0
for script in "$build"/figures/*.gp; do
  name=$(basename "${script%.gp}")
  count=$((count + 1))
  if [ ! -s "$out/$name.png" ]; then echo "FAIL: no $name.png"; status=1; continue; fi
  "$compare" "$out/$name.png" "$out/$name.png" > "$out/$name.check" 2>&1 || { echo "FAIL: $name.png"; cat "$out/$name.check"; status=1; }
done
for name in wave_profiles domain_warp spectrum_lattice jacobian_fold spectra cascade_bands fresnel butterfly lighting_vectors; do
  [ -s "$out/$name.png" ] || { echo "FAIL: $name.png missing"; status=1; }
done
[ "$status" = 0 ] && echo "figures: $count drawn, none blank"
exit $status
