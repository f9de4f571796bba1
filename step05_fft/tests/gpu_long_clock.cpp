// A 10-day clock: the phases are reduced modulo 2 pi in double precision before they become
// floats, so after ten days of simulated time the waves are still exact. One mode alone makes it
// checkable: its height repeats every period T = 2 pi / omega, and matches the closed form.
#include "step02_sine3d/wave_uniforms.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"
#include "tests/gpu/vertex_capture.hpp"

#include <cmath>

namespace {

constexpr double kTenDays = 10 * 86400.0;

struct LongClock : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
};

TEST_F(LongClock, OneFftModeAfterTenDays) {
    // h0 has one mode, k = (3, 0) * 2 pi / L; then h(x, t) = 2 |h0| cos(k x - omega t + arg h0):
    // crests travel along +k (the notes' sign would give k x + omega t, crests along -k).
    step05::SpectrumParams p;
    p.resolution = 64;
    p.wind_speed = 0;  // all zero, then one mode by hand
    step05::InitialSpectrum s = step05::initial_spectrum(p);
    const std::complex<double> amplitude(0.3, -0.4);  // |h0| = 0.5
    s.h0[3] = amplitude;
    const double k = 2 * step05::kPi * 3 / p.patch_size, omega = s.omega[3];
    const double period = 2 * step05::kPi / omega;
    step05::OceanSimulation ocean(cache.factory());
    ocean.set_spectra({&s});
    auto heights_at = [&](double t) {
        ocean.evolve(t);
        ocean.transform_fft(ocean.spectra_buffer(), ocean.fields_buffer(), 4);
        const auto fields = ocean.read_fields();
        std::vector<double> h(64);
        for (int i = 0; i < 64; ++i) h[std::size_t(i)] = fields[std::size_t(2 * i)];  // row z = 0, real part: h
        return h;
    };
    const double t0 = kTenDays + 0.37;
    const auto later = heights_at(t0), repeated = heights_at(t0 + 5 * period);
    double worst_repeat = 0, worst_exact = 0;
    for (int i = 0; i < 64; ++i) {
        const double x = i * p.patch_size / 64;
        const double exact = 2 * std::abs(amplitude) * std::cos(k * x - std::fmod(omega * t0, 2 * step05::kPi) + std::arg(amplitude));
        ASSERT_TRUE(std::isfinite(later[std::size_t(i)]));
        worst_repeat = std::max(worst_repeat, std::abs(later[std::size_t(i)] - repeated[std::size_t(i)]));
        worst_exact = std::max(worst_exact, std::abs(later[std::size_t(i)] - exact));
    }
    std::printf("after 10 days: |h(t) - h(t + 5T)| <= %.2e m, |h - closed form| <= %.2e m (amplitude 1 m)\n",
                worst_repeat, worst_exact);
    EXPECT_LT(worst_repeat, 1e-5);
    EXPECT_LT(worst_exact, 1e-5);
}

}  // namespace
