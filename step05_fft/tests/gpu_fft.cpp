// step05 on the GPU: the Stockham FFT against FFTW on random input, and the three backends'
// ocean fields against the CPU reference (spectrum, h0, time evolution in double, FFTW).
// Relative error = max |gpu - reference| / max |reference|, per field; limit 1e-4.
#include "common/error.hpp"
#include "step05_fft/fragment_fft.hpp"
#include "step05_fft/fragment_simulation.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <string>

namespace {

using namespace step05;

struct FftTest : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
    ocean::ProgramFactory factory() { return cache.factory(); }
    // The default sea at resolution n, and a OceanSimulation holding it (the spectrum must outlive it).
    static InitialSpectrum sea(int n) {
        SpectrumParams p;
        p.resolution = n;
        return initial_spectrum(p);
    }
    std::unique_ptr<OceanSimulation> ocean_of(const InitialSpectrum& s) {
        auto ocean = std::make_unique<OceanSimulation>(factory());
        ocean->set_spectra({&s});
        return ocean;
    }
};

double relative_error(const std::vector<float>& gpu, std::size_t offset, std::size_t stride,
                      const std::vector<double>& reference) {
    double worst = 0, largest = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        worst = std::max(worst, std::abs(double(gpu[offset + i * stride]) - reference[i]));
        largest = std::max(largest, std::abs(reference[i]));
    }
    return largest > 0 ? worst / largest : worst;
}

// The largest difference between the two assembled maps (RGBA, as read back) and the reference's
// fields with the choppiness where it belongs, over the largest expected value.
double choppy_maps_error(const std::vector<float>& displacement, const std::vector<float>& slopes,
                         const OceanMaps& reference, float choppiness) {
    double scale = 0, worst = 0;
    for (std::size_t i = 0; i < reference[Height].size(); ++i) {
        const double expected[8] = {choppiness * reference[DisplacementX][i], reference[Height][i],
                                    choppiness * reference[DisplacementZ][i], choppiness * reference[DDxDz][i],
                                    reference[SlopeX][i], reference[SlopeZ][i],
                                    choppiness * reference[DDxDx][i], choppiness * reference[DDzDz][i]};
        for (int c = 0; c < 8; ++c) {
            const float got = c < 4 ? displacement[i * 4 + std::size_t(c)] : slopes[i * 4 + std::size_t(c - 4)];
            worst = std::max(worst, std::abs(got - expected[c]));
            scale = std::max(scale, std::abs(expected[c]));
        }
    }
    return worst / scale;
}

// The fragment-pass FFT (the portable profiles' FFT) on random input: both fields of the texture
// against FFTW's inverse transform in double, from 2 x 2 to 512 x 512. float32 throughout, so the
// error grows like log2 N times the rounding: the same 1e-4 as the compute forms.
TEST_F(FftTest, FragmentFftMatchesFftwOnRandomInput) {
    for (int n : {2, 8, 64, 256, 512}) {
        FragmentFft fft(factory(), n);
        std::mt19937 random{unsigned(n) + 7u};
        std::uniform_real_distribution<float> uniform(-1, 1);
        std::vector<float> input(std::size_t(n) * n * 4);
        for (float& v : input) v = uniform(random);
        ocean::Texture source = ocean::make_float_texture_2d(GL_RGBA32F, n, n);
        ocean::upload_float_texture_2d(source, GL_RGBA32F, n, n, input.data());
        const ocean::Texture& result = fft.inverse(source);
        std::vector<float> output(input.size());
        glGetTextureImage(result.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(output.size() * sizeof(float)), output.data());
        for (int field = 0; field < 2; ++field) {
            // Texel (x, z) at z n + x, as ComplexField's row (z) major layout.
            ComplexField values(std::size_t(n) * n);
            for (std::size_t i = 0; i < values.size(); ++i)
                values[i] = {input[4 * i + 2 * field], input[4 * i + 2 * field + 1]};
            const ComplexField reference = inverse_fft_2d(values, n);
            std::vector<double> re(reference.size()), im(reference.size());
            for (std::size_t i = 0; i < reference.size(); ++i) {
                re[i] = reference[i].real();
                im[i] = reference[i].imag();
            }
            const double error = std::max(relative_error(output, 2 * field, 4, re), relative_error(output, 2 * field + 1, 4, im));
            EXPECT_LT(error, 1e-4) << "N = " << n << ", field " << field;
            if (field == 0) std::printf("fragment FFT, N = %d: vs FFTW relative error %.2e\n", n, error);
        }
    }
}

// The passes leave the caller's state as it was: its framebuffer, viewport and program drawn with next.
TEST_F(FftTest, FragmentFftPutsBackTheFramebufferViewportAndProgram) {
    FragmentFft fft(factory(), 16);
    ocean::Texture source = ocean::make_float_texture_2d(GL_RGBA32F, 16, 16);
    ocean::Framebuffer mine = ocean::make_framebuffer();
    ocean::Texture colour = ocean::make_float_texture_2d(GL_RGBA32F, 40, 30);
    ASSERT_TRUE(ocean::attach_texture_2d(mine, GL_COLOR_ATTACHMENT0, colour));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, mine.id());
    glViewport(3, 4, 40, 30);
    glEnable(GL_BLEND);
    fft.inverse(source);
    GLint framebuffer = 0, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(GLuint(framebuffer), mine.id());
    EXPECT_EQ(viewport[0], 3);
    EXPECT_EQ(viewport[2], 40);
    EXPECT_TRUE(glIsEnabled(GL_BLEND));
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

TEST_F(FftTest, FragmentFftRefusesASizeThatIsNotAPowerOfTwo) {
    EXPECT_THROW(FragmentFft(factory(), 100), ocean::Error);
    EXPECT_THROW(FragmentFft(factory(), 1), ocean::Error);
}

// Both forms of the GPU FFT (the plain radix 2 and radix 4 in Stockham's order), every resolution.
TEST_F(FftTest, GpuFftMatchesFftwOnRandomInput) {
    for (GpuFftForm form : {GpuFftForm::Radix2, GpuFftForm::Stockham4})
    for (int n : {64, 128, 256, 512}) {
        const std::string name = gpu_fft_form_names()[std::size_t(form)];
        SpectrumParams p;
        p.resolution = n;
        const InitialSpectrum s = initial_spectrum(p);  // only to size the buffers
        OceanSimulation ocean(factory());
        ocean.set_spectra({&s});
        ocean.set_gpu_fft_form(form);
        std::mt19937 random{unsigned(n)};
        std::uniform_real_distribution<float> uniform(-1, 1);
        std::vector<float> input(std::size_t(n) * n * 4 * 2);
        for (float& v : input) v = uniform(random);
        glNamedBufferSubData(ocean.spectra_buffer(), 0, GLsizeiptr(input.size() * sizeof(float)), input.data());
        ocean.transform_fft(ocean.spectra_buffer(), ocean.fields_buffer(), 4);
        const auto output = ocean.read_fields();
        for (int layer = 0; layer < 4; ++layer) {
            const std::size_t base = std::size_t(layer) * n * n;
            ComplexField field(std::size_t(n) * n);
            for (std::size_t i = 0; i < field.size(); ++i)
                field[i] = {input[2 * (base + i)], input[2 * (base + i) + 1]};
            const auto reference = inverse_fft_2d(field, n);
            std::vector<double> re(reference.size()), im(reference.size());
            for (std::size_t i = 0; i < reference.size(); ++i) {
                re[i] = reference[i].real();
                im[i] = reference[i].imag();
            }
            const double error = std::max(relative_error(output, 2 * base, 2, re),
                                          relative_error(output, 2 * base + 1, 2, im));
            EXPECT_LT(error, 1e-4) << name << ", N = " << n << ", layer " << layer;
            if (layer == 0) std::printf("%s, N = %d: GPU FFT vs FFTW relative error %.2e\n", name.c_str(), n, error);
        }
    }
}

// evolve.comp alone, against the chapter's CPU reference (packed_spectra, in double): every mode's
// four packed spectra (h + i Dx, Dz + i dh/dx, dh/dz + i dDx/dx, dDz/dz + i dDx/dz) at three times.
// Run before the transforms, it says which of the two stages is wrong when the backends disagree
// with the CPU (it found NVIDIA's driver swapping x and y in the nested i (i h) swizzles).
TEST_F(FftTest, EvolvedSpectraMatchTheFormulas) {
    const int n = 64;
    const InitialSpectrum s = sea(n);
    const auto ocean = ocean_of(s);
    const std::size_t area = std::size_t(n) * n;
    for (double t : {0.0, 2.5, 86400.0 * 3 + 0.25}) {
        ocean->evolve(t);
        std::vector<float> gpu(area * 4 * 2);
        glGetNamedBufferSubData(ocean->spectra_buffer(), 0, GLsizeiptr(gpu.size() * sizeof(float)), gpu.data());
        const std::array<ComplexField, 4> packed = packed_spectra(s, t);
        double worst[4] = {0, 0, 0, 0}, largest = 0;
        std::string where[4];  // the worst mode of each field, for the failure message
        int wrong[4] = {0, 0, 0, 0};  // modes off by more than 1e-5 of the largest value
        for (std::size_t mode = 0; mode < area; ++mode)
            for (int f = 0; f < 4; ++f) largest = std::max(largest, std::abs(packed[std::size_t(f)][mode]));
        for (std::size_t mode = 0; mode < area; ++mode)
            for (int f = 0; f < 4; ++f) {
                const Complex expected = packed[std::size_t(f)][mode];
                const std::size_t at = 2 * (std::size_t(f) * area + mode);
                const double error = std::abs(Complex(gpu[at], gpu[at + 1]) - expected);
                if (error > 1e-5 * largest) ++wrong[f];
                if (error > worst[f]) {
                    worst[f] = error;
                    where[f] = "mode (" + std::to_string(mode % n) + ", " + std::to_string(mode / n) + "): GPU (" +
                               std::to_string(gpu[at]) + ", " + std::to_string(gpu[at + 1]) + "), expected (" +
                               std::to_string(expected.real()) + ", " + std::to_string(expected.imag()) + ")";
                }
            }
        for (int f = 0; f < 4; ++f)
            EXPECT_LT(worst[f] / largest, 1e-5) << "packed field " << f << ", t = " << t << ", " << wrong[f]
                                                << " modes off, worst at " << where[f];
        std::printf("t = %g: evolved spectra, worst error per packed field %.1e %.1e %.1e %.1e of %.2e\n", t,
                    worst[0] / largest, worst[1] / largest, worst[2] / largest, worst[3] / largest, largest);
    }
}

TEST_F(FftTest, BackendsMatchTheCpuReference) {
    for (int n : {64, 128, 256}) {
        SpectrumParams p;
        p.resolution = n;
        p.seed = 7;
        const InitialSpectrum s = initial_spectrum(p);
        OceanSimulation ocean(factory());
        ocean.set_spectra({&s});
        for (double t : {0.0, 2.5, 86400.0 * 3 + 0.25}) {
            const OceanMaps reference = simulate_cpu(s, t);
            // Each backend, the GPU FFT in both its forms.
            std::vector<std::pair<std::string, std::function<void()>>> backends = {
                {"GPU FFT radix2", [&] {
                     ocean.evolve(t);
                     ocean.transform_radix2(ocean.spectra_buffer(), ocean.fields_buffer(), 4);
                 }},
                {"GPU FFT stockham4", [&] {
                     ocean.evolve(t);
                     ocean.transform_stockham4(ocean.spectra_buffer(), ocean.fields_buffer(), 4);
                 }},
                {"FFTW", [&] { ocean.upload_cpu_fields(t); }}};
            if (n <= kMaxDftSize)
                backends.push_back({"DFT", [&] {
                                        ocean.evolve(t);
                                        ocean.transform_dft(ocean.spectra_buffer(), ocean.fields_buffer(), 4);
                                    }});
            for (const auto& [name, run] : backends) {
                run();
                const auto fields = ocean.read_fields();
                double worst = 0;
                for (std::size_t pair = 0; pair < 4; ++pair)
                    for (std::size_t part = 0; part < 2; ++part) {
                        const double e = relative_error(fields, pair * n * n * 2 + part, 2,
                                                        reference[kPacking[pair][part]]);
                        EXPECT_LT(e, 1e-4) << "N = " << n << ", backend " << name << ", t = " << t
                                           << ", " << field_name(kPacking[pair][part]);
                        worst = std::max(worst, e);
                    }
                std::printf("N = %d, backend %s, t = %g: worst relative error %.2e\n", n, name.c_str(), t, worst);
            }
        }
    }
}

// Backend::Auto decides after kAutoTrialFrames frames of each backend, says so once, and every
// frame, deciding or not, holds the sea the CPU reference holds at that time; a new resolution
// starts a new trial.
TEST_F(FftTest, AutoBackendDecidesOnceAndEveryFrameIsTheSea) {
    const InitialSpectrum s = sea(64);
    const auto owned = ocean_of(s);
    OceanSimulation& ocean = *owned;
    int decisions = 0;
    for (int frame = 0; frame < 2 * kAutoTrialFrames + 2; ++frame) {
        const double t = 0.5 * frame;
        ocean.simulate(t, Backend::Auto, 1.0f);
        if (auto decision = ocean.take_auto_decision()) {
            ++decisions;
            EXPECT_EQ(frame, 2 * kAutoTrialFrames - 1) << *decision;
            EXPECT_NE(decision->find("at N = 64"), std::string::npos) << *decision;
        }
        // What simulate() leaves for the renderer: the height is the displacement map's green.
        const OceanMaps reference = simulate_cpu(s, t);
        EXPECT_LT(relative_error(ocean.read_map(false, 0), 1, 4, reference[Height]), 1e-4) << "frame " << frame;
    }
    EXPECT_EQ(decisions, 1);
    const InitialSpectrum larger = sea(128);
    ocean.set_spectra({&larger});
    for (int frame = 0; frame < 2 * kAutoTrialFrames; ++frame) ocean.simulate(0.5 * frame, Backend::Auto, 1.0f);
    EXPECT_TRUE(ocean.take_auto_decision().has_value());  // decided again, for the new size
}

// Both backends' textures (the GPU's assemble.comp; the CPU's CpuSimulation::assemble) hold the
// reference's maps, with the choppiness applied where it belongs.
TEST_F(FftTest, AssembledTexturesHoldTheChoppyMaps) {
    const InitialSpectrum s = sea(64);
    const OceanMaps reference = simulate_cpu(s, 4.0);
    const float choppiness = 1.3f;
    for (Backend backend : {Backend::GpuFft, Backend::Fftw}) {
        const auto ocean = ocean_of(s);
        ocean->simulate(4.0, backend, choppiness);
        const std::vector<float> displacement = ocean->read_map(false, 0), slopes = ocean->read_map(true, 0);
        EXPECT_LT(choppy_maps_error(displacement, slopes, reference, choppiness), 1e-4)
            << (backend == Backend::Fftw ? "FFTW" : "GPU FFT");
    }
}

// The FFTW backend filters its own mipmaps on the CPU, the GPU FFT backend by box_mip.comp (which
// gpu_box_mipmaps.cpp holds to glGenerateMipmap): every level of both maps the same, to float rounding
// (relative to the map's largest value at level 0: the last level is the mean, near zero).
TEST_F(FftTest, CpuMipmapsAreGlsMipmaps) {
    const InitialSpectrum s = sea(128);
    const auto gpu = ocean_of(s), cpu = ocean_of(s);
    gpu->simulate(3.0, Backend::GpuFft, 1.3f);
    cpu->simulate(3.0, Backend::Fftw, 1.3f);
    for (bool slopes : {false, true}) {
        double scale = 0;
        for (float v : gpu->read_map(slopes, 0)) scale = std::max(scale, double(std::abs(v)));
        for (int level = 0; (128 >> level) >= 1; ++level) {
            const auto expected = gpu->read_map(slopes, level), got = cpu->read_map(slopes, level);
            double worst = 0;
            for (std::size_t i = 0; i < expected.size(); ++i)
                worst = std::max(worst, double(std::abs(got[i] - expected[i])));
            EXPECT_LT(worst / scale, 1e-5) << (slopes ? "slopes" : "displacement") << " level " << level;
        }
    }
}

}  // namespace

namespace {

// The portable profiles' simulation (fragment passes: evolve.frag, the fragment FFT, assemble.frag,
// glGenerateMipmap) holds the same maps as the CPU reference: every channel of both maps, the
// choppiness where it belongs, to the compute forms' 1e-4 of the largest value.
TEST_F(FftTest, FragmentSimulationHoldsTheCpuReferencesMaps) {
    for (int n : {16, 64}) {
        const InitialSpectrum s = sea(n);
        const double time = 4.0;
        const float choppiness = 1.3f;
        const OceanMaps reference = simulate_cpu(s, time);
        FragmentSimulation fragment(factory());
        fragment.set_spectra({&s});
        fragment.simulate(time, choppiness);
        const std::vector<float> displacement = fragment.read_map(false, 0), slopes = fragment.read_map(true, 0);
        ASSERT_EQ(displacement.size(), std::size_t(n * n * 4));
        EXPECT_LT(choppy_maps_error(displacement, slopes, reference, choppiness), 1e-4) << "N = " << n;
    }
}

// Its mipmaps (glGenerateMipmap) are the compute form's box mipmaps, level by level, and a frame
// ten days on is still the reference's (the phase reduced in double on the CPU).
TEST_F(FftTest, FragmentSimulationsMipmapsAndLongClockMatchTheComputeForm) {
    const InitialSpectrum s = sea(64);
    const double ten_days = 864000.25;
    FragmentSimulation fragment(factory());
    fragment.set_spectra({&s});
    fragment.simulate(ten_days, 1.0f);
    const auto compute = ocean_of(s);
    compute->simulate(ten_days, Backend::GpuFft, 1.0f);
    for (bool slopes : {false, true}) {
        double scale = 0;
        for (float v : compute->read_map(slopes, 0)) scale = std::max(scale, double(std::abs(v)));
        for (int level = 0; (64 >> level) >= 1; ++level) {
            const auto expected = compute->read_map(slopes, level), got = fragment.read_map(slopes, level);
            ASSERT_EQ(got.size(), expected.size());
            double worst = 0;
            for (std::size_t i = 0; i < expected.size(); ++i)
                worst = std::max(worst, double(std::abs(got[i] - expected[i])));
            EXPECT_LT(worst / scale, 1e-4) << (slopes ? "slopes" : "displacement") << " level " << level;
        }
    }
}

}  // namespace
