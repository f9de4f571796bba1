// The wave field against things outside the code: the direct Fourier sum, the dispersion relation,
// the conservation of energy, Cauchy and Poisson's ring waves, Kelvin's angle and Rabaud and
// Moisy's narrower wakes, and an absorbing layer that sends back almost nothing.
#include "step08_wakes/wake_experiments.hpp"
#include "step08_wakes/wake_scene.hpp"
#include "step08_wakes/wave_field.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using step08::Complex;
constexpr double g = ocean::kGravity;

// The chapter's FFT against the direct sum, on random samples: every power of two to 64.
TEST(Step08Fft, MatchesTheDirectSumInBothDirections) {
    std::mt19937 random(8);
    std::normal_distribution<double> normal;
    for (int n = 2; n <= 64; n *= 2) {
        std::vector<Complex> x(std::size_t(n * n));
        for (auto& v : x) v = {normal(random), normal(random)};
        for (int sign : {-1, +1}) {
            std::vector<Complex> fast = x;
            step08::Fft2d fft(n);
            sign < 0 ? fft.forward(fast) : fft.inverse(fast);
            double worst = 0, scale = 0;
            for (int l = 0; l < n; ++l)
                for (int m = 0; m < n; ++m) {
                    Complex sum = 0;
                    for (int z = 0; z < n; ++z)
                        for (int xx = 0; xx < n; ++xx)
                            sum += x[std::size_t(z * n + xx)] * std::polar(1.0, sign * ocean::kTwoPi * (m * xx + l * z) / n);
                    worst = std::max(worst, std::abs(sum - fast[std::size_t(l * n + m)]));
                    scale = std::max(scale, std::abs(sum));
                }
            EXPECT_LT(worst, 1e-12 * scale) << "n = " << n << ", sign " << sign;
        }
    }
    EXPECT_THROW(step08::Fft2d(48), ocean::Error);
}

// A travelling wave eta = a cos(k.x - omega t), phi = (omega / K) a sin(k.x - omega t) on a field
// with no layer.
step08::WaveField travelling_wave(glm::ivec2 mode, double depth, int n = 32, double cell = 0.5) {
    step08::WaveFieldSettings s;
    s.n = n;
    s.cell = cell;
    s.depth = depth;
    s.absorbing_width = 0;
    step08::WaveField field(s);
    const glm::dvec2 k = field.wavenumber(mode.x, mode.y);
    const double K = step08::vertical_speed_factor(glm::length(k), depth), omega = std::sqrt(g * K);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double theta = glm::dot(k, field.cell_centre(i, j));
            field.heights()[std::size_t(j * n + i)] = 0.1 * std::cos(theta);
            field.potentials()[std::size_t(j * n + i)] = 0.1 * omega / K * std::sin(theta);
        }
    return field;
}

// The phase of mode k in the height field (its projection on cos and sin of k.x).
double phase_of(const step08::WaveField& field, glm::dvec2 k) {
    double c = 0, s = 0;
    for (int j = 0; j < field.n(); ++j)
        for (int i = 0; i < field.n(); ++i) {
            const double theta = glm::dot(k, field.cell_centre(i, j)), h = field.heights()[std::size_t(j * field.n() + i)];
            c += h * std::cos(theta);
            s += h * std::sin(theta);
        }
    return std::atan2(s, c);  // eta = a cos(theta - phase): the crest has moved phase / |k| along k
}

// Every mode travels at the phase speed sqrt(g / k tanh kh): its crest followed step by step
// (each step's turn less than half a turn) over 10 s, deep water and 3 m deep.
TEST(Step08WaveField, EachModeTravelsAtItsPhaseSpeed) {
    for (double depth : {std::numeric_limits<double>::infinity(), 3.0})
        for (glm::ivec2 mode : {glm::ivec2(1, 0), glm::ivec2(3, 2), glm::ivec2(0, 7), glm::ivec2(12, 5)}) {
            step08::WaveField field = travelling_wave(mode, depth);
            const glm::dvec2 k = field.wavenumber(mode.x, mode.y);
            const double kk = glm::length(k), dt = 0.05;
            double travelled = 0, last = phase_of(field, k);
            for (int s = 0; s < 200; ++s) {
                field.step(dt);
                const double now = phase_of(field, k);
                travelled += std::remainder(now - last, ocean::kTwoPi);
                last = now;
            }
            const double speed = travelled / kk / (200 * dt);
            const double expected = std::sqrt(g / kk * std::tanh(kk * depth));
            EXPECT_NEAR(speed / expected, 1, 0.005) << "mode " << mode.x << "," << mode.y << " depth " << depth;
        }
}

// With no sources and no layer, a random sea keeps its energy within 0.1 % over 60 s at any dt.
TEST(Step08WaveField, KeepsItsEnergyAtAnyStep) {
    for (double dt : {1.0 / 240, 1.0 / 60, 1.0 / 10}) {
        step08::WaveFieldSettings s;
        s.n = 32;
        s.absorbing_width = 0;
        step08::WaveField field(s);
        std::mt19937 random(3);
        std::normal_distribution<double> normal(0, 0.05);
        for (auto& h : field.heights()) h = normal(random);
        for (auto& p : field.potentials()) p = normal(random);
        const double start = field.energy();
        double worst = 0;
        for (int step = 0; step < int(std::lround(60 / dt)); ++step) {
            field.step(dt);
            if (step % 60 == 0) worst = std::max(worst, std::abs(field.energy() / start - 1));
        }
        worst = std::max(worst, std::abs(field.energy() / start - 1));
        EXPECT_LT(worst, 1e-3) << "dt " << dt;
        std::cout << "dt " << dt << ": energy kept within " << worst << std::endl;
    }
}

// A volume source puts in the water it is given (the mean level rises by its volume over the grid's
// area), a pressure none; and the two, sent through one transform, each act as if alone (the field
// is linear: together, the sum of the two fields alone, to rounding).
TEST(Step08WaveField, ASourcePutsInTheWaterItIsGiven) {
    step08::WaveFieldSettings s;
    s.n = 32;
    s.absorbing_width = 0;
    const std::size_t cells = std::size_t(s.n) * std::size_t(s.n);
    step08::Forcing source, pressure, both;
    source.source.assign(cells, 0.0);
    pressure.pressure.assign(cells, 0.0);
    for (int j = 10; j < 14; ++j)
        for (int i = 5; i < 9; ++i) source.source[std::size_t(j * s.n + i)] = 0.02;  // m/s over 16 cells
    pressure.pressure[std::size_t(20 * s.n + 20)] = 3.0;
    both.source = source.source, both.pressure = pressure.pressure;
    step08::WaveField fed(s), pressed(s), together(s);
    const double dt = 1.0 / 60;
    const int steps = 90;
    for (int step = 0; step < steps; ++step) fed.step(dt, source), pressed.step(dt, pressure), together.step(dt, both);
    const auto volume = [&](const step08::WaveField& f) {
        double v = 0;
        for (double h : f.heights()) v += h * s.cell * s.cell;
        return v;
    };
    const double given = 16 * 0.02 * s.cell * s.cell * steps * dt;
    EXPECT_NEAR(volume(fed), given, 1e-9 * given);
    EXPECT_NEAR(volume(pressed), 0.0, 1e-9 * given);
    double worst = 0, largest = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        worst = std::max(worst, std::abs(together.heights()[c] - fed.heights()[c] - pressed.heights()[c]));
        largest = std::max(largest, std::abs(together.heights()[c]));
    }
    EXPECT_LT(worst, 1e-12 * largest);
}

// Cauchy-Poisson: t seconds after a stone, the crests at radius r have the local wavenumber
// k = g t^2 / (4 r^2) (the waves that reach r at time t are those whose group velocity is r / t).
// Between successive crests r1 < r2, k's mean is g t^2 / (4 r1 r2), and their spacing 2 pi over it.
TEST(Step08WaveField, RingWavesHaveTheLocalWavenumberOfStationaryPhase) {
    step08::WaveFieldSettings s;
    s.n = 512;
    s.cell = 0.025;
    s.absorbing_width = 0.5;
    step08::WaveField field(s);
    field.add_impulse(field.cell_centre(256, 256), 0.01, 0.03);
    const double t = 4.0;
    for (int step = 0; step < 8; ++step) field.step(t / 8);
    const std::vector<double> crests = step08::ring_crests(field, 1.0, 5.5);
    ASSERT_GE(crests.size(), 4u);
    for (std::size_t c = 0; c + 1 < crests.size(); ++c) {
        const double r1 = crests[c], r2 = crests[c + 1];
        const double measured = ocean::kTwoPi / (r2 - r1), expected = g * t * t / (4 * r1 * r2);
        std::cout << "crests " << r1 << " " << r2 << ": k " << measured << " expected " << expected << std::endl;
        EXPECT_NEAR(measured / expected, 1, 0.05) << "between " << r1 << " and " << r2 << " m";
        if (c > 0) {
            EXPECT_GT(r2 - r1, crests[c] - crests[c - 1]) << "the leading waves are the longest";
        }
    }
}

// Cauchy and Poisson's rings in height, not only in spacing: an impulse I spread as a Gaussian of
// radius a on deep water at rest has, in linear theory, the height
//     eta(r, t) = -(I / 2 pi) integral over k of k^2 / omega sin(omega t) exp(-k^2 a^2 / 2) J0(k r) dk
// (each mode's potential starts at -I exp(-k^2 a^2 / 2), its height turns up as K phi sin(omega t) / omega,
// omega = sqrt(g k); J0 sums the modes of one wavenumber over every direction). The program's default
// stone on the program's default grid (128 cells of 0.5 m), against the integral along a ray.
double ring_height(double impulse, double radius, double r, double t) {
    const double k_end = 12 / radius, dk = k_end / 6000;  // the Gaussian is exp(-72) there
    double sum = 0;
    for (double k = 0.5 * dk; k < k_end; k += dk) {
        const double omega = std::sqrt(g * k);
        sum += k * k / omega * std::sin(omega * t) * std::exp(-0.5 * k * k * radius * radius) * std::cyl_bessel_j(0.0, k * r);
    }
    return -impulse / ocean::kTwoPi * sum * dk;
}

TEST(Step08WaveField, TheDefaultStonesRingsRiseAsCauchyAndPoissonsIntegral) {
    step08::WaveField field(step08::WaveFieldSettings{});
    const glm::dvec2 stone = field.cell_centre(64, 64);
    field.add_impulse(stone, step08::kStoneImpulse, step08::kStoneRadius);
    double t = 0;
    for (double until : {1.0, 2.0, 3.0}) {
        for (; t < until - 1e-9; t += 1.0 / 60) field.step(1.0 / 60);
        double worst = 0, largest = 0;
        // At cell centres (bilinear reading between them would blur 2 m waves), along x and along
        // the diagonal: the rings are round on the square grid. Out to 6 m.
        for (int m = 0; m <= 12; ++m)
            for (int diagonal = 0; diagonal < 2; ++diagonal) {
                const int i = 64 + m, j = 64 + diagonal * m;
                const double r = glm::length(field.cell_centre(i, j) - stone);
                const double expected = ring_height(step08::kStoneImpulse, step08::kStoneRadius, r, until);
                worst = std::max(worst, std::abs(field.heights()[std::size_t(j * field.n() + i)] - expected));
                largest = std::max(largest, std::abs(expected));
            }
        std::cout << until << " s after the default stone: largest height " << largest << " m, the field off by "
                  << worst << " m at most" << std::endl;
        EXPECT_LT(worst, 0.05 * largest) << until << " s after the stone";
    }
}

// The absorbing layer: a packet of 4 m waves sent at the edge (and, the grid being periodic, at
// the layer on the other side) is gone 40 s later: what comes back into the grid's interior is
// less than 5 % of its height.
TEST(Step08WaveField, TheAbsorbingLayerSendsBackLessThanFivePercent) {
    step08::WaveFieldSettings s;  // the chapter's defaults: 128 cells of 0.5 m, an 8 m layer
    step08::WaveField field(s);
    const double k = ocean::kTwoPi / 4, omega = std::sqrt(g * k), a = 0.1, width = 4;
    const glm::dvec2 centre = field.cell_centre(s.n / 2, s.n / 2);
    double start = 0;
    for (int j = 0; j < s.n; ++j)
        for (int i = 0; i < s.n; ++i) {
            const glm::dvec2 x = field.cell_centre(i, j) - centre;
            const double envelope = a * std::exp(-0.5 * (x.x * x.x + x.y * x.y) / (width * width));
            field.heights()[std::size_t(j * s.n + i)] = envelope * std::cos(k * x.x);
            field.potentials()[std::size_t(j * s.n + i)] = envelope * omega / k * std::sin(k * x.x);
            start = std::max(start, std::abs(field.heights()[std::size_t(j * s.n + i)]));
        }
    for (int step = 0; step < 40 * 30; ++step) field.step(1.0 / 30);
    double back = 0;
    const int layer = int(std::ceil(s.absorbing_width / s.cell));
    for (int j = layer; j < s.n - layer; ++j)
        for (int i = layer; i < s.n - layer; ++i) back = std::max(back, std::abs(field.heights()[std::size_t(j * s.n + i)]));
    std::cout << "sent back " << back / start << " of the packet's height" << std::endl;
    EXPECT_LT(back / start, 0.05);
}

// Kelvin: a patch towed at a moderate Froude number U / sqrt(g L) (L a third of the transverse
// wavelength: Fr = 0.69) makes a wake whose edge, the caustic, is at arcsin(1/3) = 19.47 degrees.
// Measured 5 to 9 wavelengths behind (nearer, the caustic's Airy profile is still wide).
TEST(Step08WaveField, KelvinsAngleAtAModerateFroudeNumber) {
    step08::TowedPatch moderate;
    const double lambda = step08::transverse_wavelength(moderate.speed);
    moderate.length = lambda / 3;
    moderate.cell = lambda / 16;
    moderate.seconds = 26;
    const step08::TowedWake wake = step08::tow(moderate);
    const double edge = step08::wake_edge_angle(wake, moderate.speed, 5 * lambda, 9 * lambda);
    const double largest = step08::largest_wave_angle(wake, moderate.speed, 5 * lambda, 9 * lambda);
    std::cout << "Fr " << step08::froude_number(moderate.speed, moderate.length) << ": edge " << edge
              << " degrees, largest waves at " << largest << std::endl;
    EXPECT_NEAR(edge, std::asin(1.0 / 3) * 180 / ocean::kPi, 1.5);
    EXPECT_NEAR(largest, edge, 4) << "the largest waves near the edge";
}

// Rabaud and Moisy (2013): the same patch towed faster (Fr = 1.5, then 2) makes its largest waves
// at a smaller angle, roughly as 1/Fr (Kelvin's caustic is still there, but its waves are no
// longer the largest). Measured half a wavelength to 1.2 wavelengths behind (a fast source's
// transverse waves are long: 12 and 21 m).
TEST(Step08WaveField, AFastSourceMakesANarrowerWake) {
    double angle_times_froude[2] = {0, 0}, angles[2] = {0, 0};
    for (int run = 0; run < 2; ++run) {
        step08::TowedPatch fast;
        fast.length = 0.85;
        const double froude = run == 0 ? 1.5 : 2.0;
        fast.speed = froude * std::sqrt(g * fast.length);
        fast.cell = fast.length / 5;
        fast.seconds = 9;
        const double lambda = step08::transverse_wavelength(fast.speed);
        const step08::TowedWake wake = step08::tow(fast);
        angles[run] = step08::largest_wave_angle(wake, fast.speed, 0.5 * lambda, 1.2 * lambda);
        angle_times_froude[run] = angles[run] * froude;
        std::cout << "Fr " << froude << ": largest waves at " << angles[run] << " degrees" << std::endl;
        EXPECT_LT(angles[run], 19.47 - 5) << "Fr " << froude;
    }
    EXPECT_LT(angles[1], angles[0]) << "faster, narrower";
    EXPECT_NEAR(angle_times_froude[1] / angle_times_froude[0], 1, 0.2) << "the angle falls roughly as 1 / Fr";
}

}  // namespace
