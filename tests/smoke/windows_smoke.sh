#!/usr/bin/env bash
# windows_smoke.sh WINDOWS_BUILD IMAGE_COMPARE: each chapter's smoke test (smoke.sh) on its Windows
# .exe under wine (./ocean windows --smoke runs it under Xvfb): the run exits 0 with no GL error,
# and its picture matches the chapter's golden within smoke.sh's limits, the ones Linux is held to.
# The list, with each golden and its flags, is the one the build wrote (BUILD/smoke_runs.txt).
set -u
build=$1 compare=$2
failed=()
wineboot --init > /dev/null 2>&1  # the prefix, made once, before the first timed run
while read -r step golden flags; do
  # shellcheck disable=SC2086  # the step's flags, one word each
  out="$build/test-output/smoke/$step"
  mkdir -p "$out"
  if OCEAN_RUNNER=wine bash "$(dirname "$0")/smoke.sh" "$build/$step/$step.exe" "$compare" "$golden" "$out" $flags \
       > "$out/run.log" 2>&1; then
    echo "windows smoke: $step: $(tail -n 1 "$out/run.log")"
  else
    cat "$out/run.log"
    echo "windows smoke: $step FAILED"
    failed+=("$step")
  fi
done < "$build/smoke_runs.txt"
[ ${#failed[@]} -eq 0 ] || { echo "windows smoke: failed: ${failed[*]}"; exit 1; }
echo "windows smoke: every chapter passed under wine"
