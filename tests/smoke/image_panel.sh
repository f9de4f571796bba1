#!/usr/bin/env bash
# image_panel.sh TOOL PICTURE OUT_DIR: the README figure tool lays out, crops and box-averages a
# picture, and refuses a bad crop or a missing file with one line and exit 2 / 1.
set -u
tool="$1" picture="$2" out="$3"
mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }
"$tool" "$out/panel.png" 160x90 2 "whole|$picture" "top left quarter|$picture|0,0,0.5,0.5" \
  || fail "a good panel did not draw"
[ -s "$out/panel.png" ] || fail "no panel written"
msg=$("$tool" "$out/bad.png" 160x90 2 "bad|$picture|0.5,0,0.2,1" 2>&1); status=$?
[ $status -eq 2 ] && [ "$(echo "$msg" | grep -c '')" -eq 1 ] || fail "bad crop: exit $status, '$msg'"
msg=$("$tool" "$out/bad.png" 160x90 1 "missing|$out/none.png" 2>&1); status=$?
[ $status -eq 1 ] && [ "$(echo "$msg" | grep -c '')" -eq 1 ] || fail "missing file: exit $status, '$msg'"
echo "image_panel: ok"
