// How the sea is transformed each frame, and what a program offers about it. In the GL 4.5
// profile (transform_choice.cpp) the choice of transform: the `backend` (the notes' naive DFT,
// the GPU FFT, FFTW on the CPU, or auto: the faster of the last two, timed on the first frames)
// and the GPU FFT's form, --bench's table of the backends against FFTW's floor, the warm-up while
// auto decides, the split view of the DFT against the GPU FFT, and the panel's comparison. In the
// portable profile (transform_choice_portable.cpp) there is one transform, the fragment passes',
// and nothing to choose: each call does the one thing there is, so a program's code is the same
// in both profiles.
#pragma once

#include "common/gpu_timer.hpp"
#include "common/params.hpp"
#include "common/split_view.hpp"
#include "step05_fft/sea_simulation.hpp"

#include <string>
#include <utility>
#include <vector>

namespace step05 {

class TransformChoice {
public:
    // Whether this build has transforms to choose between (false in the portable profile: the
    // program then offers no benchmark of them, no warm-up and no split view).
    static const bool kOffered;

    // The `backend` and `fft` parameters (none in the portable profile).
    void declare(ocean::ParamRegistry& p);
    // One frame of `simulation` at `time` through the chosen transform, timed: pass by pass
    // (evolve, fft, assemble) when one backend runs, whole ("simulation") while auto decides or
    // where there is no choice.
    void simulate(SeaSimulation& simulation, double time, float choppiness, ocean::GpuTimers& timers);

    // --bench's figures: every backend on this frame's spectra, printed as `bench:` lines too.
    std::vector<std::pair<std::string, double>> bench_figures(SeaSimulation& simulation, double time) const;
    // While auto still times the two transforms (--bench and --frames wait for it).
    bool warming_up(const SeaSimulation* simulation) const;
    // The naive DFT left, the GPU FFT right; above the DFT's resolution the left is the GPU FFT
    // too, and its label says so. Each side transforms its own maps: update() runs per side.
    ocean::SplitVariants split_variants(int resolution) const;
    // The panel's button that times the backends, and its last table.
    void ui(SeaSimulation& simulation, double time);

private:
    // The choice (none in the portable profile: there they stay unread).
    [[maybe_unused]] int backend_ = 0, fft_form_ = 0;  // Backend and GpuFftForm; declare() sets their defaults
    [[maybe_unused]] bool warned_dft_ = false;
    std::vector<std::string> table_;  // the panel's last comparison
};

}  // namespace step05
