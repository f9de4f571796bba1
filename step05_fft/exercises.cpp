// step05_fft's exercises (./ocean exercise step05_fft N): for each, the file and function
// it empties, the stub, the task, the hint, and the check that holds the learner's function to
// the chapter's CPU reference. tools/exercise gathers every chapter's (add_step's EXERCISES).
#include "tools/exercise.hpp"

#include "step05_fft/ocean_maps.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace exercises {

namespace {

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

// step05's packed pairs, all eight real numbers one after the other (pair f, real then imaginary).
Verdict check_packed_pairs(const fs::path& work) {
    Verdict verdict;
    for (int f = 0; f < 4 && (f == 0 || verdict.pass); ++f)
        verdict = check_vector(
            work, "ocean_layout.glsl,mode.glsl", "packed_pairs(a.xy, 2.0 * a.zw)[" + std::to_string(f) + "]",
            [f](const glm::dvec4& a, const glm::dvec4&) {
                const auto pair = step05::packed_pairs({a.x, a.y}, 2 * a.z, 2 * a.w)[std::size_t(f)];
                return glm::dvec3(pair.real(), pair.imag(), 0.0);
            },
            1e-4, -1, 1, {}, 2);
    return verdict;
}

std::vector<Exercise> chapter() {
    return {
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
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
