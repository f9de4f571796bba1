// cpu_fft.hpp through FFTW (single precision, threads), the fast form.
#include "step05_fft/cpu_fft.hpp"

#include "common/error.hpp"
#include "common/platform.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <thread>

namespace step05 {

namespace {
// The process's FFTW threads: set up once (fftwf_init_threads), the count used for every plan.
int fftw_thread_count() {
    static const int count = [] {
        const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
        if (fftwf_init_threads() == 0) return 1;
        return cores;
    }();
    return count;
}
}  // namespace

const char* const CpuFft::kName = "FFTW";

CpuFft::CpuFft(int n, int layers, const std::string& wisdom_file) : n_(n), layers_(layers), threads_(fftw_thread_count()) {
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
        const std::string temporary = wisdom_file + "." + std::to_string(ocean::platform::process_id()) + "." +
                                      std::to_string(reinterpret_cast<std::uintptr_t>(this));
        std::error_code ignored;
        if (fftwf_export_wisdom_to_filename(temporary.c_str()) != 0)
            std::filesystem::rename(temporary, wisdom_file, ignored);
        std::filesystem::remove(temporary, ignored);
    }
    std::fill(data_, data_ + values, std::complex<float>(0, 0));  // MEASURE wrote over it
}

CpuFft::~CpuFft() {
    if (plan_ != nullptr) fftwf_destroy_plan(static_cast<fftwf_plan>(plan_));
    fftwf_free(data_);
}

void CpuFft::run() { fftwf_execute(static_cast<fftwf_plan>(plan_)); }

}  // namespace step05
