// The check of exercises 5 and 6 (exercises.cpp): the learner's FFT stage run inside the chapter's
// whole transform.
#pragma once

#include "exercises/exercise.hpp"
#include "step05_fft/ocean_simulation.hpp"

namespace exercises {

// step05's inverse FFT in `form` with the work folder's shader (fft_radix2.comp or fft.comp), run by
// the chapter's own OceanSimulation (its buffers, twiddle table and dispatches) on random spectra at
// N = 64, 128, 256 and 512 (for Stockham4: radix-4 stages, and a radix-2 stage last where log2 N is
// odd), against the CPU reference transform.
Verdict check_fft(const fs::path& work, step05::GpuFftForm form);

}  // namespace exercises
