// Foam moves with the water it floats on, on the GPU: the mesh (ocean.vert/tesc/tese/frag) draws
// the water of rest position a at a + D(a, t) and writes a into the G-buffer, where the shading
// reads the foam kept at a (foam.hpp). So foam stored at label a0 is drawn where the water
// particle a0 is: on its orbit, back and forth about a0, neither fixed in the world (foam kept
// on an Eulerian grid) nor carried along with the crest at the phase speed.
//
// The sea is one travelling wave along x, drawn from straight above into the G-buffer at five
// times; a thin strip of labels around a0 is found in the picture (the mean world x of the pixels
// whose rest x lies in it) and held to the particle's closed-form position.
#include "common/frustum.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/gbuffer.hpp"
#include "step06_foam_sky/patch_grid.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>
#include <cstring>

namespace {

struct FoamOnOneWave : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
};

TEST_F(FoamOnOneWave, FoamIsDrawnWhereItsWaterParticleIs) {
    const auto started = std::chrono::steady_clock::now();
    // One mode in cascade 0 (a 64 m tile, N = 64, 1 m texels): k = 2 pi 2 / 64 along x (32 m
    // waves), steepness k A = 0.2, choppiness 1. h0(k) = A / 2 and h0(-k) = 0: the evolution adds
    // conj(h0(k)) at -k itself, so h = A cos(k a - omega t), a wave travelling along +x. With
    // D~ = +i k/|k| h~ (ocean_maps.hpp) its displacement is
    //     D_x(a, t) = -A sin(k a - omega t),
    // which crowds the water towards each crest (a Gerstner wave). The other cascades are calm.
    constexpr int kN = 64, kMode = 2;
    constexpr double kTile = 64;
    const double k = 2 * ocean::kPi * kMode / kTile, amplitude = 0.2 / k;
    const double omega = std::sqrt(ocean::kGravity * k);  // deep water (the spectrum's depth is 500 m)
    const double period = 2 * ocean::kPi / omega, phase_speed = omega / k;
    step05::SpectrumParams calm;
    calm.resolution = kN;
    calm.patch_size = kTile;
    calm.wind_speed = 0;
    std::vector<step05::InitialSpectrum> spectra(4, step05::initial_spectrum(calm));
    step05::InitialSpectrum& wave = spectra[0];
    wave.h0[kMode] = {amplitude / 2, 0};  // row j = 0, column i = kMode: k = (kx, 0)
    ASSERT_NEAR(wave.omega[kMode], omega, 1e-9 * omega) << "the dispersion the simulation uses";
    std::vector<const step05::InitialSpectrum*> pointers;
    for (const auto& s : spectra) pointers.push_back(&s);
    step05::OceanSimulation ocean(cache.factory());
    ocean.set_spectra(pointers);

    step06::CascadeView cascades;
    const auto sizes = step06::cascade_patch_sizes(kTile);
    for (int c = 0; c < step06::kCascades; ++c) cascades.patch_sizes[std::size_t(c)] = float(sizes[std::size_t(c)]);

    const std::string dir = "step06_foam_sky/shaders/";
    ocean::ShaderProgram* mesh =
        cache("ocean", {dir + "ocean.vert", dir + "ocean.tesc", dir + "ocean.tese", dir + "ocean.frag"}, {});
    ASSERT_NE(mesh, nullptr);

    // From straight above, orthographic: x in [0, 64] m over 256 pixels (0.25 m each), z in
    // [0, 16] over 64 rows. The pixel grid is slanted by one pixel over its height, so the 64 rows
    // meet the strip's edges at 64 different sub-pixel offsets: the wave is the same in every row,
    // and the mean position would otherwise keep a whole row's rounding (up to half a pixel).
    const glm::ivec2 size(256, 64);
    const double pixel = 64.0 / size.x;
    const glm::vec3 centre(32, 0, 8);
    glm::mat4 slant(1.0f);
    slant[1][0] = 1.0f / float(size.x);  // x_ndc += y_ndc / 256: one pixel (2 / 256) over y's 2
    const glm::mat4 view_projection = slant * glm::ortho(-32.0f, 32.0f, -8.0f, 8.0f, 1.0f, 200.0f) *
                                      glm::lookAt(centre + glm::vec3(0, 100, 0), centre, glm::vec3(0, 0, -1));
    // The tessellation: 16 m patches cut 64 times (0.25 m), the finest GL allows: the eye the
    // levels are computed from is set close, so every patch in view gets it, and the footprint
    // (twice the spacing of distance / 1000: under 0.15 m) reads the maps at mip level 0.
    step06::PatchGrid grid;
    grid.build(8, 16);
    mesh->set("u_view_projection", view_projection);
    mesh->set("u_eye", centre + glm::vec3(0, 10, 0));
    mesh->set("u_grid_offset", glm::vec2(32, 8));
    mesh->set("u_tess_patch_size", 16.0f);
    mesh->set("u_tess_scale", 1000.0f);
    mesh->set("u_frustum", ocean::frustum_planes(view_projection));
    mesh->set("u_max_displacement", float(2 * amplitude + 1));
    cascades.upload(*mesh);

    ocean::Texture depth = ocean::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
    step06::GBuffer gbuffer;
    gbuffer.resize(size, depth.id());
    GLint previous_framebuffer = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_framebuffer);

    // The strip of foam: labels a in [a0 - w/2, a0 + w/2), 2 pixels wide. a0 sits on a texel
    // (x_i = i L / N), where the CPU reference has D without interpolation.
    const double a0 = 32, width = 0.5;
    // t0 puts a0 a quarter period before its crest (k a0 - omega t0 = pi / 2: D = -A); the others
    // keep |sin| >= 0.71, where the particle is at least 0.7 A from a0, then one 3.5 periods on.
    const double t0 = (k * a0 - 0.5 * ocean::kPi + 2 * ocean::kPi) / omega;
    const double fractions[] = {0, 0.375, 0.5, 0.875, 3.5};
    // Tolerance: 0.1 pixel (2.5 cm). The error budget: the strip's mean is the midpoint of its
    // image, x(a0) + (w^2 / 8) x'' (at most 0.1 cm); the maps' bilinear interpolation between 1 m
    // texels, up to A (1 - cos(k / 2)) (0.5 cm; 0.3 cm at the strip's ends, what is measured);
    // the 0.25 m mesh, A (1 - cos(k / 8)) (0.03 cm); the 64 sub-pixel offsets, about a 64th of a
    // pixel (0.4 cm). The alternatives are 0.7 m and more away: 28 tolerances.
    const double tolerance = 0.1 * pixel;
    std::printf("one wave: lambda %.1f m, A %.3f m (kA 0.2), omega %.4f rad/s (T %.3f s), c %.3f m/s; "
                "strip [%.2f, %.2f) m; tolerance %.4f m (0.1 pixel)\n",
                2 * ocean::kPi / k, amplitude, omega, period, phase_speed, a0 - width / 2, a0 + width / 2, tolerance);
    std::printf("  t - t0 (T)  drawn at   particle  |drawn-particle|  (CPU ref D)   Eulerian  |drawn-Eul.|"
                "  crest-riding  |drawn-crest|\n");
    for (double fraction : fractions) {
        const double t = t0 + fraction * period;
        ocean.simulate(t, step05::Backend::GpuFft, 1.0f);
        gbuffer.bind();
        const float far_depth = 1.0f;
        const GLuint no_label[4] = {0x7fc00000u, 0x7fc00000u, 0, 0};  // NaN: no water drawn here
        const float zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_DEPTH, 0, &far_depth);
        glClearBufferfv(GL_COLOR, 0, zero);
        glClearBufferuiv(GL_COLOR, 1, no_label);
        ocean.bind_maps(*mesh);
        glEnable(GL_DEPTH_TEST);
        glUseProgram(mesh->id());
        grid.draw(*mesh, step06::PatchView{view_projection, centre + glm::vec3(0, 10, 0), glm::vec2(32, 8), float(2 * amplitude + 1)},
                  1000.0f, false);
        glDisable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous_framebuffer));

        std::vector<float> world(std::size_t(size.x) * std::size_t(size.y) * 4);
        std::vector<GLuint> rest(world.size());
        glGetTextureImage(gbuffer.world_texture(), 0, GL_RGBA, GL_FLOAT, GLsizei(world.size() * sizeof(float)),
                          world.data());
        glGetTextureImage(gbuffer.rest_texture(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                          GLsizei(rest.size() * sizeof(GLuint)), rest.data());
        double sum = 0;
        int in_strip = 0, uncovered = 0;
        for (std::size_t p = 0; p < world.size() / 4; ++p) {
            float label = 0;
            std::memcpy(&label, &rest[4 * p], sizeof label);
            if (std::isnan(label)) {
                ++uncovered;
                continue;
            }
            if (label >= a0 - width / 2 && label < a0 + width / 2) {
                sum += world[4 * p];
                ++in_strip;
            }
        }
        ASSERT_EQ(uncovered, 0) << "the sea must cover the picture";
        ASSERT_GT(in_strip, 64) << "the strip must be found in every row";
        const double drawn = sum / in_strip;

        // The three places the foam could be: the particle's (closed form, and the CPU
        // reference's D at a0's texel beside it, the same within float), the fixed point, the crest's.
        const double particle = a0 - amplitude * std::sin(k * a0 - omega * t);
        const step05::OceanMaps cpu = step05::simulate_cpu(wave, t);
        const double cpu_particle = a0 + cpu[step05::DisplacementX][std::size_t(a0)];
        const double eulerian = a0, crest = a0 + phase_speed * (t - t0);
        std::printf("  %10.3f  %8.4f   %8.4f  %14.4f   (%8.4f)  %9.4f  %11.4f  %12.4f  %13.4f\n", fraction, drawn,
                    particle, std::abs(drawn - particle), cpu_particle, eulerian, std::abs(drawn - eulerian), crest,
                    std::abs(drawn - crest));
        ASSERT_NEAR(cpu_particle, particle, 1e-9) << "the closed form's sign is the simulation's";
        EXPECT_NEAR(drawn, particle, tolerance) << "t - t0 = " << fraction << " T";
        EXPECT_GT(std::abs(drawn - eulerian), 20 * tolerance) << "foam fixed in the world, t - t0 = " << fraction;
        if (fraction > 0) {  // at t0 the crest-riding foam starts from a0 too
            EXPECT_GT(std::abs(drawn - crest), 20 * tolerance) << "foam riding the crest, t - t0 = " << fraction;
        }
    }
    std::printf("%.2f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
}

}  // namespace
