#!/usr/bin/env bash
# exercises.sh EXERCISE_EXE REPO: every exercise's starter fails its check, and the chapter's own
# code (the solution: the step's shader, copied over the learner's file) passes it. Schlick's
# exercise also refuses the seed's slip, (1 - cos)^5 without F0.
set -u
exe=$1 repo=$2
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0 count=0
while read -r step number rest; do
  [ -n "$step" ] || continue
  count=$((count + 1))
  dir="$work/$step-$number"
  file=$(echo "$rest" | sed 's/.*(\(.*\))$/\1/')
  "$exe" prepare "$step" "$number" "$dir" > /dev/null || { echo "FAIL: prepare $step $number"; status=1; continue; }
  if "$exe" check "$step" "$number" "$dir" > "$dir.log" 2>&1; then
    echo "FAIL: the untouched starter of $step $number passes"; cat "$dir.log"; status=1
  else
    grep -q '^hint: ' "$dir.log" || { echo "FAIL: $step $number failed without a hint"; cat "$dir.log"; status=1; }
  fi
  cp "$repo/$step/shaders/$file" "$dir/$file"
  "$exe" check "$step" "$number" "$dir" > "$dir.log" 2>&1 || { echo "FAIL: the solution of $step $number fails"; cat "$dir.log"; status=1; }
  echo "$step $number: the starter fails, the solution passes"
done < <("$exe" list)
# The seed's Fresnel, F = (1 - cos theta)^5, forgets F0: it must not pass.
dir="$work/seed-fresnel"
"$exe" prepare step06_foam_sky 1 "$dir" > /dev/null
sed -i 's|    return 0.0;|    return pow(1.0 - clamp(cos_theta, 0.0, 1.0), 5.0);|' "$dir/shading.glsl"
if "$exe" check step06_foam_sky 1 "$dir" > /dev/null 2>&1; then echo "FAIL: the seed's Fresnel passes"; status=1; fi
[ "$count" -gt 0 ] || { echo "FAIL: no exercises listed"; status=1; }
exit $status
