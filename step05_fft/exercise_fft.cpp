#include "step05_fft/exercise_fft.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <sstream>

#include "common/gl.hpp"
#include "common/program_library.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/spectrum.hpp"

namespace exercises {

Verdict check_fft(const fs::path& work, step05::GpuFftForm form) {
    // The chapter's programs as the step gets them, its own shaders read from the work folder.
    ocean::ProgramLibrary programs;
    programs.set_shader_dir(std::string(OCEAN_SOURCE_DIR) + "/step05_fft/shaders", work.string());
    const ocean::ProgramFactory factory = programs.factory();
    std::ostringstream detail;
    for (int n : {64, 128, 256, 512}) {
        step05::SpectrumParams p;
        p.resolution = n;
        const step05::InitialSpectrum sizes = step05::initial_spectrum(p);  // only to size the buffers
        step05::OceanSimulation ocean(factory);
        ocean.set_spectra({&sizes});
        ocean.set_gpu_fft_form(form);
        std::mt19937 random{unsigned(n)};
        std::uniform_real_distribution<float> uniform(-1, 1);
        std::vector<float> input(std::size_t(n) * n * 2);  // the first of the four fields
        for (float& v : input) v = uniform(random);
        glNamedBufferSubData(ocean.spectra_buffer(), 0, GLsizeiptr(input.size() * sizeof(float)),
                             input.data());
        try {
            ocean.transform_fft(ocean.spectra_buffer(), ocean.fields_buffer(), 1);
        } catch (const std::exception& error) {
            return {false, std::string("your shader does not build: ") + error.what()};
        }
        const std::vector<float> output = ocean.read_fields();
        step05::ComplexField field(std::size_t(n) * n);
        for (std::size_t i = 0; i < field.size(); ++i) field[i] = {input[2 * i], input[2 * i + 1]};
        const step05::ComplexField reference = step05::inverse_fft_2d(field, n);
        double worst = 0, largest = 0;
        std::size_t worst_at = 0;
        for (std::size_t i = 0; i < reference.size(); ++i) {
            const std::complex<double> gpu(output[2 * i], output[2 * i + 1]);
            const double difference =
                std::isfinite(gpu.real() + gpu.imag()) ? std::abs(gpu - reference[i]) : 1e30;
            largest = std::max(largest, std::abs(reference[i]));
            if (difference > worst) worst = difference, worst_at = i;
        }
        detail << "N = " << n << ": worst |yours - reference| " << worst << " of " << largest
               << " (at x = " << worst_at % std::size_t(n) << ", z = " << worst_at / std::size_t(n) << ")";
        if (worst > 1e-4 * largest) return {false, detail.str()};
        detail << "; ";
    }
    return {true, detail.str() + "the inverse 2D transform of random spectra"};
}

}  // namespace exercises
