// cpu_fft.hpp through the chapter's own radix 2 (radix2.hpp), for a build without FFTW: each pass
// (the rows of every layer, then the columns) shared among the cores in whole lines.
#include "step05_fft/cpu_fft.hpp"
#include "step05_fft/radix2.hpp"

#include <algorithm>
#include <thread>
#include <vector>

namespace step05 {

const char* const CpuFft::kName = "radix 2";  // this build has no FFTW

CpuFft::CpuFft(int n, int layers, const std::string& /*wisdom_file: FFTW's only*/)
    : n_(n), layers_(layers), threads_(int(std::max(1u, std::thread::hardware_concurrency()))) {
    data_ = new std::complex<float>[std::size_t(layers_) * n * n]();
    plan_ = new InverseFft2d<float>(n);
}

CpuFft::~CpuFft() {
    delete static_cast<InverseFft2d<float>*>(plan_);
    delete[] data_;
}

void CpuFft::run() {
    const auto& fft = *static_cast<const InverseFft2d<float>*>(plan_);
    const int lines = layers_ * n_;  // every row of every layer; then every column
    const auto pass = [&](bool columns) {
        std::vector<std::thread> workers;
        for (int t = 0; t < threads_; ++t)
            workers.emplace_back([&, t] {
                // This thread's lines, a layer's run at a time: one call (one scratch line) each.
                for (int line = lines * t / threads_, end = lines * (t + 1) / threads_; line < end;) {
                    std::complex<float>* layer = data_ + std::size_t(line / n_) * n_ * n_;
                    const int first = line % n_, count = std::min(end - line, n_ - first);
                    if (columns) fft.lines(layer + first, n_, 1, count);
                    else fft.lines(layer + std::size_t(first) * n_, 1, n_, count);
                    line += count;
                }
            });
        for (auto& w : workers) w.join();
    };
    pass(false);
    pass(true);
}

}  // namespace step05
