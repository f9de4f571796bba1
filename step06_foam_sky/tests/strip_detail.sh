# Sourced by combined_levels.sh and combined_surface.sh (with exe, check and out set): `detail NAME
# [flags...]` renders the mid-distance strip of the README's anisotropy figure (640 x 360, t = 4 s,
# no bloom) and prints its detail across the view (picture_check detail, rows 0.3 to 0.6).
detail() {
  local name=$1
  shift
  "$exe" --headless --size 640x360 --frames 11 --time 4 --dt 0.1 --set show_bloom=false --set dither=false \
    --screenshot "$out/$name.png" "$@" > /dev/null || { echo "FAIL: the step did not run: $*" >&2; return 1; }
  "$check" detail "$out/$name.png" 0.3 0.6 | sed -n 's/.*detail across the view \([0-9.]*\).*/\1/p'
}
