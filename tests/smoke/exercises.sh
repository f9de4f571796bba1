#!/usr/bin/env bash
# exercises.sh EXERCISE_EXE REPO: every exercise's starter fails its check, and the chapter's own
# code (the solution: the step's shader, copied over the learner's file) passes it. The checks
# also refuse known slips: the seed's Fresnel without F0, the notes' slope without w a, and a
# normal pointing into the water.
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
# The notes' 2.2 slope, cos(x w + phase) without w a, must not pass step01's exercise 2.
dir="$work/seed-slope"
"$exe" prepare step01_sine2d 2 "$dir" > /dev/null
sed -i 's|    return 0.0;|    return cos(x * u_waves[i].x + u_waves[i].z);|' "$dir/sine_sum.glsl"
if "$exe" check step01_sine2d 2 "$dir" > /dev/null 2>&1; then echo "FAIL: the notes' slope without w a passes"; status=1; fi
# The notes' 2.2 gradient, cos(angle) d without w a, must not pass step03's exercise 2.
dir="$work/seed-gradient"
"$exe" prepare step03_lighting 2 "$dir" > /dev/null
sed -i 's|    return vec3(wave_height(xz), 0.0, 0.0);|    vec3 r = vec3(0.0);\n    for (int i = 0; i < u_wave_count; ++i) {\n        float angle = dot(u_waves[i].xy, xz) * u_waves[i].z + u_wave_phases[i];\n        r += vec3(u_waves[i].w * sin(angle), cos(angle) * u_waves[i].xy);\n    }\n    return r;|' "$dir/wave_gradient.glsl"
if "$exe" check step03_lighting 2 "$dir" > "$dir.log" 2>&1; then echo "FAIL: the notes' gradient without w a passes"; status=1; fi
grep -q "wave_height_gradient(a.xy).y" "$dir.log" || { echo "FAIL: the notes' gradient did not fail on its slope"; cat "$dir.log"; status=1; }
# A facet normal that is not turned up (half the facets face down) must not pass step02's exercise 2.
dir="$work/unturned-facet"
"$exe" prepare step02_sine3d 2 "$dir" > /dev/null
sed -i 's|    return vec3(0.0, 1.0, 0.0);|    return normalize(cross(along_x, along_y));|' "$dir/facet.glsl"
if "$exe" check step02_sine3d 2 "$dir" > /dev/null 2>&1; then echo "FAIL: the facet normal not turned up passes"; status=1; fi
# T x B, the normal pointing into the water, must not pass step04's exercise 2.
dir="$work/downward-normal"
"$exe" prepare step04_fbm 2 "$dir" > /dev/null
sed -i 's|    return vec3(0.0, 1.0, 0.0);|    return normalize(cross(vec3(1.0, gradient.x, 0.0), vec3(0.0, gradient.y, 1.0)));|' "$dir/fbm.glsl"
if "$exe" check step04_fbm 2 "$dir" > /dev/null 2>&1; then echo "FAIL: the downward normal T x B passes"; status=1; fi
[ "$count" -gt 0 ] || { echo "FAIL: no exercises listed"; status=1; }
exit $status
