// Truth from outside the code: one Fourier mode of the choppy FFT sea is a Gerstner wave, and a
// Gerstner wave has a closed form. With h0(k) = A / 2 at one k (and nothing at -k),
//     h(x, t) = A cos(theta),  D(x, t) = -k/|k| A sin(theta),  theta = k.x - omega t,
// so with choppiness 1 the surface point of rest position x sits at (x - k/|k| A sin(theta),
// A cos(theta)): a trochoid. Its crests move along +k/|k| at omega / |k|, and the Jacobian of
// the horizontal map is J = 1 - |k| A cos(theta), smallest at the crests. Checked on the CPU
// reference (double) and on the GPU's assembled textures (what the renderer samples); the
// notes' two sign slips each fail it (crests along -k; J largest at the crests).
#include "common/gl.hpp"
#include "step05_fft/gerstner.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "tests/gpu/full_screen_draw.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/vec2.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

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

// sea=gerstner's closed form (gerstner.hpp, what gerstner.glsl is held to) is the FFT's one mode:
// with k/|k| as its direction, |k| its wavenumber, A its amplitude and Q the choppiness, its eight
// numbers are the CPU maps' at every texel, at a steepness past the fold (Q k A = 1.3), and its
// Jacobian is 1 - Q k A cos(theta).
TEST_F(GerstnerMode, ClosedFormWaveIsTheFftMode) {
    const double t = 4.1, q = 1.3 / (k * kAmplitude);
    const OceanMaps maps = simulate_cpu(spectrum, t);
    GerstnerWave wave;
    wave.direction_x = kx / k;
    wave.direction_z = kz / k;
    wave.wavenumber = k;
    wave.amplitude = kAmplitude;
    wave.steepness = q;
    double worst = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const std::size_t index = std::size_t(j) * kN + i;
            const MapSample m = gerstner_sample(wave, x_of(i), x_of(j), reduced_phase(omega, t));
            const double fft[8] = {q * maps[DisplacementX][index], maps[Height][index], q * maps[DisplacementZ][index],
                                   q * maps[DDxDz][index],         maps[SlopeX][index], maps[SlopeZ][index],
                                   q * maps[DDxDx][index],         q * maps[DDzDz][index]};
            const double closed[8] = {m.displacement[0], m.displacement[1], m.displacement[2], m.displacement[3],
                                      m.slopes[0],       m.slopes[1],       m.slopes[2],       m.slopes[3]};
            for (int f = 0; f < 8; ++f) worst = std::max(worst, std::abs(fft[f] - closed[f]));
            const double jacobian = (1 + closed[6]) * (1 + closed[7]) - closed[3] * closed[3];
            worst = std::max(worst, std::abs(jacobian - (1 - 1.3 * std::cos(theta(i, j, t)))));
        }
    EXPECT_LT(worst, 1e-9) << "one Gerstner wave in closed form is one mode of the FFT sea";
}

TEST_F(GerstnerMode, GpuTexturesHoldTheTrochoid) {
    OceanSimulation ocean(cache.factory());
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

// step05's Jacobian view (map_view.frag) on a mode steep enough to fold (|k| A = 1.2, so J runs
// from -0.2 at the crests to 2.2): every pixel is black exactly where the closed form's J < 0,
// whatever map_range says (u_range 0.1 here: the old view made the folded colour unreachable
// below a range of 1, and drew J > 1.5 in the same red). The legend's bar runs from J = 0 (red,
// bottom) to 2 (blue, top), with the black swatch below it. A tile of 64 pixels on a 64-texel
// map: pixel (96 + i, j) reads texel (i, j) at its centre.
TEST_F(GerstnerMode, JacobianViewIsBlackExactlyWhereTheSurfaceFolds) {
    const std::size_t index = std::size_t(kModeJ) * kN + kModeI;
    const double steep_amplitude = 1.2 / k;
    spectrum.h0[index] = Complex(steep_amplitude / 2, 0);
    OceanSimulation ocean(cache.factory());
    ocean.set_spectra({&spectrum});
    const double t = 3.1;
    ocean.simulate(t, Backend::GpuFft, 1.0f);
    ocean::ShaderProgram* view = cache("map_view", {"common/shaders/fullscreen.vert", "step05_fft/shaders/map_view.frag"}, {});
    ASSERT_NE(view, nullptr);
    const int width = 256, height = kN;
    ocean.bind_maps(*view);
    view->set("u_map", 5);  // MAP_JACOBIAN
    view->set("u_range", 0.1f);
    view->set("u_resolution", glm::vec2(width, height));
    view->set("u_layer", 0);
    view->set("u_spectrum_image", 3);  // not unit 0, which holds the displacement array
    const std::vector<std::uint8_t> rgba =
        ocean_test::draw_full_screen<std::uint8_t>(*view, width, height, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4);
    auto pixel = [&](int x, int y) { return &rgba[(std::size_t(y) * width + x) * 4]; };
    auto black = [&](int x, int y) { return pixel(x, y)[0] == 0 && pixel(x, y)[1] == 0 && pixel(x, y)[2] == 0; };

    int folded = 0, wrong = 0;
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const double jacobian = 1 - k * steep_amplitude * std::cos(theta(i, j, t));  // the closed form
            if (std::abs(jacobian) < 0.02) continue;  // float's margin at the boundary
            folded += jacobian < 0;
            wrong += black(96 + i, j) != (jacobian < 0);
        }
    std::printf("Jacobian view: %d of %d texels folded (J < 0), %d drawn otherwise than black iff folded\n", folded,
                kN * kN, wrong);
    EXPECT_GT(folded, 100) << "the test needs folds";
    EXPECT_EQ(wrong, 0);
    // The legend: bar at x 178..192 from y 6.4 (J = 0) to 57.6 (J = 2); the swatch at y 1.4..4.6.
    const std::uint8_t* bottom = pixel(184, 7);
    const std::uint8_t* top = pixel(184, 56);
    EXPECT_GT(bottom[0], bottom[2] + 100) << "J = 0 is red";
    EXPECT_GT(top[2], top[0] + 100) << "J = 2 is blue";
    EXPECT_TRUE(black(184, 3)) << "the folded swatch below the bar";
}

}  // namespace
