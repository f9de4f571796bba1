// What the profiles without compute shaders (GL 4.1, ES 3.0) compute in fragment passes, tested in
// every build (tests/cmake/framework_tests.cmake): float textures rendered into and read back
// (common/gl_texture.hpp, in the build's form), and step05's fragment FFT against a direct DFT in
// double, which needs nothing but the definition.
#include "common/gl_texture.hpp"
#include "step05_fft/fragment_fft.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

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

}  // namespace
