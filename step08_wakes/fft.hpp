// Chapter 8's FFT page (fft.md): the fast Fourier transform the wave field runs on, in double precision on the CPU.
// step05 uses the FFT (on the GPU, FFTW as its reference and fallback); here it is written out: the
// wave field around the boat is small (128 x 128) and its bodies need it on the CPU in the same
// step (fft.md: why the field is on the CPU).
//
// Radix 2, in place (Cooley and Tukey): a transform of length N is two of length N/2, one over
// the even samples and one over the odd, joined by N/2 "butterflies"
//     X[j]       = Xe[j] + w^j Xo[j]
//     X[j + N/2] = Xe[j] - w^j Xo[j],     w = e^{-2 pi i / N} (forward), e^{+2 pi i / N} (inverse)
// log2 N times over: N log2 N work in place of the direct sum's N^2. The samples are first put in
// bit-reversed order: then each block of the stage's length holds, in its two halves, the two
// shorter transforms that the stage joins.
#pragma once

#include "step08_wakes/mode_step.hpp"

#include <vector>

namespace step08 {

class Fft2d {
public:
    // `n`: a power of two from 2 to 4096 (anything else throws ocean::Error).
    explicit Fft2d(int n);
    int size() const { return n_; }
    // In place, on n x n samples, row (z) major. Forward: X[k] = sum_x x[x] e^{-2 pi i k x / N}
    // on each axis; inverse: the same with e^{+...}, unnormalised (inverse(forward(x)) = N^2 x).
    void forward(std::vector<Complex>& field) const { transform(field, 0); }
    void inverse(std::vector<Complex>& field) const { transform(field, 1); }

private:
    void transform(std::vector<Complex>& field, int direction) const;
    void transform_line(Complex* line, const Complex* twiddles) const;
    void transform_columns(Complex* field, const Complex* twiddles) const;

    int n_;
    std::vector<int> bit_reversed_;
    std::vector<Complex> twiddles_[2];  // e^{-2 pi i j / N} (forward) and e^{+2 pi i j / N} (inverse), j < N/2
};

}  // namespace step08
