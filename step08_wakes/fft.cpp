#include "step08_wakes/fft.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <algorithm>
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
    for (int direction = 0; direction < 2; ++direction) {
        const double sign = direction == 0 ? -1.0 : 1.0;
        twiddles_[direction].resize(std::size_t(n / 2));
        for (int j = 0; j < n / 2; ++j) twiddles_[direction][std::size_t(j)] = std::polar(1.0, sign * ocean::kTwoPi * j / n);
    }
}

void Fft2d::transform_line(Complex* line, const Complex* w) const {
    for (int i = 0; i < n_; ++i) {
        const int r = bit_reversed_[std::size_t(i)];
        if (i < r) std::swap(line[i], line[r]);
    }
    // Stage by stage: blocks of `span` samples, each two halves joined by span/2 butterflies.
    for (int span = 2; span <= n_; span *= 2) {
        const int step = n_ / span;  // w_span^j = w_N^(j step)
        for (int start = 0; start < n_; start += span)
            for (int j = 0; j < span / 2; ++j) {
                Complex& low = line[start + j];              // Xe[j], then X[j]
                Complex& high = line[start + j + span / 2];  // Xo[j], then X[j + span/2]
                const Complex turned = times(w[j * step], high);
                high = low - turned;
                low += turned;
            }
    }
}

// The columns' transforms, all at once: whole rows swapped into bit-reversed order, then each
// butterfly done for every column, a row against another (its twiddle is the same for all).
void Fft2d::transform_columns(Complex* field, const Complex* w) const {
    const std::size_t n = std::size_t(n_);  // n_, the transform's length, as a size
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t r = std::size_t(bit_reversed_[i]);
        if (i < r) std::swap_ranges(field + i * n, field + (i + 1) * n, field + r * n);
    }
    for (int span = 2; span <= n_; span *= 2) {
        const int step = n_ / span;
        for (int start = 0; start < n_; start += span)
            for (int j = 0; j < span / 2; ++j) {
                // The same butterfly as a line's, for every column at once: row `low` against row `high`.
                Complex* low = field + std::size_t(start + j) * n;
                Complex* high = field + std::size_t(start + j + span / 2) * n;
                const Complex twiddle = w[j * step];
                for (std::size_t column = 0; column < n; ++column) {
                    const Complex turned = times(twiddle, high[column]);
                    high[column] = low[column] - turned;
                    low[column] += turned;
                }
            }
    }
}

void Fft2d::transform(std::vector<Complex>& field, int direction) const {
    if (field.size() != std::size_t(n_) * std::size_t(n_))
        throw ocean::Error("FFT of " + std::to_string(field.size()) + " samples, not " + std::to_string(n_) + " squared");
    const Complex* w = twiddles_[direction].data();
    for (int row = 0; row < n_; ++row) transform_line(field.data() + std::ptrdiff_t(row) * n_, w);
    // The columns: their samples are n apart in memory, each on another cache line. So each
    // butterfly is done for all columns together, a whole row against another, along memory.
    transform_columns(field.data(), w);
}

}  // namespace step08
