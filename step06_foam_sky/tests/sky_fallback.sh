#!/usr/bin/env bash
# sky_fallback.sh STEP_EXE missing|corrupt OUT_DIR: a sky_image that cannot be read must give a
# warning naming it and the procedural sky, and the run goes on (exit 0), with no GL error.
set -u
exe=$1 case_name=$2 out=$3
mkdir -p "$out"
case "$case_name" in
  missing) file="$out/no-such-sky.hdr"; rm -f "$file" ;;
  corrupt) file="$out/corrupt-sky.png"; printf '\x89PNG\r\n\x1a\nnot an image' > "$file" ;;
  *) echo "sky_fallback.sh: unknown case $case_name"; exit 2 ;;
esac
log=$("$exe" --headless --frames 2 --size 64x36 --set "sky_image=$file" 2>&1)
status=$?
echo "$log"
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status"; exit 1; }
echo "$log" | grep -q "warning: sky_image '$file'.*using the procedural sky" || { echo "FAIL: no warning"; exit 1; }
if echo "$log" | grep -q '^GL '; then echo "FAIL: GL errors"; exit 1; fi
echo "ok: $case_name sky image -> warning and the procedural sky"
