#!/usr/bin/env bash
# lessons.sh REPO SITE_DIR: the lessons reached from the index are web pages a learner can read
# (tests/web/lessons.js: HTML, their pictures loaded, their links answering). Skipped (77) where
# there is no web build or nothing to drive it (./ocean web makes both); in CI (CI=true), where
# .ci/run builds them first, their absence is a failure.
set -u
repo=$1 site=$2
here=$(cd "$(dirname "$0")" && pwd)
. "$here/browser_ready.sh"  # missing, browser_ready
[ -f "$site/index.html" ] || missing "no index page in $site"
[ -d "$site/lessons" ] || missing "no lessons' pages in $site/lessons (./ocean web renders them where npm installed marked)"
browser_ready "$site"
NODE_PATH=$modules exec node "$here/lessons.js" "$repo" "$site"
