#!/usr/bin/env bash
# split.sh STEP_EXE SPLIT_CHECK OUT_DIR LEFT_SET RIGHT_SET [FLAGS...]: --split against two plain
# renders of its variants (same time, size, camera and FLAGS).
set -u
exe=$1 check=$2 out=$3 left=$4 right=$5
shift 5
mkdir -p "$out"
name=$(basename "$exe")
common=(--headless --frames 2 --time 1.5 --size 256x144 "$@")
"$exe" "${common[@]}" --split --screenshot "$out/$name.split.png" > /dev/null || exit 1
"$exe" "${common[@]}" --set "$left" --screenshot "$out/$name.left.png" > /dev/null || exit 1
"$exe" "${common[@]}" --set "$right" --screenshot "$out/$name.right.png" > /dev/null || exit 1
"$check" "$out/$name.split.png" "$out/$name.left.png" "$out/$name.right.png"
