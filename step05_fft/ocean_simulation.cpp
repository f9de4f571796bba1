#include "step05_fft/ocean_simulation.hpp"

#include "step05_fft/box_mipmaps.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>

namespace step05 {

namespace {
constexpr const char* kShaders = "step05_fft/shaders/";
}

ocean::ShaderProgram& OceanSimulation::program(const std::string& file, const std::vector<std::string>& defines) {
    ocean::ShaderProgram* p = programs_(file, {kShaders + file}, defines);
    if (p == nullptr) throw ocean::Error("shader " + file + " does not build");
    return *p;
}

void OceanSimulation::set_common_uniforms(const ocean::ShaderProgram& p) const {
    p.set("u_n", n_);
    p.set("u_layer_count", cascade_count());
}

void OceanSimulation::allocate(int n, int cascades) {
    const GLsizeiptr modes = GLsizeiptr(n) * n * cascades;
    h0_ = ocean::make_buffer();
    glNamedBufferStorage(h0_.id(), modes * 2 * GLsizeiptr(sizeof(float)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    omega_ = ocean::make_buffer();
    glNamedBufferStorage(omega_.id(), modes * GLsizeiptr(sizeof(double)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    for (ocean::Buffer* b : {&spectra_, &fields_}) {
        *b = ocean::make_buffer();
        glNamedBufferStorage(b->id(), modes * 4 * 2 * GLsizeiptr(sizeof(float)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const int levels = 1 + int(std::floor(std::log2(double(n))));
    for (ocean::Texture* t : {&displacement_, &slopes_}) {
        *t = ocean::make_texture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(t->id(), levels, GL_RGBA32F, n, n, cascades);
        glTextureParameteri(t->id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(t->id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
        glTextureParameteri(t->id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(t->id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    // fft.comp's twiddle factors e^{+2 pi i m / N}, m < N, computed here in double (sin and cos
    // per butterfly in float cost the shader more and are less accurate).
    std::vector<float> twiddles;
    for (int m = 0; m < n; ++m) {
        const double angle = 2 * kPi * m / n;
        twiddles.push_back(float(std::cos(angle)));
        twiddles.push_back(float(std::sin(angle)));
    }
    for (ocean::Buffer& b : radix2_scratch_) b = ocean::Buffer();  // remade at the new size when used
    twiddles_ = ocean::make_buffer();
    glNamedBufferStorage(twiddles_.id(), GLsizeiptr(twiddles.size() * sizeof(float)), twiddles.data(), 0);
    cpu_.reset();  // planned again, for the new size, when first used
    auto_ = ocean::FasterOfTwo(kAutoTrialFrames);  // which backend is faster depends on the size
    n_ = n;
}

void OceanSimulation::set_spectra(const std::vector<const InitialSpectrum*>& cascades) {
    if (cascades.empty() || int(cascades.size()) > kMaxCascades) throw ocean::Error("1 to 4 cascades");
    const int n = cascades.front()->n;
    if (n != n_ || cascades.size() != cascades_.size()) allocate(n, int(cascades.size()));
    cascades_ = cascades;
    if (cpu_) cpu_->set_spectra(cascades);
    std::vector<float> h0;
    std::vector<double> omega;
    for (const InitialSpectrum* s : cascades) {
        for (const Complex& c : s->h0) {
            h0.push_back(float(c.real()));
            h0.push_back(float(c.imag()));
        }
        omega.insert(omega.end(), s->omega.begin(), s->omega.end());
    }
    glNamedBufferSubData(h0_.id(), 0, GLsizeiptr(h0.size() * sizeof(float)), h0.data());
    glNamedBufferSubData(omega_.id(), 0, GLsizeiptr(omega.size() * sizeof(double)), omega.data());
}

void OceanSimulation::evolve(double time) {
    auto& p = program("evolve.comp");
    set_common_uniforms(p);
    glProgramUniform1d(p.id(), p.location("u_time"), time);
    std::vector<float> patch_sizes(kMaxCascades, 1.0f);
    for (std::size_t c = 0; c < cascades_.size(); ++c) patch_sizes[c] = float(cascades_[c]->patch_size);
    p.set("u_patch_size", patch_sizes);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, h0_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, omega_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, spectra_.id());
    glUseProgram(p.id());
    glDispatchCompute(GLuint((n_ + 7) / 8), GLuint((n_ + 7) / 8), GLuint(cascade_count()));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void OceanSimulation::transform_fft(GLuint source, GLuint target, int layers) {
    if (form_ == GpuFftForm::Radix2)
        transform_radix2(source, target, layers);
    else
        transform_stockham4(source, target, layers);
}

void OceanSimulation::transform_radix2(GLuint source, GLuint target, int layers) {
    const GLsizeiptr bytes = GLsizeiptr(n_) * n_ * 4 * cascade_count() * 2 * GLsizeiptr(sizeof(float));
    for (ocean::Buffer& b : radix2_scratch_)
        if (b.id() == 0) {  // allocate() empties them when the size changes
            b = ocean::make_buffer();
            glNamedBufferStorage(b.id(), bytes, nullptr, 0);
        }
    const int stages = int(std::lround(std::log2(double(n_)))), group = std::min(64, n_ / 2);
    auto& p = program("fft_radix2.comp", {"FFT_SIZE " + std::to_string(n_), "GROUP " + std::to_string(group)});
    set_common_uniforms(p);
    glUseProgram(p.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, twiddles_.id());
    for (int axis = 0; axis < 2; ++axis) {  // rows (x) from source to target, then the columns of target
        p.set("u_axis", axis);
        GLuint from = axis == 0 ? source : target;
        for (int stage = 0; stage < stages; ++stage) {
            // Stage 0 reads bit-reversed, so its butterflies would overwrite values others still
            // read; later stages could work in place (a butterfly reads and writes the same two
            // elements), but alternating two scratch buffers keeps every stage alike and the
            // source untouched. The last stage writes the target.
            const GLuint to = stage == stages - 1 ? target : radix2_scratch_[std::size_t(stage % 2)].id();
            p.set("u_stage", stage);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, from);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, to);
            glDispatchCompute(GLuint(n_ / 2 / group), GLuint(n_), GLuint(layers));
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);  // this stage's writes before the next's reads
            from = to;
        }
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void OceanSimulation::transform_stockham4(GLuint source, GLuint target, int layers) {
    // fft.comp's LINES: four lines a workgroup, fewer where their 2 x 4 x N values would not fit
    // GL's minimum of 32 KB of shared memory (N = 1024 and up).
    const int lines = std::clamp(2048 / n_, 1, 4);
    auto& p = program("fft.comp", {"FFT_SIZE " + std::to_string(n_), "LINES " + std::to_string(lines)});
    set_common_uniforms(p);
    glUseProgram(p.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, twiddles_.id());
    for (int axis = 0; axis < 2; ++axis) {  // rows (x) from source to target, then columns in place
        p.set("u_axis", axis);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, axis == 0 ? source : target);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, target);
        glDispatchCompute(GLuint(n_ / lines), GLuint(layers), 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    }
}

void OceanSimulation::transform_dft(GLuint source, GLuint target, int layers) {
    if (n_ > kMaxDftSize)
        throw ocean::Error("the naive DFT is for N <= " + std::to_string(kMaxDftSize) + ", not " +
                           std::to_string(n_));
    auto& p = program("dft.comp");
    set_common_uniforms(p);
    glUseProgram(p.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, source);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, target);
    glDispatchCompute(GLuint((n_ * n_ + 63) / 64), GLuint(layers), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

CpuSimulation& OceanSimulation::cpu() {
    if (!cpu_) {
        cpu_ = std::make_unique<CpuSimulation>(n_, cascade_count(), default_wisdom_file());
        cpu_->set_spectra(cascades_);
    }
    return *cpu_;
}

void OceanSimulation::upload_cpu_fields(double time) {
    cpu().run(time);
    glNamedBufferSubData(fields_.id(), 0, GLsizeiptr(cpu_->float_count() * sizeof(float)), cpu_->fields());
}

void OceanSimulation::upload_cpu_maps(double time, float choppiness) {
    cpu().run(time);
    cpu_->assemble(choppiness);
    const auto& levels = cpu_->levels();
    for (std::size_t level = 0; level < levels.size(); ++level) {
        const int size = levels[level].size;
        glTextureSubImage3D(displacement_.id(), GLint(level), 0, 0, 0, size, size, cascade_count(), GL_RGBA, GL_FLOAT,
                            levels[level].displacement.data());
        glTextureSubImage3D(slopes_.id(), GLint(level), 0, 0, 0, size, size, cascade_count(), GL_RGBA, GL_FLOAT,
                            levels[level].slopes.data());
    }
}

void OceanSimulation::assemble(float choppiness) {
    auto& p = program("assemble.comp");
    set_common_uniforms(p);
    p.set("u_choppiness", choppiness);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, fields_.id());
    glBindImageTexture(0, displacement_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, slopes_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUseProgram(p.id());
    glDispatchCompute(GLuint((n_ + 7) / 8), GLuint((n_ + 7) / 8), GLuint(cascade_count()));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    // Mipmaps let distant water average its waves instead of sparkling. By compute, both maps' 4
    // layers together, three levels a dispatch: glGenerateTextureMipmap was 0.67 of this
    // simulation's 0.73 ms on an H200 (box_mipmaps.hpp).
    make_box_mipmaps(programs_, displacement_.id(), slopes_.id());
}

void OceanSimulation::simulate(double time, Backend backend, float choppiness, ocean::GpuTimers* timers) {
    if (backend == Backend::Auto) {
        simulate_auto(time, choppiness, timers);
        return;
    }
    ocean::GpuTimers untimed;  // disabled: its scopes cost nothing
    ocean::GpuTimers& t = timers != nullptr ? *timers : untimed;
    const int layers = 4 * cascade_count();
    maps_on_cpu_ = backend == Backend::Fftw;
    if (backend == Backend::Fftw) {
        ocean::GpuScope scope(t, "fftw+assemble+upload");
        upload_cpu_maps(time, choppiness);
        return;
    }
    {
        ocean::GpuScope scope(t, "evolve");
        evolve(time);
    }
    {
        ocean::GpuScope scope(t, backend == Backend::Dft ? "dft" : "fft");
        if (backend == Backend::Dft)
            transform_dft(spectra_.id(), fields_.id(), layers);
        else
            transform_fft(spectra_.id(), fields_.id(), layers);
    }
    ocean::GpuScope scope(t, "assemble");
    assemble(choppiness);
}

namespace {

template <class Work>
double median_ms(int repeats, Work work) {
    std::vector<double> ms;
    for (int r = 0; r < repeats; ++r) ms.push_back(ocean::wall_ms_around_finish(work));
    return ocean::median(ms);
}

std::string format_ms(const char* label, double ms) {
    char line[128];
    std::snprintf(line, sizeof line, "%-8s %10.3f ms", label, ms);
    return line;
}

}  // namespace

BackendTimes time_backends(OceanSimulation& ocean, double time, int repeats) {
    BackendTimes t;
    t.n = ocean.resolution();
    t.layers = 4 * ocean.cascade_count();
    t.repeats = repeats;
    ocean.evolve(time);
    t.gpu_fft_ms = median_ms(repeats, [&] { ocean.transform_stockham4(ocean.spectra_buffer(), ocean.fields_buffer(), t.layers); });
    t.gpu_radix2_ms = median_ms(repeats, [&] { ocean.transform_radix2(ocean.spectra_buffer(), ocean.fields_buffer(), t.layers); });
    if (t.n <= kMaxDftSize)
        t.dft_ms = median_ms(repeats, [&] { ocean.transform_dft(ocean.spectra_buffer(), ocean.fields_buffer(), t.layers); });
    // The floor: the same inverse transforms in single precision on all cores, planned with
    // FFTW_MEASURE (remembered in the wisdom file, so only the first run of a size measures).
    CpuSimulation floor(t.n, ocean.cascade_count(), default_wisdom_file());
    t.threads = floor.threads();
    t.fftw_ms = median_ms(repeats, [&] { floor.transform_only(); });
    t.simulation_fftw_ms = median_ms(repeats, [&] { ocean.simulate(time, Backend::Fftw, 1.0f); });
    t.simulation_gpu_fft_ms = median_ms(repeats, [&] { ocean.simulate(time, Backend::GpuFft, 1.0f); });
    ocean.transform_fft(ocean.spectra_buffer(), ocean.fields_buffer(), t.layers);  // leave the frame's result
    return t;
}

void OceanSimulation::simulate_auto(double time, float choppiness, ocean::GpuTimers* timers) {
    const auto backend_of = [](int which) { return which == 0 ? Backend::Fftw : Backend::GpuFft; };
    if (!auto_.deciding()) {
        simulate(time, backend_of(auto_.chosen()), choppiness, timers);
        return;
    }
    const int trial = auto_.next();
    auto_.record(trial, ocean::wall_ms_around_finish([&] { simulate(time, backend_of(trial), choppiness, timers); }));
    if (!auto_.deciding()) auto_decision_ = "at N = " + std::to_string(n_) + ": " + auto_.verdict(CpuFft::kName, "GPU FFT");
}

std::vector<std::string> BackendTimes::lines() const {
    std::vector<std::string> out;
    out.push_back("N = " + std::to_string(n) + ", " + std::to_string(layers) + " complex maps, median of " +
                  std::to_string(repeats) + ", wall ms around glFinish:");
    out.push_back(n <= kMaxDftSize ? format_ms("DFT", dft_ms) : "DFT      (only for N <= 64)");
    out.push_back(format_ms("GPU FFT", gpu_fft_ms) + " (radix 4, Stockham, stages in shared memory)");
    out.push_back(format_ms("radix 2", gpu_radix2_ms) + " (one dispatch a stage, through memory)");
    char line[200];
    if (std::string(CpuFft::kName) == "FFTW")
        std::snprintf(line, sizeof line, "FFTW floor (fftwf, %d threads, FFTW_MEASURE) %10.3f ms", threads, fftw_ms);
    else  // a build without FFTW has no floor: its CPU transform stands in, and says what it is
        std::snprintf(line, sizeof line, "CPU floor (%s: this build has no FFTW, %d threads) %10.3f ms", CpuFft::kName,
                      threads, fftw_ms);
    out.push_back(line);
    if (n <= kMaxDftSize) {
        std::snprintf(line, sizeof line, "DFT / GPU FFT = %.1f", dft_ms / gpu_fft_ms);
        out.push_back(line);
    }
    std::snprintf(line, sizeof line, "GPU FFT kernel = %.1f x the floor; radix 2 = %.1f x the GPU FFT", gpu_fft_ms / fftw_ms,
                  gpu_radix2_ms / gpu_fft_ms);
    out.push_back(line);
    std::snprintf(line, sizeof line, "whole simulation (evolve, transforms, upload, unpack): FFTW backend %.2f ms = %.1f x the floor, "
                  "GPU FFT backend %.2f ms = %.1f x", simulation_fftw_ms, simulation_fftw_ms / fftw_ms, simulation_gpu_fft_ms,
                  simulation_gpu_fft_ms / fftw_ms);
    out.push_back(line);
    return out;
}

std::vector<float> OceanSimulation::read_map(bool slopes, int level) const {
    const int size = std::max(1, n_ >> level);
    std::vector<float> out(std::size_t(size) * std::size_t(size) * 4 * cascades_.size());
    glGetTextureImage(slopes ? slopes_.id() : displacement_.id(), level, GL_RGBA, GL_FLOAT,
                      GLsizei(out.size() * sizeof(float)), out.data());
    return out;
}

std::vector<float> OceanSimulation::read_fields() const {
    std::vector<float> out(std::size_t(n_) * n_ * 4 * 2 * cascades_.size());
    glGetNamedBufferSubData(fields_.id(), 0, GLsizeiptr(out.size() * sizeof(float)), out.data());
    return out;
}

}  // namespace step05
