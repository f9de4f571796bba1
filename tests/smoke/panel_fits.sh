#!/usr/bin/env bash
# panel_fits.sh STEP_EXE IMAGE_COMPARE: the step's panel as a headless run draws it (--ui), at its
# first size in 640x360 and 960x540:
#  - it covers at most a quarter of the picture and lies inside it (all four edges): measured on
#    the screenshot, as the pixels that differ from the same frame without the panel (--time 1:
#    the same picture twice; image_compare --box);
#  - nothing in it reaches past its right edge, where ImGui would cut it off (App::draw_panel names
#    the first part that does: "warning: panel: ...").
set -u
exe=$1
image_compare=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for size in 640x360 960x540; do
  width=${size%x*}
  height=${size#*x}
  for panel in ui plain; do
    flags=(--headless --size "$size" --frames 2 --time 1 --screenshot "$out/$panel.png")
    [ "$panel" = ui ] && flags+=(--ui)
    if ! "$exe" "${flags[@]}" > "$out/$panel.log" 2>&1; then
      cat "$out/$panel.log"
      echo "FAIL: the step failed at $size ($panel)"
      exit 1
    fi
  done
  if grep -q '^warning: panel: ' "$out/ui.log"; then
    grep '^warning: panel: ' "$out/ui.log"
    echo "FAIL: at $size a part of the panel is cut off at its edge"
    exit 1
  fi
  box=$("$image_compare" "$out/ui.png" "$out/plain.png" --box --threshold 8) || {
    echo "FAIL: image_compare could not measure the panel at $size"
    exit 1
  }
  read -r _ x0 y0 x1 y1 <<< "$box"
  [ "$x0" = none ] && { echo "FAIL: at $size --ui drew no panel"; exit 1; }
  share=$(awk -v w="$width" -v h="$height" -v a="$x0" -v b="$y0" -v c="$x1" -v d="$y1" \
    'BEGIN { printf "%.1f", 100 * (c - a + 1) * (d - b + 1) / (w * h) }')
  echo "at $size the panel covers $((x1 - x0 + 1))x$((y1 - y0 + 1)) at ($x0, $y0): $share % of the picture"
  awk -v s="$share" 'BEGIN { exit !(s <= 25.0) }' || {
    echo "FAIL: at $size the panel covers $share % of the picture, more than a quarter"
    exit 1
  }
  if [ "$x0" -le 0 ] || [ "$y0" -le 0 ] || [ "$x1" -ge $((width - 1)) ] || [ "$y1" -ge $((height - 1)) ]; then
    echo "FAIL: at $size the panel ($x0, $y0)-($x1, $y1) reaches an edge of the $size picture"
    exit 1
  fi
  echo "ok: at $size the panel fits: at most a quarter of the picture, inside it, nothing cut at its edge"
done
