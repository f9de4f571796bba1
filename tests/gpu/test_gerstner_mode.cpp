// Truth from outside the code: one Fourier mode of the choppy FFT sea is a Gerstner wave, and a
// Gerstner wave has a closed form. With h0(k) = A / 2 at one k (and nothing at -k),
//     h(x, t) = A cos(theta),  D(x, t) = -k/|k| A sin(theta),  theta = k.x - omega t,
// so with choppiness 1 the surface point of rest position x sits at (x - k/|k| A sin(theta),
// A cos(theta)): a trochoid. Its crests move along +k/|k| at omega / |k|, and the Jacobian of
// the horizontal map is J = 1 - |k| A cos(theta), smallest at the crests. Checked on the CPU
// reference (double) and on the GPU's assembled textures (what the renderer samples); the
// notes' two sign slips each fail it (crests along -k; J largest at the crests).
#include "step05_fft/gpu_ocean.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <cmath>

namespace {

using namespace step05;

constexpr int kN = 64;
constexpr int kModeI = 3, kModeJ = 2;  // k = (3, 2) * 2 pi / L: a diagonal wave
constexpr double kAmplitude = 2.5;     // metres; |k| A = 0.23: J from 0.77 to 1.23

struct GerstnerMode : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
    InitialSpectrum spectrum;
    double kx = 0, kz = 0, k = 0, omega = 0;
    void SetUp() override {
        GlTest::SetUp();
        SpectrumParams p;
        p.resolution = kN;
        p.patch_size = 250;
        p.wind_speed = 0;  // all zero, then one mode by hand
        spectrum = initial_spectrum(p);
        const std::size_t index = std::size_t(kModeJ) * kN + kModeI;
        spectrum.h0[index] = Complex(kAmplitude / 2, 0);
        kx = wavenumber(kModeI, kN, p.patch_size);
        kz = wavenumber(kModeJ, kN, p.patch_size);
        k = std::hypot(kx, kz);
        omega = spectrum.omega[index];
    }
    double x_of(int i) const { return i * spectrum.patch_size / kN; }
    double theta(int i, int j, double t) const { return kx * x_of(i) + kz * x_of(j) - omega * t; }
};

// Where along k/|k| the crest through the origin's wavefront is (metres, modulo a wavelength):
// from the phase of the height field's projection on e^{ik.x}, no knowledge of omega needed.
double crest_position(const std::vector<double>& height, double kx, double kz, double patch_size) {
    double re = 0, im = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const double phase = kx * i * patch_size / kN + kz * j * patch_size / kN;
            re += height[std::size_t(j) * kN + i] * std::cos(phase);
            im -= height[std::size_t(j) * kN + i] * std::sin(phase);
        }
    // height = A cos(k.x + phi): the sum is (A/2) N^2 e^{i phi}, and the crest is at k.x = -phi.
    return -std::atan2(im, re) / std::hypot(kx, kz);
}

TEST_F(GerstnerMode, CrestMovesAlongKAtThePhaseSpeed) {
    const double t0 = 2.0, dt = 0.15;  // dt short of half a period: no ambiguity modulo a wavelength
    const OceanMaps a = simulate_cpu(spectrum, t0), b = simulate_cpu(spectrum, t0 + dt);
    const double moved = std::remainder(crest_position(b[Height], kx, kz, spectrum.patch_size) -
                                            crest_position(a[Height], kx, kz, spectrum.patch_size),
                                        2 * kPi / k);
    const double deep_water_speed = std::sqrt(kGravity / k);  // depth 500 m: tanh(k h) = 1
    std::printf("one mode: crest moved %+.5f m along k in %.2f s: %.4f m/s, omega/k = %.4f, sqrt(g/k) = %.4f\n",
                moved, dt, moved / dt, omega / k, deep_water_speed);
    EXPECT_NEAR(moved / dt, omega / k, 1e-9);
    EXPECT_NEAR(moved / dt, deep_water_speed, 1e-6);
}

TEST_F(GerstnerMode, CpuProfileIsTheTrochoidAndJIsSmallestAtTheCrest) {
    const double t = 7.3;
    const OceanMaps maps = simulate_cpu(spectrum, t);
    double worst = 0, smallest_j = 1e9, theta_at_smallest = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const std::size_t index = std::size_t(j) * kN + i;
            const double th = theta(i, j, t);
            worst = std::max({worst, std::abs(maps[Height][index] - kAmplitude * std::cos(th)),
                              std::abs(maps[DisplacementX][index] + kx / k * kAmplitude * std::sin(th)),
                              std::abs(maps[DisplacementZ][index] + kz / k * kAmplitude * std::sin(th))});
            const double jacobian = maps.jacobian(index, 1.0);
            worst = std::max(worst, std::abs(jacobian - (1 - k * kAmplitude * std::cos(th))));
            if (jacobian < smallest_j) smallest_j = jacobian, theta_at_smallest = th;
        }
    EXPECT_LT(worst, 1e-12) << "the CPU maps are the closed-form trochoid";
    EXPECT_LT(std::abs(std::remainder(theta_at_smallest, 2 * kPi)), 2 * kPi / 16) << "J is smallest at a crest";
    EXPECT_NEAR(smallest_j, 1 - k * kAmplitude, 0.02);
}

TEST_F(GerstnerMode, GpuTexturesHoldTheTrochoid) {
    GpuOcean ocean(cache.factory());
    ocean.set_spectra({&spectrum});
    const double t = 7.3;
    ocean.simulate(t, Backend::GpuFft, 1.0f);
    std::vector<float> displacement(kN * kN * 4), slopes(kN * kN * 4);
    glGetTextureSubImage(ocean.displacement_texture(), 0, 0, 0, 0, kN, kN, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(displacement.size() * sizeof(float)), displacement.data());
    glGetTextureSubImage(ocean.slopes_texture(), 0, 0, 0, 0, kN, kN, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(slopes.size() * sizeof(float)), slopes.data());
    double worst = 0, smallest_j = 1e9, theta_at_smallest = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const std::size_t at = (std::size_t(j) * kN + i) * 4;
            const double th = theta(i, j, t);
            // The rendered point: rest position + (l Dx, h, l Dz), against (x - k^ A sin, A cos).
            worst = std::max({worst, std::abs(displacement[at + 1] - kAmplitude * std::cos(th)),
                              std::abs(displacement[at + 0] + kx / k * kAmplitude * std::sin(th)),
                              std::abs(displacement[at + 2] + kz / k * kAmplitude * std::sin(th))});
            const double jacobian = (1 + slopes[at + 2]) * (1 + slopes[at + 3]) - displacement[at + 3] * displacement[at + 3];
            if (jacobian < smallest_j) smallest_j = jacobian, theta_at_smallest = th;
        }
    std::printf("GPU trochoid: worst |position - closed form| = %.2e m (A = %.1f m); min J = %.4f at theta = %.3f\n",
                worst, kAmplitude, smallest_j, std::remainder(theta_at_smallest, 2 * kPi));
    EXPECT_LT(worst, 1e-4 * kAmplitude);  // float phases and a float FFT
    EXPECT_LT(std::abs(std::remainder(theta_at_smallest, 2 * kPi)), 2 * kPi / 16) << "J is smallest at a crest";
}

}  // namespace
