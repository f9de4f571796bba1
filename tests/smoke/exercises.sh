#!/usr/bin/env bash
# exercises.sh EXERCISE_EXE REPO: every exercise's starter fails its check, and the chapter's own
# code (the solution: the step's shader, copied over the learner's file) passes it; every exercise
# has its formula, the second hint (`exercise hint STEP N`: a non-empty line after the title). The checks
# also refuse known slips: the notes' Fresnel without F0, their slope without w a, their e^{+i omega t}
# and -i choppiness, a normal pointing into the water, GGX without 1/pi, and a spectrum centred the
# wrong way.
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
  solution="$repo/$step/shaders/$file"
  [ -f "$solution" ] || solution="$repo/$step/$file"  # a C++ exercise: a file of the step's folder
  cp "$solution" "$dir/$file"
  "$exe" check "$step" "$number" "$dir" > "$dir.log" 2>&1 || { echo "FAIL: the solution of $step $number fails"; cat "$dir.log"; status=1; }
  # The second hint: the title, then the formula (a non-empty line).
  formula=$("$exe" hint "$step" "$number" | sed -n '2p')
  [ -n "${formula// /}" ] || { echo "FAIL: $step $number has no formula (exercise hint $step $number)"; status=1; }
  echo "$step $number: the starter fails, the solution passes"
done < <("$exe" list)
# refuses NAME STEP N FILE STUB_LINE BODY WHAT: exercise N of STEP with its stub line replaced by
# BODY (a known slip) must fail its check; with WHAT, the failure must name that expression.
refuses() {
  local name=$1 step=$2 number=$3 file=$4 stub=$5 body=$6 what=${7:-}
  local dir="$work/$name"
  "$exe" prepare "$step" "$number" "$dir" > /dev/null
  sed -i "s|$stub|$body|" "$dir/$file"
  if "$exe" check "$step" "$number" "$dir" > "$dir.log" 2>&1; then echo "FAIL: $name passes $step $number"; status=1; return; fi
  [ -z "$what" ] || grep -qF "$what" "$dir.log" || { echo "FAIL: $name did not fail on $what"; cat "$dir.log"; status=1; }
}
# Archimedes without the torque: the force alone does not tip a heeled hull back.
refuses force-without-torque step07_buoyancy 2 hull_forces.cpp '    return {};' '    Wrench w; for (std::size_t i = 0; i < cells.size(); ++i) w.force.y += kWaterDensity * ocean::kGravity * wet_share(water_lines[i], centre_of_mass.y + (rotation * cells[i].offset).y, vertical_half_extent(rotation, cells[i])) * cells[i].volume; return w;' 'value 3'
# A mode turned without its sources (free rotation only): no dent under the boat, no wake.
refuses mode-without-sources step08_wakes 1 mode_step.cpp '    return mode;' '    if (K == 0) return mode; const double w = std::sqrt(9.81 * K); return {mode.eta * std::cos(w * dt) + (K / w) * mode.phi * std::sin(w * dt), mode.phi * std::cos(w * dt) - (9.81 / w) * mode.eta * std::sin(w * dt)};'
# Kelvin's angle with the energy at the phase speed (n taken as 1 everywhere): every wake 90 degrees.
refuses kelvin-phase-speed step08_wakes 2 kelvin.cpp '    return 0;' '    return std::asin(1.0);' 'value 0'
# The overhead sun's focus kept for a slanted sun: right at noon, wrong for every other sun.
refuses overhead-focus-for-a-low-sun step10_underwater 3 lens.cpp '    return 0;' '    return kWaterIndex / ((kWaterIndex - 1) * amplitude * wavenumber * wavenumber);' 'value 0'
# The image a source instead of a sink (a rigid lid): phi is no longer 0 on the surface.
refuses rigid-lid-image step09_radiation 1 image_source.cpp '    return {};' '    SourceAt at; for (int m = 0; m < 2; ++m) { const glm::dvec3 d = x - (m ? glm::dvec3(xi.x, -xi.y, xi.z) : xi); const double r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z); at.potential += -1 / (4 * ocean::kPi * r); at.along += (d.x * n.x + d.y * n.y + d.z * n.z) / (4 * ocean::kPi * r * r * r); } return at;' 'value 0'
# The water through the surface from the source alone, its image forgotten: half of it.
refuses surface-flow-without-image step09_radiation 2 image_source.cpp '    return 0;' '    const double r = std::sqrt(across * across + depth * depth); return depth / (4 * ocean::kPi * r * r * r);' 'value 0'
# The notes' Fresnel, F = (1 - cos theta)^5, forgets F0.
refuses notes-fresnel step06_foam_sky 1 shading.glsl '    return 0.0;' '    return pow(1.0 - clamp(cos_theta, 0.0, 1.0), 5.0);'
# The notes' 2.2 slope, cos(x w + phase) without w a.
refuses notes-slope step01_sine2d 2 sine_sum.glsl '    return 0.0;' '    return cos(x * u_waves[i].x + u_waves[i].z);'
# The curvature with the sign of the height (the derivative of cos taken as +sin): crests bend up.
refuses curvature-sign step01_sine2d 3 sine_sum.glsl '    return 0.0;' '    return u_waves[i].y * u_waves[i].x * u_waves[i].x * sin(x * u_waves[i].x + u_waves[i].z);' \
  'sum_of_sines_curvature(a.x)'
# The notes' 2.2 gradient in 2D, cos(angle) d without w a: it must fail on the slope.
refuses notes-gradient step03_lighting 2 wave_gradient.glsl '    return vec3(wave_height(xz), 0.0, 0.0);' \
  '    vec3 r = vec3(0.0);\n    for (int i = 0; i < u_wave_count; ++i) {\n        float angle = dot(u_waves[i].xy, xz) * u_waves[i].z + u_wave_phases[i];\n        r += vec3(u_waves[i].w * sin(angle), cos(angle) * u_waves[i].xy);\n    }\n    return r;' \
  'wave_height_gradient(a.xy).y'
# A ripple whose amplitude falls as 1 / r (the amplitude spread round the circle, not the energy).
refuses ripple-amplitude-spread step02_sine3d 3 ripple.glsl '    return 0.0;' \
  '    float r = distance(xz, u_ripple.xy), l = 6.2831853 / u_ripple.z;\n    return u_ripple.w * (l / max(r, l)) * sin(r * u_ripple.z + u_ripple_phase);' \
  'ripple_height(a.xy)'
# Phong's mirrored sun with Blinn-Phong's exponent unchanged: a glint half as wide as Blinn-Phong's.
refuses phong-blinn-exponent step03_lighting 3 lighting.glsl '    return 0.0;' \
  '    float f = dot(normal, u_to_sun);\n    return f > 0.0 ? pow(max(dot(reflect(-u_to_sun, normal), to_eye), 0.0), u_shininess) : 0.0;' \
  'phong_specular(n, v)'
# A facet normal not turned up: half the facets face down.
refuses unturned-facet step02_sine3d 2 facet.glsl '    return vec3(0.0, 1.0, 0.0);' '    return normalize(cross(along_x, along_y));'
# T x B, the normal pointing into the water.
refuses downward-normal step04_fbm 2 fbm.glsl '    return vec3(0.0, 1.0, 0.0);' \
  '    return normalize(cross(vec3(1.0, gradient.x, 0.0), vec3(0.0, gradient.y, 1.0)));'
# The notes' 4.3, h0(k) e^{+i omega t}: crests upwind.
refuses notes-evolution step05_fft 4 mode.glsl '    return h0_k;' \
  '    vec2 r = vec2(cos(phase), sin(phase));\n    return complex_multiply(h0_k, r) + complex_multiply(vec2(h0_minus_k.x, -h0_minus_k.y), vec2(r.x, -r.y));'
# The notes' 4.5, D = -i k/|k| h: folds in the troughs (the first pair, h + i Dx, shows it).
refuses notes-choppiness step05_fft 7 mode.glsl '    vec2 pairs\[4\] = vec2\[4\](h, vec2(0.0), vec2(0.0), vec2(0.0));' \
  '    vec2 u = k / max(length(k), 1e-9);\n    vec2 pairs[4] = vec2[4]((1.0 + u.x) * h, vec2(0.0), vec2(0.0), vec2(0.0));' \
  'packed_pairs(a.xy, 2.0 * a.zw)[0].x'
# GGX without its 1/pi: the shape, not the normalisation.
refuses unnormalised-ggx step06_foam_sky 5 shading.glsl '    return pow(max(n_dot_h, 0.0), 2.0 / (alpha * alpha) - 2.0);' \
  '    float d = n_dot_h * n_dot_h * (alpha * alpha - 1.0) + 1.0;\n    return alpha * alpha / (d * d);'
# The texel's index used as the frequency everywhere (no negative half): fails on k's x.
refuses unsigned-frequency step05_fft 3 mode.glsl '    return (6.2831853 / patch_size) \* vec2(texel);' \
  '    return (6.2831853 / patch_size) * vec2(texel - n / 2);'
# The notes' h0 = xi sqrt(Phi dk^2 / 2): forgets that conj(h0(-k)) doubles every mode's energy.
refuses notes-h0 step05_fft 8 mode_amplitude.cpp '    return {0.0, 0.0};' \
  '    return std::complex<double>(xi_real, xi_imaginary) * std::sqrt(energy / 2);' 'got 1.99'
# The warp's Jacobian moved past the wave before its gradient is carried back (the Jacobian of the
# next wave's point, not this one's), and the Jacobian without its transpose.
refuses warp-jacobian-too-late step04_fbm 3 fbm.glsl '    total.yz += slope;' \
  '    jacobian = (mat2(1.0) - u_warp * a * a * w * w * shape.z * outerProduct(d, d)) * jacobian;\n    total.yz += transpose(jacobian) * slope;' \
  'fbm_height_gradient(a.xy).y'
refuses warp-jacobian-untransposed step04_fbm 3 fbm.glsl '    total.yz += slope;' \
  '    total.yz += jacobian * slope;\n    jacobian = (mat2(1.0) - u_warp * a * a * w * w * shape.z * outerProduct(d, d)) * jacobian;' \
  'fbm_height_gradient(a.xy).y'
# Bands that overlap: each cascade from its own boundary up to all its grid resolves.
refuses overlapping-bands step06_foam_sky 7 cascade_bands.cpp \
  '    for (int c = 0; c < kCascades; ++c) bands\[std::size_t(c)\] = {0.0, ocean::kPi \* resolution / patch_sizes\[std::size_t(c)\]};' \
  '    for (int c = 0; c < kCascades; ++c) bands[std::size_t(c)] = {c == 0 ? 0.0 : 2 * ocean::kPi * kWavesPerTileAtBoundary / patch_sizes[std::size_t(c)], ocean::kPi * resolution / patch_sizes[std::size_t(c)]};'
# GPU Gems' cubed sine centred on the middle of its range, 1/2, not on its mean over a period, 5/16:
# the sea floats down (step04 4).
refuses power-sine-middle step04_fbm 4 fbm.glsl '    return vec3(sin(theta), cos(theta), -sin(theta));' \
  '    float s = sin(theta), c = cos(theta), u = 0.5 * (1.0 + s);\n    return 0.86466472 * vec3(u * u * u - 0.5, 1.5 * u * u * c, 1.5 * (u * c * c - u * u * s));' \
  'power_sine_shape(a.x).x'
# sech^2 normalised over the whole line (beta / 2), as if the lobe ended before +-pi: the short
# waves' wide lobes lose energy (step05 10).
refuses sech2-whole-line step05_fft 10 donelan_banner.cpp '    return 0;' \
  '    const double sech = 1 / std::cosh(beta * theta); return beta / 2 * sech * sech;' 'value 0'
# A sphere heaving with the box's period, 2 pi / sqrt(g / d - c^2 / 4), as if its waterplane were
# the same at every draft (step07 3).
refuses box-heave-sphere step07_buoyancy 3 hull_forces.cpp '    return 0;' \
  '    return 2 * ocean::kPi / std::sqrt(ocean::kGravity / draft - 0.25 * linear_drag * linear_drag);' 'value 0'
[ "$count" -gt 0 ] || { echo "FAIL: no exercises listed"; status=1; }
exit $status
