// step05_fft's exercises (./ocean exercise step05_fft N): for each, the file and function
// it empties, the stub, the task, the hint, and the check that holds the learner's function to
// the chapter's CPU reference. The exercise tool (exercises/) gathers every chapter's (add_step's
// EXERCISES).
#include "exercises/exercise.hpp"

#include "step05_fft/donelan_banner.hpp"
#include "step05_fft/exercise_fft.hpp"
#include "step05_fft/gerstner.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/spectrum.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

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

// Exercise 8's check: the height variance the learner's initial_amplitude gives, averaged over many
// draws, against the spectrum's integral (resolved_variance: the sum of Phi dk^2 over the resolved
// modes, computed without h0). The driver holds the default sea's mode energies (N = 64) and draws
// its own Gaussian numbers; by Parseval the height's variance at t = 0 is sum_k |h0(k) + conj(h0(-k))|^2.
std::string variance_driver() {
    step05::SpectrumParams p;
    p.resolution = 64;
    const step05::InitialSpectrum sea = step05::initial_spectrum(p);
    std::ostringstream driver;
    driver.precision(17);
    driver << "#include \"step05_fft/mode_amplitude.hpp\"\n#include <complex>\n#include <cstdio>\n#include <random>\n"
           << "#include <vector>\nconst int n = " << p.resolution << ";\nconst double integral = "
           << step05::resolved_variance(p) << ";\nconst double energy[] = {";
    for (double e : sea.density) driver << e << ",";
    driver << R"(};
int main() {
    const int draws = 200;
    double mean = 0;
    for (int draw = 0; draw < draws; ++draw) {
        std::mt19937_64 random(std::uint64_t(draw) + 1);
        std::normal_distribution<double> normal;
        std::vector<std::complex<double>> h0(n * n);
        for (int i = 0; i < n * n; ++i) {
            const double xr = normal(random), xi = normal(random);
            h0[std::size_t(i)] = step05::initial_amplitude(xr, xi, energy[i]);
        }
        double variance = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::size_t k = std::size_t(j * n + i), minus_k = std::size_t(((n - j) % n) * n + (n - i) % n);
                variance += std::norm(h0[k] + std::conj(h0[minus_k]));
            }
        mean += variance / draws;
    }
    std::printf("%.17g\n", mean / integral);
}
)";
    return driver.str();
}

// Exercise 9's check: gerstner_wave's eight numbers against gerstner.hpp, three components at a time.
// The inputs: rest position within 50 m, a direction all round, k from 0.05 to 0.55 rad/m, A from
// 0.2 to 2.2 m, Q up to 1.2 / (k A) (past the fold), any phase.
Verdict check_gerstner(const fs::path& work) {
    const std::string call = "gerstner_wave(50.0 * a.xy, vec4(cos(3.14159265 * b.x), sin(3.14159265 * b.x), "
                             "0.3 + 0.25 * b.y, 1.2 + b.z), (0.6 + 0.6 * b.w) / ((0.3 + 0.25 * b.y) * (1.2 + b.z)), "
                             "3.14159265 * a.z)";
    const auto sample = [](const glm::dvec4& a, const glm::dvec4& b) {
        step05::GerstnerWave w;
        w.direction_x = std::cos(3.14159265 * b.x);
        w.direction_z = std::sin(3.14159265 * b.x);
        w.wavenumber = 0.3 + 0.25 * b.y;
        w.amplitude = 1.2 + b.z;
        w.steepness = (0.6 + 0.6 * b.w) / (w.wavenumber * w.amplitude);
        return step05::gerstner_sample(w, 50 * a.x, 50 * a.y, 3.14159265 * a.z);
    };
    Verdict verdict = check_vector(work, "gerstner.glsl", call + ".displacement.xyz", [&](const glm::dvec4& a, const glm::dvec4& b) {
        const auto m = sample(a, b);
        return glm::dvec3(m.displacement[0], m.displacement[1], m.displacement[2]);
    }, 1e-4, -1, 1);
    if (!verdict.pass) return verdict;
    verdict = check_vector(work, "gerstner.glsl", "vec3(" + call + ".displacement.w, " + call + ".slopes.xy)",
                           [&](const glm::dvec4& a, const glm::dvec4& b) {
                               const auto m = sample(a, b);
                               return glm::dvec3(m.displacement[3], m.slopes[0], m.slopes[1]);
                           }, 1e-4, -1, 1);
    if (!verdict.pass) return verdict;
    return check_vector(work, "gerstner.glsl", call + ".slopes.zw", [&](const glm::dvec4& a, const glm::dvec4& b) {
        const auto m = sample(a, b);
        return glm::dvec3(m.slopes[2], m.slopes[3], 0.0);
    }, 1e-4, -1, 1, {}, 2);
}

// Exercise 10's cases: an angle from the wind in [-pi, pi] and a beta from 0.02 (a lobe round the
// whole circle) to 50 (3 degrees wide), even in log beta, from one seed per case.
double sech2_case(int index, double* beta) {
    std::mt19937 random(std::uint32_t(5000 + index));
    std::uniform_real_distribution<double> unit(-1, 1), zero_one(0, 1);
    const double theta = step05::kPi * unit(random);
    *beta = std::exp(std::log(0.02) + zero_one(random) * std::log(2500.0));
    return theta;
}
std::vector<double> sech2_reference(int index) {
    double beta = 0;
    const double theta = sech2_case(index, &beta);
    return {step05::sech2_spreading(theta, beta)};
}
const char* kSech2Driver = R"(#include "step05_fft/donelan_banner.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index) {
        std::mt19937 random(std::uint32_t(5000 + index));
        std::uniform_real_distribution<double> unit(-1, 1), zero_one(0, 1);
        const double theta = 3.14159265358979323846 * unit(random);
        const double beta = std::exp(std::log(0.02) + zero_one(random) * std::log(2500.0));
        std::printf("%.17g\n", step05::sech2_spreading(theta, beta));
    }
}
)";

std::vector<Exercise> chapter() {
    return {
        {"step05_fft", 1, "Where the surface folds", "ocean_maps.glsl", "float jacobian(vec4 displacement, vec4 slopes) {",
         "    // TODO (exercise 1): the Jacobian of the choppy displacement.\n    return 1.0;\n",
         "Write jacobian. The water resting at x is drawn at x + l D(x). How much does that map stretch a small\n"
         "square around x? The factor is the determinant of the map's 2 x 2 matrix of derivatives: below 1 the\n"
         "water is squeezed (crests), below 0 the surface has folded over itself (a breaking crest: foam).\n"
         "Derive the matrix from x + l D(x), then its determinant. The maps hold the derivatives of l D already:\n"
         "slopes.z = l dDx/dx, slopes.w = l dDz/dz, displacement.w = l dDx/dz (= l dDz/dx). view=jacobian shows J.",
         "Each diagonal entry is the derivative of one coordinate of x + l D along its own axis: it starts at 1. "
         "The matrix is symmetric.",
         "J = (1 + l dDx/dx)(1 + l dDz/dz) - (l dDx/dz)^2 = (1 + slopes.z)(1 + slopes.w) - displacement.w^2",
         {"--set", "view=jacobian", "--set", "choppiness=2"},
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
         "Write choppy_normal. The surface point of rest position p is P(p) = (p.x + l Dx, h, p.z + l Dz).\n"
         "A normal is perpendicular to the surface's two tangents, the derivatives of P along x and along z.\n"
         "Derive both tangents from P (the maps hold every derivative you need: slopes = (dh/dx, dh/dz,\n"
         "l dDx/dx, l dDz/dz), displacement.w = l dDx/dz), then combine them. The starter is step03's normal,\n"
         "right only where l = 0: crank up choppiness and watch the crests' shading.",
         "Differentiate each coordinate of P: the horizontal ones start at 1 on their own axis. The order of the "
         "cross product decides up or down: check it on a flat sea.",
         "dP/dx = (1 + l dDx/dx, dh/dx, l dDx/dz), dP/dz = (l dDx/dz, dh/dz, 1 + l dDz/dz), "
         "N = normalize(cross(dP/dz, dP/dx))",
         {"--set", "choppiness=2.5", "--set", "wind_speed=20"},
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
         "Write wave_vector: which wave vector k does texel (i, j) of the N x N spectrum hold? On a tile of side\n"
         "L only whole numbers of wavelengths fit, so k = 2 pi (n, m) / L. An FFT of N points cannot tell\n"
         "frequency n from n - N (e^{2 pi i n u / N} is the same at every sample u); the README's primer lays\n"
         "out the FFT's order (its table for N = 8): translate it to GLSL for any N. Texel N/2, the Nyquist\n"
         "frequency, means -N/2 (the check expects k = -(N/2) 2 pi / L there). The step runs the GPU FFT\n"
         "(backend=gpu_fft) so that your shader is used.",
         "The texels are in the FFT's order, not centred: texel 0 is k = 0, texel 1 is +2 pi / L, and texel N - 1 "
         "is the wave next to k = 0 on the other side.",
         "n = i for i < N/2, n = i - N for i >= N/2 (the same for m); k = (2 pi / L) (n, m)",
         {"--set", "backend=gpu_fft"},
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
         "Write evolve_mode, README section 2's mode at time t, in GLSL: from h0(k), h0(-k) and phase = omega t.\n"
         "Check what you write against the two requirements section 2 builds it from: each wave travels along +k (a crest at k.x - omega t = const moves forward as t grows), and the\n"
         "spectrum stays Hermitian, h~(-k) = conj(h~(k)), so that the height the FFT makes is real. Build the\n"
         "term that moves h0(k) forward, then add the partner that makes the pair Hermitian. Complex numbers\n"
         "are vec2 (real, imaginary); complex_multiply is in ocean_layout.glsl. The starter is a frozen sea.",
         "Which sign of the exponent moves a crest of e^{i(k.x + s omega t)} towards +k? Then write h~(-k) from your "
         "first term and take its conjugate. The notes' 4.3 has the sign that sends the crests upwind.",
         "h~(k, t) = h0(k) e^{-i phase} + conj(h0(-k)) e^{+i phase}; e^{-i phase} = vec2(cos(phase), -sin(phase))",
         {"--set", "backend=gpu_fft"},
         [](const fs::path& work) {
             return check_vector(
                 work, "ocean_layout.glsl,mode.glsl", "evolve_mode(a.xy, a.zw, 6.2831853 * b.x)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     const auto h = step05::evolve_mode({a.x, a.y}, {a.z, a.w}, 6.2831853 * b.x);
                     return glm::dvec3(h.real(), h.imag(), 0.0);
                 },
                 1e-4, -1, 1, {}, 2);
         }},
        {"step05_fft", 5, "One radix-2 stage of the FFT", "fft_radix2.comp",
         "void radix2_butterfly(int s, int b, int layer, int line) {",
         "    // TODO (exercise 5): butterfly b of stage s, source -> target. For now, a copy.\n"
         "    target[element(layer, line, 2 * b)] = line_value(layer, line, 2 * b);\n"
         "    target[element(layer, line, 2 * b + 1)] = line_value(layer, line, 2 * b + 1);\n",
         "Write radix2_butterfly, the heart of the plain FFT (fft.md derives it). A transform of 2M\n"
         "points is two transforms of M points, E of the even samples and O of the odd ones, joined by one\n"
         "complex multiplication per pair. After the bit-reversed read of stage 0 (line_value does it), stage s\n"
         "(M = 2^s) finds E and O side by side in every block of 2M elements. Butterfly b (0 <= b < N/2) is\n"
         "one frequency r of one block: work out from s and b which two elements it joins, which power of the\n"
         "root of unity it needs (the table twiddle[m] holds e^{+2 pi i m / N}), and which two outputs it\n"
         "writes. The step runs the GPU FFT in this form (fft=radix2); the starter's 'transform' copies.",
         "r = b mod M; the block starts at 2M (b div M) = 2 (b - r). X[r] and X[r + M] share the same E[r] and "
         "O[r]: they differ only by the sign of the twiddled O. zeta = e^{2 pi i / (2M)} is twiddle entry N / (2M).",
         "M = 2^s, r = b & (M - 1), even = 2 (b - r) + r, odd = even + M, zeta^r = twiddle[r N / (2M)];\n"
         "e = line_value(even), o = zeta^r line_value(odd); target[even] = e + o, target[odd] = e - o",
         {"--set", "backend=gpu_fft", "--set", "fft=radix2"},
         [](const fs::path& work) { return check_fft(work, step05::GpuFftForm::Radix2); }},
        {"step05_fft", 6, "One radix-4 stage of the FFT", "fft.comp", "void radix4_stage(int t, int p, int from) {",
         "    // TODO (exercise 6): thread t's four butterflies of the stage of stride p, lines[from] -> lines[1 - from].\n"
         "    for (int j = 0; j < 4; ++j) lines[1 - from][t + j * QUARTER] = lines[from][t + j * QUARTER];\n",
         "Write radix4_stage, the optimisation of exercise 5 (fft.md section 3): split a transform four ways\n"
         "instead of two, so an unnormalised 4-point inverse DFT (factors e^{+2 pi i j q / 4} = 1, i, -1, -i: no\n"
         "multiplications) joins four quarter-size transforms, and half as many stages run, all in shared\n"
         "memory. In Stockham's order a stage of stride p reads its four inputs a quarter of the line apart\n"
         "and writes its outputs where the next stage will read them, so no bit reversal is needed. Derive the index rule from fft.md's Stockham\n"
         "radix-2 rule (item 1 of its section 3, not exercise 5's bit-reversed one), with four blocks for two.",
         "r = t mod p picks the twiddle, as in exercise 5. Twiddle the inputs before the 4-point inverse DFT, not after; "
         "output q is a sum of the four inputs turned by q quarter turns per j.",
         "r = t & (p - 1); a_j = x[t + j N/4] zeta^(j r), zeta^(j r) = twiddle[j r N / (4 p)];\n"
         "out[(t - r) 4 + r + q p] = sum_j a_j i^(j q), q = 0..3: q = 1 is a0 + i a1 - a2 - i a3, q = 2 is\n"
         "a0 - a1 + a2 - a3, q = 3 is a0 - i a1 - a2 + i a3",
         {"--set", "backend=gpu_fft", "--set", "fft=stockham4"},
         [](const fs::path& work) { return check_fft(work, step05::GpuFftForm::Stockham4); }},
        {"step05_fft", 7, "Choppiness and slopes in the spectrum", "mode.glsl", "vec2[4] packed_pairs(vec2 h, vec2 k) {",
         "    // TODO (exercise 7): the four packed pairs from h~ at k. For now the height alone.\n"
         "    vec2 pairs[4] = vec2[4](h, vec2(0.0), vec2(0.0), vec2(0.0));\n    return pairs;\n",
         "Write packed_pairs: the spectra of the choppy displacement and of the slopes, packed two per transform.\n"
         "Every map is h~ times a factor: a derivative d/dx of e^{i k.x} is a factor i kx. The horizontal\n"
         "displacement is the height's phase turned by a quarter along u = k/|k|, towards the crest (README\n"
         "section 4 gives its sign and why: translate it into vec2s). Pack two real maps a, b as a + i b (README\n"
         "section 4, 'Two real maps per transform'):\n"
         "h + i Dx, Dz + i dh/dx, dh/dz + i dDx/dx, dDz/dz + i dDx/dz; zeros at k = 0. The starter is the height\n"
         "alone: round waves lit as if flat.",
         "i times a complex (x, y) is (-y, x). The notes' 4.5 writes D~ = -i u h~: round crests and folds in the "
         "troughs; one Gerstner wave says which sign moves points towards its crest.",
         "D~ = +i u h~, grad h~ = i k h~, dDx/dx~ = i kx Dx~ ...: h + i (i ux h) = (1 - ux) h; "
         "i kz h + i (i kx)(i ux h) = (kz - kx ux) i h; and so on",
         {"--set", "backend=gpu_fft", "--camera", "low"},
         [](const fs::path& work) { return check_packed_pairs(work); }},
        {"step05_fft", 8, "A mode's initial amplitude, h0(k)", "mode_amplitude.cpp",
         "std::complex<double> initial_amplitude(double xi_real, double xi_imaginary, double energy) {",
         "    // TODO (exercise 8): h0(k) from two standard normal numbers and the mode's energy Phi(k) dk^2.\n"
         "    return {0.0, 0.0};\n",
         "Write initial_amplitude (C++). The spectrum says how much energy each mode holds on average,\n"
         "energy = Phi(k) dk^2 (m^2 of height variance); a real sea is one random draw of it: each mode gets a\n"
         "complex amplitude with a random phase and a random, Gaussian size. Scale a complex Gaussian\n"
         "(xi_real + i xi_imaginary, each of mean 0 and variance 1) so that the sea's height variance is the\n"
         "spectrum's integral, the sum of energy. Mind that the time evolution (exercise 4) adds conj(h0(-k)) to every\n"
         "mode: count how many copies of each mode's energy the height then holds. ./ocean check averages\n"
         "the height variance of 200 draws of the default sea (N = 64) and compares it with the integral.",
         "E|xi_real + i xi_imaginary|^2 = 2 (E: the mean over many draws). At t = 0, h~(k) = h0(k) + conj(h0(-k)): two "
         "independent draws. The notes' sqrt(energy / 2) makes the sea's variance twice the spectrum's.",
         "h0(k) = (xi_real + i xi_imaginary) sqrt(energy / 4): E|h0|^2 = energy / 2, and with its partner E|h~(k)|^2 = "
         "(energy(k) + energy(-k)) / 2, so sum E|h~|^2 = sum energy",
         {},
         [](const fs::path& work) {
             return check_cpp(work, "mode_amplitude.cpp", variance_driver(), 1,
                              [](int) { return std::vector<double>{1.0}; }, 0.05);
         }},
        {"step05_fft", 9, "One Gerstner wave", "gerstner.glsl", "MapSample gerstner_wave(vec2 p, vec4 wave, float steepness, float phase) {",
         "    // TODO (exercise 9): one Gerstner wave's displacement and slopes. For now, a sine that only rises and falls.\n"
         "    float theta = wave.z * dot(wave.xy, p) - phase;\n"
         "    MapSample m;\n"
         "    m.displacement = vec4(0.0, wave.w * cos(theta), 0.0, 0.0);\n"
         "    m.slopes = vec4(-wave.w * wave.z * wave.xy * sin(theta), 0.0, 0.0);\n"
         "    return m;\n",
         "Write gerstner_wave: gerstner.md's Gerstner wave (README section 4), with Q, in the maps' form (GPU Gems 1, chapter 1;\n"
         "steepness is Q: the step passes gerstner_steepness / (k A)). In a real wave the water moves in\n"
         "circles: each point rises at the crest and moves forward there, sinks in the trough and moves\n"
         "back. So a Gerstner wave moves the point of rest position p up by A cos(theta) and also sideways,\n"
         "along the wave's direction d, by Q A times a quarter-turned copy of the same oscillation. Translate\n"
         "gerstner.md's sign, which moves points towards the crest (crests sharpen, troughs widen), and fill the\n"
         "maps' form: displacement (Q Dx, h, Q Dz, Q dDx/dz), slopes (dh/dx, dh/dz, Q dDx/dx, Q dDz/dz), with\n"
         "theta = k d.p - phase and wave = (d.x, d.z, k, A). At which Q k A does the crest become a cusp?\n"
         "The step draws your wave with sea=gerstner; try gerstner_steepness = 0.5, 1, 1.3.",
         "A point just behind a crest (theta slightly negative) must move forward, along +d. Differentiate each "
         "of h, Dx, Dz along x and z: every derivative brings a factor k times a component of d.",
         "h = A cos(theta), D = -Q A d sin(theta); dh/dx = -A k d.x sin(theta), Q dDx/dx = -Q A k d.x^2 cos(theta), "
         "Q dDz/dz = -Q A k d.z^2 cos(theta), Q dDx/dz = -Q A k d.x d.z cos(theta); the Jacobian is 1 - Q k A cos(theta), "
         "so the crest folds when Q k A > 1",
         {"--set", "sea=gerstner", "--set", "wind_direction=120"},
         [](const fs::path& work) { return check_gerstner(work); }},
        // derived: the lesson normalises Hasselmann's cos^2s lobe only; sech^2's constant is the learner's
        {"step05_fft", 10, "Another spreading: sech^2, normalised", "donelan_banner.cpp",
         "double sech2_spreading(double theta, double beta) {",
         "    // TODO (exercise 10): sech^2(beta theta), scaled to integrate to 1 over [-pi, pi].\n"
         "    (void)theta, (void)beta;\n"
         "    return 0;\n",
         "Write sech2_spreading (C++, in donelan_banner.cpp; \"Making the sea right\", Directions): the\n"
         "spectrum gives each frequency its energy, and the spreading shares it among directions theta\n"
         "from the wind. For that, G(theta) must integrate to 1 over the circle, theta from -pi to pi:\n"
         "then no energy is made or lost. Hasselmann's lobe is cos^2s(theta / 2) times C(s); Donelan and\n"
         "Banner measured another, sech^2(beta theta) (sech = 1 / cosh), narrow at the peak (beta 2.28)\n"
         "and wide for the short waves (beta down to 0.4). Find the factor that normalises it for every\n"
         "beta > 0, and return G. The program draws it with --set spreading=donelan_banner.\n"
         "./ocean check compiles your file with a small program and compares 200 angles and betas from\n"
         "0.02 to 50; tests/test_spectrum.cpp holds it to the midpoint rule.",
         "sech^2 has an antiderivative you know from tanh's derivative. The integral runs over the circle, "
         "not the whole line: sech^2 never reaches 0, and where beta is small the lobe reaches round to "
         "theta = +-pi, so the whole line's factor is too small there.",
         "the integral of sech^2(beta theta) over [-pi, pi] is 2 tanh(beta pi) / beta, so "
         "G = beta / (2 tanh(beta pi)) sech^2(beta theta) (beta / 2 on the whole line)",
         {"--set", "spreading=donelan_banner"},
         [](const fs::path& work) {
             return check_cpp(work, "donelan_banner.cpp", kSech2Driver, 200, sech2_reference, 1e-9);
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
