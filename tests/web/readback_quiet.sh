#!/usr/bin/env bash
# readback_quiet.sh SITE_DIR STEP OUT_DIR: a chapter that reads the sea back from the GPU (step07's
# map_readback.hpp) runs 60 frames in headless chromium (tests/web/page.js) with chromium's
# warnings about its read-back buffer ("READ-usage buffer was written, then fenced, but written
# again before being read back", "... read back without waiting on a fence") at most once: the
# read-back done as chromium does not expect logs one a frame, and the console a learner opens
# then shows nothing else (step07_buoyancy/map_readback.cpp). The sea at resolution 64: the same
# read-back, smaller, so that 60 frames take about 15 s in SwiftShader rather than 45.
# Skipped (77) as tests/web/smoke.sh is, where there is no web build or no browser to drive.
set -u
site=$1 step=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
. "$here/browser_ready.sh"  # missing, browser_ready
[ -f "$site/$step.js" ] || missing "no web build of $step in $site"
browser_ready "$site"
mkdir -p "$out"
NODE_PATH=$modules node "$here/page.js" "$site" "$step" "$out" readback_quiet \
  --no-ui --frames 60 --set resolution=64 --time 0.5 --dt 0.05 --size 160x90 > /dev/null || { cat "$out/readback_quiet.log"; exit 1; }
warnings=$(grep -c "READ-usage buffer" "$out/readback_quiet.log")
if [ "$warnings" -gt 1 ]; then
  grep -m 3 "READ-usage buffer" "$out/readback_quiet.log"
  echo "FAIL: $warnings warnings about the read-back buffer in 60 frames (at most 1)"
  exit 1
fi
echo "ok: $warnings warnings about the read-back buffer in 60 frames ($(grep -m1 '^exit status' "$out/readback_quiet.log"))"
