#!/usr/bin/env bash
# panel_fits.sh STEP_EXE: the step's panel as a headless run draws it (--ui), at its first-use width
# in 640x360 and 960x540: nothing in it reaches past its right edge, where ImGui would cut it off
# (App::draw_panel names the first part that does: "warning: panel: ...").
set -u
exe=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for size in 640x360 960x540; do
  if ! "$exe" --headless --ui --size "$size" --frames 2 --screenshot "$out/panel.png" > "$out/log" 2>&1; then
    cat "$out/log"
    echo "FAIL: the step failed at $size"
    exit 1
  fi
  if grep -q '^warning: panel: ' "$out/log"; then
    grep '^warning: panel: ' "$out/log"
    echo "FAIL: at $size a part of the panel is cut off at its edge"
    exit 1
  fi
  echo "ok: at $size the whole panel fits its width"
done
