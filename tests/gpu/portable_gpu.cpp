// What the profiles without compute shaders (GL 4.1, ES 3.0) compute in fragment passes, tested in
// every build (tests/cmake/framework_tests.cmake): float textures rendered into and read back
// (common/gl_texture.hpp, in the build's form), step05's fragment FFT against a direct DFT in
// double, which needs nothing but the definition, step05's whole fragment simulation against
// the maps written from their definitions, and step06's sky, drawn face by face, and foam, a
// ping-pong of two textures.
#include "common/gl_texture.hpp"
#include "step05_fft/fragment_fft.hpp"
#include "step05_fft/fragment_simulation.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/sky.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <random>
#include <vector>

namespace {

using Complex = std::complex<double>;

struct PortableGpu : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
    ocean::ProgramFactory factory() { return cache.factory(); }
};

// The texels of level 0 of a GL_RGBA32F texture, read through a framebuffer (glGetTexImage is
// not in ES), row by row from the bottom.
std::vector<float> read_back(const ocean::Texture& texture, int width, int height) {
    ocean::Framebuffer framebuffer = ocean::make_framebuffer();
    EXPECT_TRUE(ocean::attach_texture_2d(framebuffer, GL_COLOR_ATTACHMENT0, texture));
    GLint before = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &before);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
    std::vector<float> texels(std::size_t(width) * height * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, texels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(before));
    return texels;
}

TEST_F(PortableGpu, AFloatTextureKeepsWhatWasUploaded) {
    std::vector<float> values(5 * 3 * 4);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.25f * float(i) - 7.0f;  // outside [0, 1]: a float target
    ocean::Texture texture = ocean::make_float_texture_2d(GL_RGBA32F, 5, 3);
    ocean::upload_float_texture_2d(texture, GL_RGBA32F, 5, 3, values.data());
    EXPECT_EQ(read_back(texture, 5, 3), values);
}

// y[x, z] = sum over (m, l) of v[m, l] e^{+2 pi i (m x + l z) / n}, straight from the definition.
std::vector<Complex> direct_inverse_dft(const std::vector<Complex>& v, int n) {
    const double pi = 3.14159265358979323846;
    std::vector<Complex> y(v.size());
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            Complex sum = 0;
            for (int l = 0; l < n; ++l)
                for (int m = 0; m < n; ++m)
                    sum += v[std::size_t(l * n + m)] * std::polar(1.0, 2 * pi * double((m * x + l * z) % n) / n);
            y[std::size_t(z * n + x)] = sum;
        }
    return y;
}

TEST_F(PortableGpu, TheFragmentFftMatchesTheDirectDft) {
    for (int n : {4, 16, 32}) {
        step05::FragmentFft fft(factory(), n);
        std::mt19937 random{unsigned(n)};
        std::uniform_real_distribution<float> uniform(-1, 1);
        std::vector<float> input(std::size_t(n) * n * 4);
        for (float& v : input) v = uniform(random);
        ocean::Texture source = ocean::make_float_texture_2d(GL_RGBA32F, n, n);
        ocean::upload_float_texture_2d(source, GL_RGBA32F, n, n, input.data());
        const std::vector<float> output = read_back(fft.inverse(source), n, n);
        for (int field = 0; field < 2; ++field) {
            std::vector<Complex> values(std::size_t(n) * n);
            for (std::size_t i = 0; i < values.size(); ++i) values[i] = {input[4 * i + 2 * field], input[4 * i + 2 * field + 1]};
            const std::vector<Complex> reference = direct_inverse_dft(values, n);
            double worst = 0, largest = 0;
            for (std::size_t i = 0; i < reference.size(); ++i) {
                const Complex gpu(output[4 * i + 2 * field], output[4 * i + 2 * field + 1]);
                worst = std::max(worst, std::abs(gpu - reference[i]));
                largest = std::max(largest, std::abs(reference[i]));
            }
            // float32 sums of n^2 terms of size 1: rounding of order log2(n) 1e-7 of the largest.
            EXPECT_LT(worst / largest, 1e-5) << "N = " << n << ", field " << field;
            if (field == 0) std::printf("fragment FFT, N = %d: vs the direct DFT relative error %.2e\n", n, worst / largest);
        }
    }
}

// A sea of random modes at N = 16 (h0 standard normal, none on the Nyquist row and column, where
// k and -k share a texel; omega = sqrt(g |k|)), simulated by the fragment passes at t = 3.7 s, and
// its eight maps from their definitions in double: h~(k, t) = h0(k) e^{-i omega t} +
// conj(h0(-k)) e^{+i omega t}, then the inverse DFT of h~ (height), i u h~ (Dx, Dz, u = k/|k|),
// i k h~ (slopes) and i k times i u h~ (the derivatives of D), each the real field it must be.
TEST_F(PortableGpu, TheFragmentSimulationHoldsTheMapsOfItsDefinition) {
    const int n = 16;
    const double pi = 3.14159265358979323846, g = 9.81, time = 3.7;
    const float choppiness = 1.2f;
    step05::InitialSpectrum sea;
    sea.n = n;
    sea.patch_size = 40;
    std::mt19937 random{7};
    std::normal_distribution<double> normal;
    auto signed_index = [n](int i) { return i < n / 2 ? i : i - n; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const bool nyquist = i == n / 2 || j == n / 2;
            const double kx = 2 * pi * signed_index(i) / sea.patch_size, kz = 2 * pi * signed_index(j) / sea.patch_size;
            const double a = normal(random), b = normal(random);
            sea.h0.push_back(nyquist ? Complex(0) : Complex(a, b));
            sea.omega.push_back(std::sqrt(g * std::hypot(kx, kz)));
        }
    // The eight fields' spectra, in assemble.frag's channel order.
    std::array<std::vector<Complex>, 8> spectra;
    for (auto& f : spectra) f.assign(std::size_t(n) * n, 0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t here = std::size_t(j * n + i), minus = std::size_t(((n - j) % n) * n + (n - i) % n);
            const double kx = 2 * pi * signed_index(i) / sea.patch_size, kz = 2 * pi * signed_index(j) / sea.patch_size;
            const double k = std::hypot(kx, kz);
            if (k == 0) continue;  // the mean level: nothing
            const Complex turn = std::polar(1.0, -sea.omega[here] * time), I(0, 1);
            const Complex h = sea.h0[here] * turn + std::conj(sea.h0[minus]) * std::conj(turn);
            const double ux = kx / k, uz = kz / k, l = choppiness;
            spectra[0][here] = l * I * ux * h;             // l Dx
            spectra[1][here] = h;                          // h
            spectra[2][here] = l * I * uz * h;             // l Dz
            spectra[3][here] = l * (I * kz) * (I * ux) * h;  // l dDx/dz
            spectra[4][here] = I * kx * h;                 // dh/dx
            spectra[5][here] = I * kz * h;                 // dh/dz
            spectra[6][here] = l * (I * kx) * (I * ux) * h;  // l dDx/dx
            spectra[7][here] = l * (I * kz) * (I * uz) * h;  // l dDz/dz
        }
    step05::FragmentSimulation simulation(factory());
    simulation.set_spectra({&sea});
    simulation.simulate(time, choppiness);
    const std::vector<float> displacement = simulation.read_map(false, 0), slopes = simulation.read_map(true, 0);
    ASSERT_EQ(displacement.size(), std::size_t(n) * n * 4);
    double worst = 0, largest = 0, imaginary = 0;
    for (int c = 0; c < 8; ++c) {
        const std::vector<Complex> field = direct_inverse_dft(spectra[std::size_t(c)], n);
        for (std::size_t t = 0; t < field.size(); ++t) {
            const float gpu = c < 4 ? displacement[4 * t + std::size_t(c)] : slopes[4 * t + std::size_t(c - 4)];
            worst = std::max(worst, std::abs(gpu - field[t].real()));
            largest = std::max(largest, std::abs(field[t].real()));
            imaginary = std::max(imaginary, std::abs(field[t].imag()));
        }
    }
    EXPECT_LT(imaginary, 1e-9 * largest);  // the reference itself: real fields, as the packing assumes
    EXPECT_LT(worst / largest, 1e-5);
    // Its mipmaps (glGenerateMipmap on 32-bit floats: EXT_color_buffer_float and
    // OES_texture_float_linear in ES): each texel of level 1 the mean of the 2 x 2 it covers.
    for (bool of_slopes : {false, true}) {
        const std::vector<float> level0 = of_slopes ? slopes : displacement, level1 = simulation.read_map(of_slopes, 1);
        ASSERT_EQ(level1.size(), std::size_t(n / 2) * (n / 2) * 4);
        double mip_worst = 0;
        for (int j = 0; j < n / 2; ++j)
            for (int i = 0; i < n / 2; ++i)
                for (int c = 0; c < 4; ++c) {
                    auto at = [&](int x, int z) { return double(level0[std::size_t(4 * (z * n + x) + c)]); };
                    const double mean = (at(2 * i, 2 * j) + at(2 * i + 1, 2 * j) + at(2 * i, 2 * j + 1) + at(2 * i + 1, 2 * j + 1)) / 4;
                    mip_worst = std::max(mip_worst, std::abs(level1[std::size_t(4 * (j * (n / 2) + i) + c)] - mean));
                }
        EXPECT_LT(mip_worst, 1e-6 * largest) << (of_slopes ? "slopes" : "displacement") << ": level 1";
    }
    std::printf("fragment simulation, N = %d: vs the maps' definitions relative error %.2e\n", n, worst / largest);
}

// Level 0 of cubemap face `face` (side `size`), RGBA floats, through a framebuffer.
std::vector<float> read_cube_face(GLuint cubemap, int face, int size) {
    ocean::Framebuffer framebuffer = ocean::make_framebuffer();
    GLint before = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &before);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum(face),
                           cubemap, 0);
    std::vector<float> texels(std::size_t(size) * std::size_t(size) * 4);
    glReadPixels(0, 0, size, size, GL_RGBA, GL_FLOAT, texels.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(before));
    return texels;
}

// A pass into textures (ocean::OffscreenPassState) must write every texel whatever the caller
// left on (a scissor box, culling of both faces, a closed colour mask, blending, the depth test)
// and put all of it back, the bindings too, even where they were 0 (a page draws to framebuffer
// 0: a pass that left its own bound drew the sea into it). The inverse FFT of a unit impulse at the origin is 1 everywhere: a texel
// the caller's state kept from being written shows it.
TEST_F(PortableGpu, AFragmentPassWritesEveryTexelAndPutsBackTheCallersState) {
    const int n = 8;
    step05::FragmentFft fft(factory(), n);
    std::vector<float> impulse(std::size_t(n) * n * 4, 0.0f);
    impulse[0] = 1;  // field 0 at (0, 0); field 1 (.ba) stays zero
    ocean::Texture source = ocean::make_float_texture_2d(GL_RGBA32F, n, n);
    ocean::upload_float_texture_2d(source, GL_RGBA32F, n, n, impulse.data());
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 1, 1);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    const GLuint framebuffer_before = ocean::detail::bound(GL_DRAW_FRAMEBUFFER_BINDING);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glUseProgram(0);
    const ocean::Texture& result = fft.inverse(source);
    EXPECT_EQ(ocean::detail::bound(GL_DRAW_FRAMEBUFFER_BINDING), 0u);
    EXPECT_EQ(ocean::detail::bound(GL_CURRENT_PROGRAM), 0u);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_before);
    EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST) && glIsEnabled(GL_CULL_FACE) && glIsEnabled(GL_BLEND) &&
                glIsEnabled(GL_DEPTH_TEST));
    GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    EXPECT_FALSE(mask[0] || mask[1] || mask[2] || mask[3]);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    const std::vector<float> texels = read_back(result, n, n);
    for (std::size_t i = 0; i < texels.size(); i += 4) {
        ASSERT_NEAR(texels[i], 1.0f, 1e-6f) << "texel " << i / 4;
        ASSERT_NEAR(texels[i + 1], 0.0f, 1e-6f) << "texel " << i / 4;
    }
}

// step06's sky in the build's profile, drawn face by face into its cubemap and tabulated round the
// horizon by fragment passes, held to what anyone can check by looking: without clouds, the
// brightest texel of the cube is the sun's (its glow: the disc is not in the cube), the texel
// straight up has the zenith's colour and the one nearest the horizon away from the sun the
// gradient's colour there (sky.glsl's definition: mix(horizon, zenith, up^0.45) above it, the
// horizon's darkening to 35 % below); and the fog's table is brightest towards the sun's
// azimuth. A face drawn upside down or faces swapped fail it (the sun's texel 0.71 rad off when
// the faces' rows are flipped); the fog's reading of the table is step06's own test.
TEST_F(PortableGpu, TheSkyIsDrawnFaceByFaceWithTheSunWhereItIs) {
    const int size = 32;
    step06::Sky sky(factory(), size);
    step06::SkySettings settings;
    settings.to_sun = glm::normalize(glm::vec3(0.6f, 0.35f, -0.7f));
    settings.cloud_cover = 0;  // the gradient and the sun's glow alone
    sky.render(settings);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));

    float brightest = -1;
    glm::vec3 brightest_direction(0), up_colour(0), away_colour(0);
    float up_best = -2, away_best = -2, away_up = 0;
    const glm::vec3 away = glm::normalize(glm::vec3(-settings.to_sun.x, 0, -settings.to_sun.z));
    for (int face = 0; face < 6; ++face) {
        const std::vector<float> texels = read_cube_face(sky.cubemap(), face, size);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const float* t = &texels[std::size_t(y * size + x) * 4];
                ASSERT_TRUE(std::isfinite(t[0]) && std::isfinite(t[1]) && std::isfinite(t[2]));
                const glm::vec3 colour(t[0], t[1], t[2]), d = step06::cube_texel_direction(face, x, y, size);
                if (colour.r + colour.g + colour.b > brightest) {
                    brightest = colour.r + colour.g + colour.b;
                    brightest_direction = d;
                }
                if (d.y > up_best) up_best = d.y, up_colour = colour;
                if (glm::dot(d, away) > away_best) away_best = glm::dot(d, away), away_colour = colour, away_up = d.y;
            }
    }
    // A texel spans about 2 / 32 rad at a face's centre: the glow's peak within two of them.
    EXPECT_GT(glm::dot(brightest_direction, settings.to_sun), std::cos(0.13f));
    const glm::vec3 gradient_at_horizon =
        away_up >= 0 ? glm::mix(settings.horizon, settings.zenith, std::pow(away_up, 0.45f))
                     : settings.horizon * glm::mix(1.0f, 0.35f, std::min(-away_up * 4.0f, 1.0f));
    for (int c = 0; c < 3; ++c) {  // RGBA16F (3 digits), and a trace of the sun's wide glow: within 2 %
        EXPECT_NEAR(up_colour[c], settings.zenith[c], 0.02f * settings.zenith[c]) << "straight up, channel " << c;
        EXPECT_NEAR(away_colour[c], gradient_at_horizon[c], 0.02f * gradient_at_horizon[c])
            << "the horizon (up = " << away_up << "), channel " << c;
    }

    // The fog's table: one row of kHorizonTexels, brightest towards the sun's azimuth.
    ocean::Framebuffer framebuffer = ocean::make_framebuffer();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, sky.horizon(), 0);
    std::vector<float> table(std::size_t(step06::kHorizonTexels) * 4);
    glReadPixels(0, 0, step06::kHorizonTexels, 1, GL_RGBA, GL_FLOAT, table.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    int peak = 0;
    for (int i = 0; i < step06::kHorizonTexels; ++i) {
        ASSERT_TRUE(std::isfinite(table[std::size_t(i) * 4]));
        if (table[std::size_t(i) * 4] > table[std::size_t(peak) * 4]) peak = i;
    }
    const glm::dvec2 peak_direction = glm::normalize(step06::horizon_direction((peak + 0.5) / step06::kHorizonTexels));
    const glm::dvec2 sun_azimuth = glm::normalize(glm::dvec2(settings.to_sun.x, settings.to_sun.z));
    EXPECT_GT(glm::dot(peak_direction, sun_azimuth), std::cos(0.1)) << "the table's brightest texel, " << peak;
    std::printf("sky: brightest texel %.3f rad from the sun; the fog's table peaks %.3f rad from its azimuth\n",
                double(std::acos(std::min(1.0f, glm::dot(brightest_direction, settings.to_sun)))),
                std::acos(std::min(1.0, glm::dot(peak_direction, sun_azimuth))));
}

// step06's foam in the build's profile (foam.frag drawn into each level's layer of one texture
// while it reads the other) against the closed form of its equation df/dt = q - r f on a calm sea
// (J = 1: nothing made, q = 0): foam at 1 decays as e^{-r t}, whatever the frame rate. The maps
// come from the fragment simulation of four flat cascades.
TEST_F(PortableGpu, FoamDecaysAsExpOfRateTimesTimeAtAnyFrameRate) {
    const int n = 32;
    std::vector<step05::InitialSpectrum> calm(4);
    std::vector<const step05::InitialSpectrum*> cascades;
    step06::CascadeView view;
    for (std::size_t c = 0; c < calm.size(); ++c) {
        calm[c].n = n;
        calm[c].patch_size = 500.0 / std::pow(5.0, double(c));
        calm[c].h0.assign(std::size_t(n) * n, 0.0);
        calm[c].omega.assign(std::size_t(n) * n, 0.0);
        view.patch_sizes[c] = float(calm[c].patch_size);
        cascades.push_back(&calm[c]);
    }
    step05::FragmentSimulation sea(factory());
    sea.set_spectra(cascades);
    sea.simulate(0, 1.0f);
    step06::FoamSettings settings;
    settings.decay_rate = 1.3;
    for (int frames_a_second : {10, 40}) {
        step06::FoamSimulation foam(factory());
        foam.resize(n);
        foam.fill(1.0f);
        for (int i = 0; i < frames_a_second; ++i)
            foam.update(sea.maps(), view, {0, 0}, {1, 0}, 1.0 / frames_a_second, settings);
        ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        const double expected = std::exp(-1.3);
        for (int level = 0; level < step06::kFoamLevels; ++level)
            for (float v : foam.read_level(level))
                ASSERT_NEAR(v / expected, 1.0, 0.01) << frames_a_second << " frames a second, level " << level;
        std::printf("foam after 1 s at %d frames a second: %.6f, exp(-1.3) = %.6f\n", frames_a_second,
                    double(foam.read_level(0)[0]), expected);
    }
}

}  // namespace
