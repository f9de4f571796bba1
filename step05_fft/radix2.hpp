// The chapter's own FFT on the CPU: radix 2, in place, for any power-of-two n. It stands in for
// FFTW where a build has none (the Windows cross-build, whose toolchain has no FFTW package); the
// tests hold it to FFTW and to a closed form (tests/test_spectrum.cpp). fft.md derives it.
//
// A transform of length N is two of length N/2 (the even samples and the odd) joined by N/2
// butterflies X[j] = E[j] + w^j O[j], X[j + N/2] = E[j] - w^j O[j], w = e^{+2 pi i / N} for the
// inverse; in place, once the samples are in bit-reversed order.
#pragma once

#include <cmath>
#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

namespace step05 {

template <class Real>
class InverseFft2d {
public:
    explicit InverseFft2d(int n) : n_(n), reversed_(std::size_t(n)), twiddles_(std::size_t(n / 2)) {
        int bits = 0;
        while ((1 << bits) < n) ++bits;
        for (int i = 0; i < n; ++i) {
            int r = 0;
            for (int b = 0; b < bits; ++b) r |= ((i >> b) & 1) << (bits - 1 - b);
            reversed_[std::size_t(i)] = r;
        }
        const double turn = 2 * 3.14159265358979323846 / n;  // twiddles in double, then rounded
        for (int j = 0; j < n / 2; ++j)
            twiddles_[std::size_t(j)] = {Real(std::cos(turn * j)), Real(std::sin(turn * j))};
    }

    // sum_k x[k] e^{+2 pi i j k / n} along `count` lines of n values, `stride` apart within a line
    // and `next` apart from one line to the next: rows (stride 1, next n) or columns (n, 1).
    void lines(std::complex<Real>* data, std::ptrdiff_t stride, std::ptrdiff_t next, int count) const {
        std::vector<std::complex<Real>> line(static_cast<std::size_t>(n_));
        for (int l = 0; l < count; ++l) {
            std::complex<Real>* first = data + l * next;
            for (int i = 0; i < n_; ++i) line[std::size_t(reversed_[std::size_t(i)])] = first[i * stride];
            for (int half = 1; half < n_; half *= 2) {
                const int step = n_ / (2 * half);  // this stage's w^j is twiddles_[j * step]
                for (int block = 0; block < n_; block += 2 * half)
                    for (int j = 0; j < half; ++j) {
                        const std::complex<Real> odd = twiddles_[std::size_t(j * step)] * line[std::size_t(block + j + half)];
                        const std::complex<Real> even = line[std::size_t(block + j)];
                        line[std::size_t(block + j)] = even + odd;
                        line[std::size_t(block + j + half)] = even - odd;
                    }
            }
            for (int i = 0; i < n_; ++i) first[i * stride] = line[std::size_t(i)];
        }
    }

    // The unnormalised inverse 2D transform of one n x n field, row major, in place (what FFTW's
    // FFTW_BACKWARD computes).
    void field(std::complex<Real>* data) const {
        lines(data, 1, n_, n_);   // every row
        lines(data, n_, 1, n_);   // every column
    }

private:
    int n_;
    std::vector<int> reversed_;
    std::vector<std::complex<Real>> twiddles_;
};

}  // namespace step05
