#include "step08_wakes/fft.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace step08 {

Fft2d::Fft2d(int n) : n_(n) {
    if (n < 2 || n > 4096 || (n & (n - 1)) != 0)
        throw ocean::Error("FFT size " + std::to_string(n) + " is not a power of two from 2 to 4096");
    int bits = 0;
    while ((1 << bits) < n) ++bits;
    bit_reversed_.resize(std::size_t(n));
    for (int i = 0; i < n; ++i) {
        int r = 0;
        for (int b = 0; b < bits; ++b) r |= ((i >> b) & 1) << (bits - 1 - b);
        bit_reversed_[std::size_t(i)] = r;
    }
    twiddles_.resize(std::size_t(n / 2));
    for (int j = 0; j < n / 2; ++j) twiddles_[std::size_t(j)] = std::polar(1.0, -ocean::kTwoPi * j / n);
}

void Fft2d::transform_line(Complex* line, std::ptrdiff_t stride, int sign) const {
    auto at = [&](int i) -> Complex& { return line[i * stride]; };
    for (int i = 0; i < n_; ++i) {
        const int r = bit_reversed_[std::size_t(i)];
        if (i < r) std::swap(at(i), at(r));
    }
    // Stage by stage: blocks of `span` samples, each two halves joined by span/2 butterflies.
    for (int span = 2; span <= n_; span *= 2) {
        const int step = n_ / span;  // w_span^j = w_N^(j step)
        for (int start = 0; start < n_; start += span)
            for (int j = 0; j < span / 2; ++j) {
                const Complex w = sign < 0 ? twiddles_[std::size_t(j * step)] : std::conj(twiddles_[std::size_t(j * step)]);
                Complex& even = at(start + j);
                Complex& odd = at(start + j + span / 2);
                const Complex turned = times(w, odd);
                odd = even - turned;
                even += turned;
            }
    }
}

void Fft2d::transform(std::vector<Complex>& field, int sign) const {
    if (field.size() != std::size_t(n_) * std::size_t(n_))
        throw ocean::Error("FFT of " + std::to_string(field.size()) + " samples, not " + std::to_string(n_) + " squared");
    for (int row = 0; row < n_; ++row) transform_line(field.data() + std::ptrdiff_t(row) * n_, 1, sign);
    // Each column copied into a line of its own and back: transformed in place, its samples n
    // apart would each fall on another cache line.
    std::vector<Complex> line(static_cast<std::size_t>(n_));
    for (int column = 0; column < n_; ++column) {
        for (int row = 0; row < n_; ++row) line[std::size_t(row)] = field[std::size_t(row) * std::size_t(n_) + std::size_t(column)];
        transform_line(line.data(), 1, sign);
        for (int row = 0; row < n_; ++row) field[std::size_t(row) * std::size_t(n_) + std::size_t(column)] = line[std::size_t(row)];
    }
}

}  // namespace step08
