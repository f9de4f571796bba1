// A 10-day clock: the phases are reduced modulo 2 pi in double precision before they become
// floats, so after ten days of simulated time the waves are still exact. One wave alone makes it
// checkable: its height repeats every period T = 2 pi / omega, and matches the closed form.
#include "step02_sine3d/wave_uniforms.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"
#include "tests/gpu/vertex_capture.hpp"

#include <cmath>

namespace {

constexpr double kTenDays = 10 * 86400.0;

struct LongClock : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
};


TEST_F(LongClock, DirectionalSinesAfterTenDays) {
    const std::vector<step02::DirectionalWave> waves{{30, 12.0, 1.0, 4.3}};
    const double period = 12.0 / 4.3;  // wavelength / speed
    ocean::ShaderProgram capture("ocean", {OCEAN_SOURCE_DIR "/step02_sine3d/shaders/ocean.vert"}, {"v_world_position"});
    ASSERT_FALSE(capture.build());
    ocean::GridMesh grid;
    grid.build({40.0f, 40.0f}, 16, 16);
    auto heights_at = [&](double t) {
        step02::upload_waves(capture, waves, t);
        capture.set("u_view_projection", glm::mat4(1.0f));
        return ocean_test::capture_vertices(capture, grid, 3);
    };
    const double t0 = kTenDays + 0.11;
    const auto a = heights_at(t0), b = heights_at(t0 + 7 * period);
    const auto rest = ocean::grid_positions({40.0f, 40.0f}, 16, 16);
    double worst_repeat = 0, worst_exact = 0;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        ASSERT_TRUE(std::isfinite(a[3 * i + 1]));
        worst_repeat = std::max(worst_repeat, double(std::abs(a[3 * i + 1] - b[3 * i + 1])));
        worst_exact = std::max(worst_exact, std::abs(a[3 * i + 1] - step02::height(waves, rest[i].x, rest[i].y, t0)));
    }
    EXPECT_LT(worst_repeat, 1e-4);
    EXPECT_LT(worst_exact, 1e-4);
}

}  // namespace
