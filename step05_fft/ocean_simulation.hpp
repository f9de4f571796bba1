// The FFT ocean's simulation: buffers, the compute passes (evolve, transform, assemble) and the two
// textures the renderer samples. It simulates one or more cascades of the same resolution at
// once (step05 uses one; a program may run several), and transforms with one of three backends: the naive DFT
// and the FFT on the GPU, or FFTW on the CPU (CpuSimulation), whose maps it uploads.
#pragma once

#include "common/faster_of_two.hpp"
#include "common/gl.hpp"
#include "common/gpu_timer.hpp"
#include "common/shader.hpp"
#include "step05_fft/cpu_simulation.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/simulation_maps.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace step05 {

// Auto: the faster of GpuFft and Fftw, found on the frames themselves. While deciding, frames
// alternate between the two and each whole simulate() (evolve, transform, unpack, and for FFTW the
// upload) is timed, wall ms around glFinish; after kAutoTrialFrames of each the lower median wins,
// until the resolution changes. No frame is spent only on timing, so a step starts as fast as
// before. On llvmpipe the "GPU" is the CPU, and FFTW wins; on a real GPU the GPU FFT does.
enum class Backend { Dft = 0, GpuFft = 1, Fftw = 2, Auto = 3 };
// Each backend's name, written once (Backend's order): the `backend` parameters' choices.
inline const std::vector<std::string>& backend_names() {
    static const std::vector<std::string> names = {"dft", "gpu_fft", "fftw", "auto"};
    return names;
}
// The names of `offered`, in that order (a step that offers some of the backends).
template <std::size_t N>
std::vector<std::string> backend_names(const std::array<Backend, N>& offered) {
    std::vector<std::string> names;
    for (Backend b : offered) names.push_back(backend_names()[std::size_t(b)]);
    return names;
}
// The GPU FFT's two forms (the `fft` parameter): the plain radix-2 FFT the chapter derives first,
// one dispatch per stage through memory (fft_radix2.comp), and its optimisation, radix 4 in Stockham's
// order with every stage of a line in shared memory (fft.comp). Same sums, same result.
enum class GpuFftForm { Radix2 = 0, Stockham4 = 1 };
inline const std::vector<std::string>& gpu_fft_form_names() {
    static const std::vector<std::string> names = {"radix2", "stockham4"};
    return names;
}
constexpr int kAutoTrialFrames = 3;
constexpr int kMaxDftSize = 64;  // the naive DFT is O(N^4)
constexpr int kMaxCascades = 4;

using ocean::ProgramFactory;

class OceanSimulation {
public:
    explicit OceanSimulation(ProgramFactory programs) : programs_(std::move(programs)) {}

    // Uploads h0 and omega of each cascade (all of the same resolution). Call when the spectrum
    // changes; buffers and textures are re-made when the size or the cascade count changes.
    void set_spectra(const std::vector<const InitialSpectrum*>& cascades);

    // One frame: evolve to `time`, inverse-transform with `backend`, unpack into the textures.
    // The FFTW backend does all of it on the CPU (CpuSimulation), mipmaps included, and uploads
    // the finished textures.
    // With `timers`, each pass is timed on its own (evolve, fft, assemble); without, the caller
    // may time the whole (one "simulation" timer).
    void simulate(double time, Backend backend, float choppiness, ocean::GpuTimers* timers = nullptr);

    // The passes one by one (simulate calls them; tests and the benchmark call them alone).
    void evolve(double time);
    void transform_fft(GLuint source, GLuint target, int layers);  // 2D inverse FFT, in place allowed
    void transform_radix2(GLuint source, GLuint target, int layers);     // the same, GpuFftForm::Radix2
    void transform_stockham4(GLuint source, GLuint target, int layers);  // the same, GpuFftForm::Stockham4
    // Which form transform_fft (and so Backend::GpuFft) uses; Stockham4 unless set.
    void set_gpu_fft_form(GpuFftForm form) { form_ = form; }
    GpuFftForm gpu_fft_form() const { return form_; }
    void transform_dft(GLuint source, GLuint target, int layers);  // N <= 64
    void upload_cpu_fields(double time);                   // FFTW: the fields buffer, as the GPU FFT leaves it
    void assemble(float choppiness);
    void upload_cpu_maps(double time, float choppiness);  // FFTW: the textures, as assemble leaves them

    // Backend::Auto's choice when it has just been made, once, for the log: "at N = 256: FFTW
    // 5.6 ms, GPU FFT 94.8 ms a frame (median of 3): FFTW"; nothing on every other call.
    std::optional<std::string> take_auto_decision() { return std::exchange(auto_decision_, std::nullopt); }
    // Backend::Auto is still timing both backends at this resolution: its frames alternate
    // between them, so they are not the steady state a benchmark should time.
    bool auto_deciding() const { return n_ == 0 || auto_.deciding(); }

    int resolution() const { return n_; }
    int cascade_count() const { return int(cascades_.size()); }
    GLuint spectra_buffer() const { return spectra_.id(); }
    GLuint fields_buffer() const { return fields_.id(); }
    GLuint displacement_texture() const { return displacement_.id(); }  // 2D array, a layer a cascade
    GLuint slopes_texture() const { return slopes_.id(); }
    // The two maps, for what reads them (SimulationMaps::bind); bind_maps(p) is maps().bind(p).
    SimulationMaps maps() const { return {displacement_.id(), slopes_.id()}; }
    void bind_maps(const ocean::ShaderProgram& program) const { maps().bind(program); }
    // This frame's maps as the FFTW backend left them on the CPU (level 0 and mipmaps, layer
    // major), when this frame's came from it; nullptr after a GPU transform (a reader on the CPU
    // then reads the textures back).
    const CpuSimulation* maps_on_cpu() const { return maps_on_cpu_ ? cpu_.get() : nullptr; }
    // The fields of every cascade as 4 packed complex values per texel (tests, export).
    std::vector<float> read_fields() const;
    // One mip level of the displacement (or slopes) texture, every cascade: layer major, RGBA (tests).
    std::vector<float> read_map(bool slopes, int level) const;

private:
    ocean::ShaderProgram& program(const std::string& file, const std::vector<std::string>& defines = {});
    void set_common_uniforms(const ocean::ShaderProgram& p) const;
    void allocate(int n, int cascades);
    void simulate_auto(double time, float choppiness, ocean::GpuTimers* timers);
    CpuSimulation& cpu();  // made (and planned) when first used

    ProgramFactory programs_;
    std::vector<const InitialSpectrum*> cascades_;
    int n_ = 0;
    ocean::Buffer h0_, omega_;
    ocean::Buffer spectra_, fields_;
    ocean::Buffer twiddles_;  // e^{+2 pi i m / N} for fft.comp and fft_radix2.comp
    std::array<ocean::Buffer, 2> radix2_scratch_;  // the radix-2 stages' ping-pong pair, made when first used
    GpuFftForm form_ = GpuFftForm::Stockham4;
    ocean::Texture displacement_, slopes_;
    std::unique_ptr<CpuSimulation> cpu_;  // the FFTW backend, made when first used
    bool maps_on_cpu_ = false;             // the last simulate() was FFTW's
    // Backend::Auto at this resolution (allocate() starts a new one): FFTW is 0, the GPU FFT 1.
    // No margin: both draw the same maps, so the faster by any amount is the one to keep.
    ocean::FasterOfTwo auto_{kAutoTrialFrames};
    std::optional<std::string> auto_decision_;
};

// The same transforms (4 complex N x N fields per cascade) timed with each backend, and the whole
// simulation with each, against the floor: FFTW in single precision (fftwf_plan_many_dft, all
// cores, FFTW_MEASURE) doing the same inverse transforms in this process, the least this work can
// cost on this machine's CPU. Medians of `repeats` runs, wall ms around glFinish.
struct BackendTimes {
    int n = 0, layers = 0, repeats = 0, threads = 0;
    double dft_ms = std::nan(""), gpu_fft_ms = 0;  // no DFT above N = 64; the GPU FFT is Stockham4
    double gpu_radix2_ms = 0;                        // the plain radix-2 form of the same transforms
    double fftw_ms = 0;                              // the floor: the transforms alone, fftwf
    double simulation_fftw_ms = 0, simulation_gpu_fft_ms = 0;  // whole simulate() per backend
    // One line per backend and the ratios to the floor (the panel and --bench print them).
    std::vector<std::string> lines() const;
    // For --bench's machine-readable line.
    std::vector<std::pair<std::string, double>> figures() const {
        return {{"dft_ms", dft_ms}, {"gpu_fft_ms", gpu_fft_ms}, {"gpu_radix2_ms", gpu_radix2_ms}, {"fftw_ms", fftw_ms},
                {"simulation_ms", std::min(simulation_fftw_ms, simulation_gpu_fft_ms)}};
    }
};
BackendTimes time_backends(OceanSimulation& ocean, double time, int repeats);

}  // namespace step05
