#include "step05_fft/cpu_simulation.hpp"

#include "common/error.hpp"

#include <fftw3.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include <unistd.h>

namespace step05 {

int fftw_thread_count() {
    static const int count = [] {
        const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
        if (fftwf_init_threads() == 0) return 1;
        return cores;
    }();
    return count;
}

std::string default_wisdom_file() {
    std::error_code error;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) return "";
    return (exe.parent_path() / "fftwf.wisdom").string();
}

CpuSimulation::CpuSimulation(int n, int cascades, std::string wisdom_file)
    : n_(n), layers_(4 * cascades), threads_(fftw_thread_count()) {
    const std::size_t values = std::size_t(layers_) * n * n;
    data_ = reinterpret_cast<std::complex<float>*>(fftwf_malloc(values * sizeof(fftwf_complex)));
    if (data_ == nullptr) throw ocean::Error("out of memory for the CPU simulation");
    // Wisdom first: a size measured before plans at once. Another process may write the file at
    // the same moment, so it is written to a private name and renamed (atomic on one file system).
    if (!wisdom_file.empty()) fftwf_import_wisdom_from_filename(wisdom_file.c_str());
    fftwf_plan_with_nthreads(threads_);
    const int size[2] = {n, n};
    auto* data = reinterpret_cast<fftwf_complex*>(data_);
    plan_ = fftwf_plan_many_dft(2, size, layers_, data, nullptr, 1, n * n, data, nullptr, 1, n * n, FFTW_BACKWARD,
                                FFTW_MEASURE);
    if (plan_ == nullptr) throw ocean::Error("FFTW could not plan the CPU simulation");
    if (!wisdom_file.empty()) {
        const std::string temporary = wisdom_file + "." + std::to_string(getpid()) + "." +
                                      std::to_string(reinterpret_cast<std::uintptr_t>(this));
        std::error_code ignored;
        if (fftwf_export_wisdom_to_filename(temporary.c_str()) != 0)
            std::filesystem::rename(temporary, wisdom_file, ignored);
        std::filesystem::remove(temporary, ignored);
    }
    std::fill(data_, data_ + values, std::complex<float>(0, 0));  // MEASURE wrote over it
}

CpuSimulation::~CpuSimulation() {
    if (plan_ != nullptr) fftwf_destroy_plan(static_cast<fftwf_plan>(plan_));
    fftwf_free(data_);
}

void CpuSimulation::set_spectra(const std::vector<const InitialSpectrum*>& cascades) {
    if (int(cascades.size()) * 4 != layers_) throw ocean::Error("CPU simulation: cascade count changed");
    modes_.clear();
    modes_.reserve(std::size_t(layers_ / 4) * n_ * n_);
    for (const InitialSpectrum* s : cascades) {
        if (s->n != n_) throw ocean::Error("CPU simulation: resolution changed");
        for (int j = 0; j < n_; ++j)
            for (int i = 0; i < n_; ++i) {
                const std::size_t index = std::size_t(j) * n_ + i;
                const std::size_t minus = std::size_t((n_ - j) % n_) * n_ + std::size_t((n_ - i) % n_);
                const double kx = wavenumber(i, n_, s->patch_size), kz = wavenumber(j, n_, s->patch_size);
                const double k = std::hypot(kx, kz);
                Mode m;
                m.h0 = std::complex<float>(s->h0[index]);
                m.h0_minus_conj = std::complex<float>(std::conj(s->h0[minus]));
                m.omega = s->omega[index];
                m.ux = k > 0 ? float(kx / k) : 0.0f;
                m.uz = k > 0 ? float(kz / k) : 0.0f;
                m.kx = float(kx);
                m.kz = float(kz);
                if (k == 0) m.h0 = m.h0_minus_conj = 0.0f;  // the mean level: zero
                modes_.push_back(m);
            }
    }
}

void CpuSimulation::evolve_range(double time, std::size_t begin, std::size_t end) {
    const std::size_t area = std::size_t(n_) * n_;
    const double turns_per_radian = 1.0 / (2 * kPi);
    for (std::size_t index = begin; index < end; ++index) {
        const Mode& q = modes_[index];
        const std::size_t c = index / area, m = index - c * area;
        std::complex<float>* f0 = data_ + std::size_t(c * 4) * area;  // h + i Dx
        std::complex<float>* f1 = f0 + area;                         // Dz + i dh/dx
        std::complex<float>* f2 = f1 + area;                         // dh/dz + i dDx/dx
        std::complex<float>* f3 = f2 + area;                         // dDz/dz + i dDx/dz
        // The phase reduced in double (omega t grows without bound: days of clock), the rest in
        // float, as evolve.comp. Whole turns removed by floor: cheaper than fmod, same result.
        const double radians = q.omega * time;
        const float p = float(radians - 2 * kPi * std::floor(radians * turns_per_radian));
        const float cs = std::cos(p), sn = std::sin(p);
        // h = h0 e^{-i phase} + conj(h0(-k)) e^{+i phase}: crests along +k.
        const float hr = q.h0.real() * cs + q.h0.imag() * sn + q.h0_minus_conj.real() * cs - q.h0_minus_conj.imag() * sn;
        const float hi = q.h0.imag() * cs - q.h0.real() * sn + q.h0_minus_conj.imag() * cs + q.h0_minus_conj.real() * sn;
        // i * a * h = (-a hi, a hr); with D = +i k/|k| h and slopes i k h (ocean_maps.cpp's packing).
        const float dxr = -q.ux * hi, dxi = q.ux * hr, dzr = -q.uz * hi, dzi = q.uz * hr;
        const float sxr = -q.kx * hi, sxi = q.kx * hr, szr = -q.kz * hi, szi = q.kz * hr;
        const float dxxr = -q.kx * q.ux * hr, dxxi = -q.kx * q.ux * hi;
        const float dzzr = -q.kz * q.uz * hr, dzzi = -q.kz * q.uz * hi;
        const float dxzr = -q.kx * q.uz * hr, dxzi = -q.kx * q.uz * hi;
        // a + i b for complex a, b: (a.re - b.im, a.im + b.re).
        f0[m] = {hr - dxi, hi + dxr};
        f1[m] = {dzr - sxi, dzi + sxr};
        f2[m] = {szr - dxxi, szi + dxxr};
        f3[m] = {dzzr - dxzi, dzzi + dxzr};
    }
}

void CpuSimulation::run(double time) {
    // Every mode is independent: the modes are split evenly between the cores, as FFTW's threads.
    const std::size_t count = modes_.size(), workers = std::size_t(threads_);
    std::vector<std::thread> helpers;
    for (std::size_t w = 1; w < workers; ++w)
        helpers.emplace_back([this, time, count, workers, w] { evolve_range(time, count * w / workers, count * (w + 1) / workers); });
    evolve_range(time, 0, count / workers);
    for (std::thread& helper : helpers) helper.join();
    fftwf_execute(static_cast<fftwf_plan>(plan_));
}

void CpuSimulation::transform_only() { fftwf_execute(static_cast<fftwf_plan>(plan_)); }

const float* CpuSimulation::fields() const { return reinterpret_cast<const float*>(data_); }

}  // namespace step05
