#!/usr/bin/env bash
# every_view.sh STEP_EXE: each choice of the step's `view` parameter renders two small headless
# frames and exits 0 (a headless run exits 3 on any GL error). A step without `view` passes.
set -u
exe="$1"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
choices=$("$exe" --list-params | awk '$1 == "view" { print $3 }' | tr '|' ' ')
if [ -z "$choices" ]; then echo "no view parameter"; exit 0; fi
status=0
for view in $choices; do
  if "$exe" --headless --size 160x90 --frames 2 --time 1 --set "view=$view" --screenshot "$out/$view.png" \
       >"$out/log" 2>&1; then
    echo "view=$view: ok"
  else
    echo "view=$view: FAILED (exit $?)"; cat "$out/log"; status=1
  fi
done
exit $status
