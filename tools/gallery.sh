#!/usr/bin/env bash
# tools/gallery.sh [BUILD_DIR]: draws docs/gallery/: every step06 preset from the deck (a few
# metres above the water) and from the overview (40 m up), a backlit view, and their README with
# each picture's command beside it. Headless, 960x540, on a fixed clock reached by 0.25 s steps
# (t = 10 s: the foam has grown and decayed as it would on screen). About two minutes on llvmpipe.
# ./ocean gallery runs it after building. A failure ends with one line "gallery: error: ...".
set -euo pipefail
die() { printf 'gallery: error: %s\n' "$*" >&2; exit 1; }
[ $# -le 1 ] || die "give at most one argument, the build folder"
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/release}
exe="$build/step06_foam_sky/step06_foam_sky"
[ -x "$exe" ] || die "$exe is not built"
out="$root/docs/gallery"
mkdir -p -- "$out" || die "cannot make $out"
clock=(--headless --size 960x540 --frames 41 --time 0 --dt 0.25)
readme="$out/README.md"
cat > "$readme" <<'TEXT' || die "cannot write $readme"
# Gallery: step06 under each preset

Drawn by `./ocean gallery` (tools/gallery.sh) from the code as it is: each picture's command is
under it (run from the repository's root after `./ocean run step06_foam_sky --help` has built it).
The clock runs 41 steps of 0.25 s from t = 0, so the foam has grown and decayed for 10 s.
The presets are in `step06_foam_sky/presets/`; the heights they draw are in step06's README.

TEXT
shoot() {  # shoot IMAGE CAPTION [flags...]
  local image=$1 caption=$2
  shift 2
  "$exe" "${clock[@]}" --screenshot "$out/$image" "$@" > /dev/null || die "step06 failed on $image"
  # The command as a reader types it: from the repository's root, the release build's program.
  local shown="build/release/step06_foam_sky/step06_foam_sky ${clock[*]} --screenshot docs/gallery/$image $*"
  printf '## %s\n\n![%s](%s)\n\n    %s\n\n' "$caption" "$caption" "$image" "${shown//"$root"\//}" >> "$readme"
  echo "docs/gallery/$image"
}
for preset in calm breezy stormy crossing; do
  file="$root/step06_foam_sky/presets/$preset.preset"
  [ -f "$file" ] || die "no preset $file"
  about=$(sed -n '1s/^# step06_foam_sky preset: //p' "$file")
  shoot "$preset-deck.png" "$preset, from the deck: $about" --preset "$file" --camera deck
  shoot "$preset-overview.png" "$preset, from 40 m up" --preset "$file" --camera overview
done
shoot backlit.png "Backlit, 5 m above the water: the sun low ahead, light through the crests beside the glitter path" \
  --camera low --set sun_elevation=10 --set sun_azimuth=315
