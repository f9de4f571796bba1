#!/usr/bin/env bash
# smoke.sh SITE_DIR STEP IMAGE_COMPARE GOLDEN.png OUT_DIR [--query=Q] [FLAGS...]
# A chapter's page in headless chromium (tests/web/page.js): the native smoke test's run (6 frames
# of 0.2 s from t = 0.5 s at 320x180, tests/smoke/smoke.sh) with the panel hidden, compared with the
# same golden. The browser draws through SwiftShader, not llvmpipe: its far sparkles and the sea's
# edge pixels land a little differently, so the tolerance is the native one widened (RMSE <= 4/255,
# at most 1 % of pixels off by more than 24/255; measured: the README's tests table, STEP.web.smoke;
# SMOKE_RMSE and SMOKE_BAD_FRACTION, where a test sets them, are its own limits, and where they are
# set says why).
# With --query=Q the address also carries Q (name=value&...): the picture must then DIFFER from the
# golden, the check that a parameter set from the address reaches the program. FLAGS go to the
# program after the run's own (the step's SMOKE_FLAGS, add_step: what its golden holds still).
# Skipped (77) where there is no web build or no browser to drive (./ocean web makes both); in CI
# (CI=true), where .ci/run builds them first, their absence is a failure.
set -u
site=$1 step=$2 compare=$3 golden=$4 out=$5 query=
shift 5
if [ $# -gt 0 ] && [ "${1#--query=}" != "$1" ]; then query=$1; shift; fi
here=$(cd "$(dirname "$0")" && pwd)
. "$here/browser_ready.sh"  # missing, browser_ready
[ -f "$site/$step.js" ] || missing "no web build of $step in $site"
browser_ready "$site"
name=$(basename "$golden" .png)${query:+.query}
mkdir -p "$out"
rm -f "$out/$name.png" "$out/$name.diff.png"
NODE_PATH=$modules node "$here/page.js" "$site" "$step" "$out" "$name" ${query:+"$query"} \
  --no-ui --frames 6 --time 0.5 --dt 0.2 --size 320x180 --screenshot /smoke.png "$@" || exit 1
[ -s "$out/$name.png" ] || { echo "FAIL: the page wrote no screenshot"; exit 1; }
if [ -n "$query" ]; then
  if "$compare" "$out/$name.png" "$golden" --rmse 4 --bad-fraction 0.01 > /dev/null 2>&1; then
    echo "FAIL: with ?${query#--query=} the picture is still the golden's: the parameter did not reach the program"
    exit 1
  fi
  echo "ok: ?${query#--query=} changes the picture"
  exit 0
fi
"$compare" "$out/$name.png" "$golden" --rmse "${SMOKE_RMSE:-4}" --bad-fraction "${SMOKE_BAD_FRACTION:-0.01}" \
  --diff "$out/$name.diff.png"
