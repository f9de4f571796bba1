// The exercises: for each, the chapter's file and function it empties, the stub, the task, the
// hint, and the check that holds the learner's function to the chapter's CPU reference.
#include "tools/exercise.hpp"

#include "step01_sine2d/sine_sum.hpp"
#include "step02_sine3d/wave_uniforms.hpp"
#include "step03_lighting/lighting.hpp"
#include "step04_fbm/fbm.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/fog.hpp"
#include "step06_foam_sky/shading.hpp"
#include "step06_foam_sky/tessellation.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace exercises {

namespace {

// The waves the checks of steps 01 and 02 give the learner's functions, at t = 1.7 s.
constexpr double kCheckTime = 1.7;
const std::vector<step01::Wave> kStep01Waves{{8.0, 0.5, 1.2}, {3.1, 0.2, -0.7}, {1.7, 0.08, 0.9}};
const std::vector<step02::DirectionalWave> kStep02Waves{{20, 14.0, 0.6, 3.0}, {75, 6.5, 0.25, 2.1}, {-40, 3.2, 0.1, 1.4}};

// step01's uniforms as its main.cpp sets them: (w, a, -t phi mod 2 pi, 0) per wave.
void set_step01_waves(const ocean::ShaderProgram& p) {
    std::vector<glm::vec4> packed;
    for (const step01::Wave& w : kStep01Waves)
        packed.emplace_back(float(step01::angular_wavenumber(w)), float(w.amplitude),
                            float(step01::phase_at(step01::phase_rate(w), kCheckTime)), 0.0f);
    p.set("u_wave_count", int(packed.size()));
    p.set("u_waves", packed);
}

// A sample of step05's maps from a and b: displacement (0, 0, 0, l dDx/dz), slopes (dh/dx, dh/dz,
// l dDx/dx, l dDz/dz), as GLSL and as the CPU's OceanMaps (one cell, choppiness 1).
const char* kStep05Sample = "vec4(0.0, 0.0, 0.0, b.x), a";
step05::OceanMaps step05_cell(const glm::dvec4& a, const glm::dvec4& b) {
    step05::OceanMaps maps;
    maps.n = 1;
    for (auto& field : maps.fields) field.assign(1, 0.0);
    maps.fields[step05::SlopeX][0] = a.x;
    maps.fields[step05::SlopeZ][0] = a.y;
    maps.fields[step05::DDxDx][0] = a.z;
    maps.fields[step05::DDzDz][0] = a.w;
    maps.fields[step05::DDxDz][0] = b.x;
    return maps;
}

// step03's light with the sun at `sun`, a white sun, the default water and shininess 64.
step03::Light step03_light(const Vec3& sun) {
    step03::Light light;
    light.to_sun = sun;
    light.sun = {1, 1, 1};
    light.water = {0.05, 0.25, 0.35};
    light.ambient = {0.02, 0.04, 0.06};
    light.shininess = 64;
    return light;
}

// step03's light_terms on the GPU, one term: its uniforms set as step03_light says.
Verdict check_step03_term(const fs::path& work, const std::string& term, double (*pick)(const step03::LightTerms&)) {
    static const Vec3 sun = step03::normalize({0.4, 0.5, -0.3});
    const step03::Light light = step03_light(sun);
    return check_glsl(
        work, "lighting.glsl", "light_terms(n, v)." + term,
        [&](const Vec3& n, const Vec3& v, const Vec3&, double) { return pick(step03::light_terms(n, v, light)); }, 1e-4,
        [&](const ocean::ShaderProgram& p) {
            p.set("u_to_sun", glm::vec3(float(sun.x), float(sun.y), float(sun.z)));
            p.set("u_sun_color", glm::vec3(1.0f));
            p.set("u_water_color", glm::vec3(float(light.water.r), float(light.water.g), float(light.water.b)));
            p.set("u_ambient_color", glm::vec3(float(light.ambient.r), float(light.ambient.g), float(light.ambient.b)));
            p.set("u_shininess", float(light.shininess));
        },
        &sun);
}

// step05's packed pairs, all eight real numbers one after the other (pair f, real then imaginary).
Verdict check_packed_pairs(const fs::path& work) {
    Verdict verdict;
    for (int f = 0; f < 4 && (f == 0 || verdict.pass); ++f)
        for (int part = 0; part < 2 && (part == 0 || verdict.pass); ++part)
            verdict = check_values(
                work, "ocean_layout.glsl,mode.glsl",
                "packed_pairs(a.xy, 2.0 * a.zw)[" + std::to_string(f) + "]." + "xy"[part],
                [f, part](const glm::dvec4& a, const glm::dvec4&) {
                    const auto pairs = step05::packed_pairs({a.x, a.y}, 2 * a.z, 2 * a.w);
                    return part == 0 ? pairs[std::size_t(f)].real() : pairs[std::size_t(f)].imag();
                },
                1e-4, -1, 1);
    return verdict;
}

// step06's fog, as the amount of fog colour (surface black, fog white), for eyes 2-52 m up and
// points on the sea within 1.5 km.
constexpr double kFogDensity = 0.0012, kFogFalloff = 0.02;
const char* kFogRay = "vec3(100.0 * a.x, 27.0 + 25.0 * a.y, 100.0 * a.z), vec3(1500.0 * b.x, 3.0 * b.y, 1500.0 * b.z)";

// step06's tessellation uniforms in the checks: an eye 12 m up, 16 m patches, scale 12 (the defaults).
const glm::dvec3 kTessEye(10.0, 12.0, -20.0);
constexpr double kTessPatch = 16, kTessScale = 12;

}  // namespace

std::vector<Exercise> all() {
    using step06::Microfacet;
    return {
        {"step01_sine2d", 1, "One sine wave", "sine_sum.glsl", "float wave_height(int i, float x) {",
         "    // TODO (exercise 1): the height of wave i at x.\n    return 0.0;\n",
         "Write wave_height: wave i arrives as u_waves[i] = (w, a, phase, 0), w = 2 pi / wavelength already, and\n"
         "its height at x is a sin(x w + phase). Without it the plot is a flat line.",
         "u_waves[i].x is w (radians per metre), .y the amplitude a, .z the phase (-t phi, reduced on the CPU): "
         "a * sin(x * w + phase). The phase is added, not multiplied.",
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) { return step01::sum_of_sines(kStep01Waves, a.x, kCheckTime); },
                 1e-4, -20, 20, set_step01_waves);
         }},
        {"step01_sine2d", 2, "The slope of a sine", "sine_sum.glsl", "float wave_slope(int i, float x) {",
         "    // TODO (exercise 2): d/dx of wave i's height at x.\n    return 0.0;\n",
         "Write wave_slope, the derivative of a sin(x w + phase) with respect to x. The plot uses it to draw\n"
         "its line equally thick on steep slopes: without it the line thins where the wave is steep.",
         "The chain rule brings w out of the sine, and the amplitude stays: a w cos(x w + phase). The notes' 2.2 "
         "writes cos(...) alone, without w a: that is the slope of a wave of one radian per metre and amplitude 1.",
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines_slope(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     return step01::sum_of_sines_slope(kStep01Waves, a.x, kCheckTime);
                 },
                 1e-4, -20, 20, set_step01_waves);
         }},
        {"step02_sine3d", 1, "Waves with a direction", "waves.glsl", "float wave_height(vec2 xz) {",
         "    // TODO (exercise 1): the sum of the directional waves at xz.\n    return 0.0;\n",
         "Write wave_height: the sum over the u_wave_count waves of a sin(dot(d, xz) w + phase), with\n"
         "u_waves[i] = (d.x, d.z, w, a) and the phase in u_wave_phases[i]. Without it the sea is flat.",
         "dot(d, xz) is how far along the wave's direction the point lies: crests are lines across d. "
         "u_waves[i].xy is d, .z is w, .w is a; the phase is its own uniform array, u_wave_phases[i].",
         [](const fs::path& work) {
             return check_values(
                 work, "waves.glsl", "wave_height(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) { return step02::height(kStep02Waves, a.x, a.y, kCheckTime); },
                 1e-4, -60, 60,
                 [](const ocean::ShaderProgram& p) { step02::upload_waves(p, kStep02Waves, kCheckTime); });
         }},
        {"step02_sine3d", 2, "A facet's normal", "facet.glsl", "vec3 facet_normal(vec3 along_x, vec3 along_y) {",
         "    // TODO (exercise 2): the unit normal of the facet spanned by the two edges, facing up.\n"
         "    return vec3(0.0, 1.0, 0.0);\n",
         "Write facet_normal: the cross product of the two edges is perpendicular to both; normalise it, and\n"
         "turn it up (y >= 0) whichever way round the edges come. The starter's normal is straight up: every\n"
         "facet is shaded alike and the waves' shape is hard to read (step02 draws with facet_shading on).",
         "normalize(cross(along_x, along_y)), then negate it when its y is negative: the order of the edges "
         "(and the screen's orientation) decides which side the cross product points to.",
         [](const fs::path& work) {
             return check_vector(
                 work, "facet.glsl", "facet_normal(a.xyz, b.xyz)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     const step02::Vector n = step02::facet_normal({a.x, a.y, a.z}, {b.x, b.y, b.z});
                     return glm::dvec3(n.x, n.y, n.z);
                 },
                 1e-4, -1, 1);
         }},
        {"step03_lighting", 1, "Lambert and Blinn-Phong", "lighting.glsl", "LightTerms light_terms(vec3 normal, vec3 to_eye) {",
         "    // TODO (exercise 1): ambient, Lambert diffuse and Blinn-Phong specular.\n"
         "    LightTerms t;\n    t.ambient = u_ambient_color;\n    t.diffuse = vec3(0.0);\n    t.specular = vec3(0.0);\n"
         "    return t;\n",
         "Write light_terms: diffuse = water * sun * max(N.L, 0) (Lambert); specular = sun * max(N.H, 0)^shininess "
         "with the halfway vector H = normalize(V + L), and no specular when the sun is behind the surface "
         "(N.L <= 0). Without them the sea is flat ambient colour.",
         "H is normalize(to_eye + to_sun), the direction halfway between eye and sun, not the reflection of either; "
         "the specular needs N.L > 0 (a sun below the surface makes no glint) even where N.H is large.",
         [](const fs::path& work) {
             const Verdict diffuse = check_step03_term(work, "diffuse.y", [](const step03::LightTerms& t) { return t.diffuse.g; });
             if (!diffuse.pass) return diffuse;
             return check_step03_term(work, "specular.x", [](const step03::LightTerms& t) { return t.specular.r; });
         }},
        {"step03_lighting", 2, "The slope of the waves", "wave_gradient.glsl", "vec3 wave_height_gradient(vec2 xz) {",
         "    // TODO (exercise 2): (h, dh/dx, dh/dz). For now the height alone: a sea lit as if flat.\n"
         "    return vec3(wave_height(xz), 0.0, 0.0);\n",
         "Write wave_height_gradient: in one loop over the waves, the height a sin(angle) and its two partial\n"
         "derivatives, with angle = dot(d, xz) w + phase. The normal (and so all the light) comes from them.",
         "The derivative of a sin(dot(d, xz) w + phase) along x is a w cos(angle) d.x (the chain rule brings out w "
         "and the direction); the notes' 2.2 forgets the w a. u_waves[i] = (d.x, d.z, w, a).",
         [](const fs::path& work) {
             return check_vector(
                 work, "wave_gradient.glsl", "wave_height_gradient(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const auto g = step03::height_and_gradient(kStep02Waves, a.x, a.y, kCheckTime);
                     return glm::dvec3(g.height, g.dh_dx, g.dh_dz);
                 },
                 1e-4, -60, 60, [](const ocean::ShaderProgram& p) { step02::upload_waves(p, kStep02Waves, kCheckTime); });
         }},
        {"step04_fbm", 1, "The exp-sine wave and its derivatives", "fbm.glsl", "vec3 wave_shape(float theta) {",
         "    // TODO (exercise 1): (W, W', W'') of the exp-sine wave, mean removed. For now, a sine.\n"
         "    return vec3(sin(theta), cos(theta), -sin(theta));\n",
         "Write wave_shape for SHAPE 1: W = e^(sin theta - 1) - 0.46575961 (its mean, so the sea stays at y = 0),\n"
         "W' = dW/dtheta and W'' = d2W/dtheta2. W' makes the normals, W'' the domain warp's Jacobian.\n"
         "The starter is step02's sine: round crests, as wide as the troughs.",
         "d/dtheta e^(sin theta - 1) = e^(sin theta - 1) cos theta; differentiate that product again: "
         "e^(sin theta - 1)(cos^2 theta - sin theta). The mean is subtracted from W only.",
         [](const fs::path& work) {
             return check_vector(
                 work, "fbm.glsl", "wave_shape(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const step04::ShapeValue w = step04::wave_shape(step04::Shape::ExpSine, a.x);
                     return glm::dvec3(w.value, w.first, w.second);
                 },
                 1e-4, -10, 10);
         }},
        {"step04_fbm", 2, "The normal from the gradient", "fbm.glsl", "vec3 fbm_normal(vec2 gradient) {",
         "    // TODO (exercise 2): the unit normal from (dh/dx, dh/dz).\n    return vec3(0.0, 1.0, 0.0);\n",
         "Write fbm_normal: with the tangents T = (1, dh/dx, 0) and B = (0, dh/dz, 1), N = B x T, normalised.\n"
         "The starter's normal is straight up: the sea is lit as if flat.",
         "B x T = (-dh/dx, 1, -dh/dz) before normalising; T x B points down, into the water (then the light is "
         "on the wrong side of every wave).",
         [](const fs::path& work) {
             return check_vector(
                 work, "fbm.glsl", "fbm_normal(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const step03::Vec3 n = step03::normal({0.0, a.x, a.y});
                     return glm::dvec3(n.x, n.y, n.z);
                 },
                 1e-4, -2, 2);
         }},
        {"step05_fft", 1, "Where the surface folds", "ocean_maps.glsl", "float jacobian(vec4 displacement, vec4 slopes) {",
         "    // TODO (exercise 1): the Jacobian of the choppy displacement.\n    return 1.0;\n",
         "Write jacobian: J = (1 + l dDx/dx)(1 + l dDz/dz) - (l dDx/dz)^2, with l dDx/dx = slopes.z, l dDz/dz =\n"
         "slopes.w, l dDx/dz = displacement.w. J < 0 where the surface folds over itself: view=jacobian shows\n"
         "it, and step06 puts its foam there.",
         "J is the determinant of the 2 x 2 matrix [[1 + l dDx/dx, l dDx/dz], [l dDx/dz, 1 + l dDz/dz]]: the "
         "product of the diagonal minus the square of the off-diagonal term (the maps hold l D already).",
         [](const fs::path& work) {
             return check_values(
                 work, "ocean_maps.glsl", std::string("jacobian(") + kStep05Sample + ")",
                 [](const glm::dvec4& a, const glm::dvec4& b) { return step05_cell(a, b).jacobian(0, 1.0); }, 1e-4, -0.8,
                 0.8);
         }},
        {"step05_fft", 2, "The normal of the choppy surface", "ocean_maps.glsl",
         "vec3 choppy_normal(vec4 displacement, vec4 slopes) {",
         "    // TODO (exercise 2): the normal of the displaced surface. For now, step03's.\n"
         "    return normalize(vec3(-slopes.x, 1.0, -slopes.y));\n",
         "Write choppy_normal: the surface point of rest position p is P = (p.x + l Dx, h, p.z + l Dz); its\n"
         "tangents are dP/dx = (1 + l dDx/dx, dh/dx, l dDx/dz) and dP/dz = (l dDx/dz, dh/dz, 1 + l dDz/dz), and\n"
         "N = normalize(dP/dz x dP/dx). The starter is step03's normal, right only where l = 0.",
         "slopes = (dh/dx, dh/dz, l dDx/dx, l dDz/dz), displacement.w = l dDx/dz (= l dDz/dx). The order of the "
         "cross product decides up or down: dP/dz x dP/dx points up for a flat sea.",
         [](const fs::path& work) {
             return check_vector(
                 work, "ocean_maps.glsl", std::string("choppy_normal(") + kStep05Sample + ")",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     const auto n = step05_cell(a, b).normal(0, 1.0);
                     return glm::dvec3(n[0], n[1], n[2]);
                 },
                 1e-4, -0.6, 0.6);
         }},
        {"step05_fft", 3, "From texel to wave vector", "mode.glsl", "vec2 wave_vector(ivec2 texel, int n, float patch_size) {",
         "    // TODO (exercise 3): the wave vector k that texel (i, j) of the spectrum holds.\n"
         "    return (6.2831853 / patch_size) * vec2(texel);\n",
         "Write wave_vector: texel (i, j) of an N x N spectrum holds k = 2 pi (n, m) / L. The inverse FFT sums\n"
         "frequencies 0, 1, ..., N/2 - 1 and then -N/2, ..., -1 in that order, so n = i for i < N/2 and i - N\n"
         "above, and the same for m. The starter takes n = i everywhere: half the waves run the wrong way, and\n"
         "the tile is no longer a sum of Hermitian pairs.",
         "Texels N/2 .. N-1 hold the negative frequencies: n = i - N there (an FFT of N points cannot tell "
         "frequency n from n - N, and the spectrum is centred on k = 0). Check both halves: texel 1 is "
         "+2 pi / L, texel N - 1 is -2 pi / L.",
         [](const fs::path& work) {
             return check_vector(
                 work, "ocean_layout.glsl,mode.glsl", "wave_vector(ivec2(64.0 * a.xy), 64, 100.0 + 400.0 * b.x)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     return glm::dvec3(step05::wavenumber(int(64 * a.x), 64, 100 + 400 * b.x),
                                       step05::wavenumber(int(64 * a.y), 64, 100 + 400 * b.x), 0.0);
                 },
                 1e-5, 0, 0.999, {}, 2);
         }},
        {"step05_fft", 4, "The phase: a mode in time", "mode.glsl", "vec2 evolve_mode(vec2 h0_k, vec2 h0_minus_k, float phase) {",
         "    // TODO (exercise 4): h~(k, t) from h0(k), h0(-k) and phase = omega t.\n    return h0_k;\n",
         "Write evolve_mode: h~(k, t) = h0(k) e^{-i omega t} + conj(h0(-k)) e^{+i omega t}, with phase = omega t\n"
         "(omega from the dispersion relation, omega^2 = g k tanh(k depth), formed and reduced in double on the\n"
         "CPU). Complex numbers are vec2 (real, imaginary); complex_multiply is in ocean_layout.glsl. The\n"
         "starter returns h0(k): a frozen sea, and not even a real one.",
         "e^{-i phase} is vec2(cos(phase), -sin(phase)); the second term is the conjugate of h0(-k) times the "
         "conjugate rotation, which makes h~(-k) = conj(h~(k)) and the height real. With e^{+i omega t} on h0(k) "
         "(the notes' 4.3) the crests run upwind.",
         [](const fs::path& work) {
             return check_vector(
                 work, "ocean_layout.glsl,mode.glsl", "evolve_mode(a.xy, a.zw, 6.2831853 * b.x)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     const auto h = step05::evolve_mode({a.x, a.y}, {a.z, a.w}, 6.2831853 * b.x);
                     return glm::dvec3(h.real(), h.imag(), 0.0);
                 },
                 1e-4, -1, 1, {}, 2);
         }},
        {"step05_fft", 5, "One radix-4 stage of the FFT", "fft.comp", "void radix4_stage(int t, int p, int from) {",
         "    // TODO (exercise 5): thread t's four butterflies of the stage of stride p, lines[from] -> lines[1 - from].\n"
         "    for (int j = 0; j < 4; ++j) lines[1 - from][t + j * QUARTER] = lines[from][t + j * QUARTER];\n",
         "Write radix4_stage from the rule in fft.comp's header: with k = t mod p, take a_j = x[t + j N/4] w^(j k)\n"
         "(w^(j k) = twiddle[j k N / (4 p)]), and write y[(t - k) 4 + k + q p] = sum_j a_j e^{+2 pi i j q / 4}\n"
         "for q = 0..3. The factors e^{2 pi i j q / 4} are 1, i, -1, -i: additions and times_i only. The\n"
         "starter copies the line through: the 'transform' is the spectrum itself.",
         "Output q = 1 is a0 + i a1 - a2 - i a3 (a quarter turn per j), q = 2 is a0 - a1 + a2 - a3, q = 3 is "
         "a0 - i a1 - a2 + i a3. Twiddle the inputs before the 4-point DFT, not after, and write at (t - k) * 4 + k "
         "+ q * p (Stockham: each stage puts its results where the next one reads them).",
         [](const fs::path& work) { return check_fft(work); }},
        {"step05_fft", 6, "Choppiness and slopes in the spectrum", "mode.glsl", "vec2[4] packed_pairs(vec2 h, vec2 k) {",
         "    // TODO (exercise 6): the four packed pairs from h~ at k. For now the height alone.\n"
         "    vec2 pairs[4] = vec2[4](h, vec2(0.0), vec2(0.0), vec2(0.0));\n    return pairs;\n",
         "Write packed_pairs: every map is h~ times a factor, because d/dx of e^{i k.x} is i kx e^{i k.x}. With\n"
         "u = k/|k|: D~ = +i u h~ (choppy displacement), slopes i k h~, and the derivatives of D one more factor\n"
         "i k. Pack them as h + i Dx, Dz + i dh/dx, dh/dz + i dDx/dx, dDz/dz + i dDx/dz, and return zeros at\n"
         "k = 0. The starter gives the height alone: no choppiness, and a sea lit as if flat.",
         "i times a complex (x, y) is (-y, x). Multiply it out: h + i (i ux h) = (1 - ux) h; i kz h + i (i kx)(i ux h) "
         "= (kz - kx ux) i h. The notes' 4.5 writes D~ = -i u h~: round crests and folds in the troughs.",
         [](const fs::path& work) { return check_packed_pairs(work); }},
        {"step06_foam_sky", 1, "Schlick's Fresnel", "shading.glsl", "float fresnel_schlick(float cos_theta, float f0) {",
         "    // TODO (exercise 1): how much light the water reflects, seen at cos_theta from the normal.\n"
         "    return 0.0;\n",
         "Write fresnel_schlick: F = F0 + (1 - F0)(1 - cos theta)^5, with cos theta clamped to [0, 1].\n"
         "Without it the sea reflects nothing: no sky in the water, no glint.",
         "Looking straight down (cos theta = 1) water reflects F0 = 0.02; at grazing (cos theta = 0), "
         "everything (1). Check both ends of your formula, and clamp cos theta: a normal bent past 90 degrees "
         "gives a negative one.",
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "fresnel_schlick(dot(n, v), 0.02)",
                                  [](const Vec3& n, const Vec3& v, const Vec3&, double) {
                                      return step06::fresnel_schlick(step03::dot(n, v), 0.02);
                                  },
                                  1e-4);
         }},
        {"step06_foam_sky", 2, "The microfacet specular", "shading.glsl",
         "vec3 specular_term(vec3 n, vec3 v, vec3 l, float alpha, float f0, vec3 sun) {",
         "    // TODO (exercise 2): the sun's reflection towards v: sun * D * G * F / (4 N.V).\n"
         "    return vec3(0.0);\n",
         "Write specular_term from the parts above it: H = normalize(V + L), D = "
         "microfacet_distribution(N.H, alpha), G = 1 / (1 + smith_lambda(N.V) + smith_lambda(N.L)), F = "
         "fresnel_schlick(V.H, f0); return sun D G F / (4 N.V), and nothing when the sun or the eye is below "
         "the surface (N.L <= 0 or N.V <= 0). Without it there is no sun glint.",
         "Fresnel takes V.H here, not N.V (the microfacets that reflect the sun face H); the 4 N.V in the "
         "denominator is N.V alone (N.L cancels with the irradiance); return vec3(0.0) for N.L <= 0 or N.V <= 0.",
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "specular_term(n, v, l, alpha, 0.02, vec3(1.0)).x",
                                  [](const Vec3& n, const Vec3& v, const Vec3& l, double alpha) {
                                      return step06::specular_factor(n, v, l, alpha, 0.02, Microfacet::Ggx);
                                  },
                                  1e-4);
         }},
        {"step06_foam_sky", 3, "Foam, exact at any frame rate", "foam_step.glsl",
         "float foam_step(float foam, float injection_rate, float decay_rate, float dt) {",
         "    // TODO (exercise 3): the foam after dt seconds. The starter is the explicit step.\n"
         "    return clamp(foam * exp(-decay_rate * dt) + injection_rate * dt, 0.0, 1.0);\n",
         "Write foam_step: solve df/dt = q - r f over the frame, q = injection_rate and r = decay_rate held\n"
         "constant, from f(0) = foam, and clamp to [0, 1]. The starter's explicit step makes 6 % more foam at\n"
         "6 frames a second than at 60.",
         "The solution of df/dt = q - r f is f(dt) = f e^{-r dt} + q (1 - e^{-r dt}) / r; for r dt -> 0 it tends "
         "to f + q dt (mind the division by r = 0, and float's cancellation in 1 - e^{-x} for tiny x).",
         [](const fs::path& work) {
             return check_values(
                 work, "foam_step.glsl", "foam_step(a.x, 20.0 * a.y, 5.0 * a.z, 0.5 * b.x)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     step06::FoamSettings s;
                     s.threshold = 1;  // J = 0: the injection rate is s.injection
                     s.injection = 20 * a.y;
                     s.decay_rate = 5 * a.z;
                     return step06::foam_step(a.x, 0.0, 0.5 * b.x, s);
                 },
                 1e-4, 0, 1);
         }},
        {"step06_foam_sky", 4, "The tessellation level", "tessellation.glsl", "float edge_level(vec2 a, vec2 b) {",
         "    // TODO (exercise 4): how many segments the edge from a to b (x, z, at y = 0) is cut into.\n"
         "    return 16.0;\n",
         "Write edge_level: the level falls as 1 / distance from the eye (u_eye) to the edge's midpoint, so that\n"
         "a segment covers about the same part of the screen near and far: u_tess_scale * u_patch_size /\n"
         "distance, clamped to [1, 64]. The starter cuts every edge into 16: too coarse near the camera, wasted far\n"
         "away (view=tessellation shows it).",
         "Use the midpoint of the edge (so the two patches that share it compute the same level and no crack "
         "opens), at y = 0, and its distance to u_eye in 3D; clamp to [1, 64].",
         [](const fs::path& work) {
             return check_values(
                 work, "tessellation.glsl", "edge_level(300.0 * a.xy, 300.0 * a.zw)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     const glm::dvec3 midpoint(150.0 * (a.x + a.z), 0.0, 150.0 * (a.y + a.w));
                     const glm::dvec3 d = midpoint - kTessEye;
                     return step06::tessellation_level(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), kTessPatch, kTessScale);
                 },
                 1e-4, -1, 1, [](const ocean::ShaderProgram& p) {
                     p.set("u_eye", glm::vec3(kTessEye));
                     p.set("u_patch_size", float(kTessPatch));
                     p.set("u_tess_scale", float(kTessScale));
                 });
         }},
        {"step06_foam_sky", 5, "The GGX distribution, normalised", "shading.glsl",
         "float ggx_distribution(float n_dot_h, float alpha) {",
         "    // TODO (exercise 5): GGX's D(h). The starter is step03's Blinn-Phong lobe, not normalised.\n"
         "    return pow(max(n_dot_h, 0.0), 2.0 / (alpha * alpha) - 2.0);\n",
         "Write ggx_distribution: D(h) = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2), the density of microfacet\n"
         "normals around h for slopes of spread alpha. It is normalised: the integral of D (N.H) over the\n"
         "hemisphere is 1, so a rougher sea spreads the sun's glint wider and dimmer without making light. The\n"
         "starter's lobe has the right shape and the wrong size.",
         "At N.H = 1, D = 1 / (pi alpha^2): a smooth sea (small alpha) has a tall, narrow peak. Without the pi the "
         "glint is pi times too bright; check D(1) for alpha = 0.1 (31.8).",
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "ggx_distribution(max(dot(n, normalize(v + l)), 0.0), alpha)",
                               [](const Vec3& n, const Vec3& v, const Vec3& l, double alpha) {
                                   const Vec3 h = step03::normalize({v.x + l.x, v.y + l.y, v.z + l.z});
                                   return step06::microfacet_distribution(std::max(step03::dot(n, h), 0.0), alpha,
                                                                          step06::Microfacet::Ggx);
                               },
                               1e-4);
         }},
        {"step06_foam_sky", 6, "Height fog", "fog.glsl", "vec3 apply_fog(vec3 colour, vec3 eye, vec3 p, vec3 fog_colour) {",
         "    // TODO (exercise 6): fog between the eye and p. The starter's fog is as thick at any height.\n"
         "    return mix(fog_colour, colour, exp(-u_fog_density * length(p - eye)));\n",
         "Write apply_fog: the fog's density falls with height, rho(y) = u_fog_density e^{-u_fog_falloff y}. Sum it\n"
         "along the segment from eye to p (the optical depth tau: the integral has a closed form), and keep\n"
         "e^{-tau} of the colour, the rest fog_colour. The starter's fog ignores height: a camera up high sees\n"
         "as much as one on deck.",
         "Parametrise the segment as eye + s (p - eye), s in [0, 1]: tau = |p - eye| * density e^{-f eye.y} * "
         "(1 - e^{-f dy}) / (f dy), dy = p.y - eye.y. A level ray (f dy -> 0) needs the limit 1.",
         [](const fs::path& work) {
             return check_values(
                 work, "fog.glsl", std::string("apply_fog(vec3(0.0), ") + kFogRay + ", vec3(1.0)).x",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     return step06::fog_amount({100 * a.x, 27 + 25 * a.y, 100 * a.z}, {1500 * b.x, 3 * b.y, 1500 * b.z},
                                               kFogDensity, kFogFalloff);
                 },
                 1e-4, -1, 1, [](const ocean::ShaderProgram& p) {
                     p.set("u_fog_density", float(kFogDensity));
                     p.set("u_fog_falloff", float(kFogFalloff));
                 });
         }},
    };
}

}  // namespace exercises
