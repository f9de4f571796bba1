# browser_ready.sh, sourced by the browser tests (smoke.sh, readback_quiet.sh, lessons.sh):
#   missing REASON     skipped (77) where there is no web build or nothing to drive it (./ocean web
#                      makes both); in CI (CI=true), where .ci/run builds them first, a failure.
#   browser_ready SITE sets `modules` to the node_modules beside SITE, after checking that
#                      playwright-core, chromium and node are there.
missing() {
  if [ "${CI:-}" = true ]; then echo "FAIL: $1 (CI builds the pages first: ./ocean web --no-serve)"; exit 1; fi
  echo "skipped: $1 (./ocean web builds the pages and installs what drives them)"; exit 77
}
browser_ready() {
  modules=$(cd "$1/.." 2> /dev/null && pwd)/node_modules
  [ -d "$modules/playwright-core" ] || missing "no playwright-core in $modules"
  [ -x /usr/bin/chromium ] && command -v node > /dev/null || missing "no /usr/bin/chromium or no node"
}
