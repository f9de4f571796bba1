// Two ways of doing the same work, timed by turns on the first frames, and the faster kept: for a
// choice that depends on the machine more than on the code (step05's transforms by FFTW or by the
// GPU FFT, `backend=auto`: on llvmpipe FFTW is 12 times faster; step06's shading as a fragment or
// a compute shader: on llvmpipe the fragment shader is 1.4 times faster, on an H100 the compute
// shader 20 times). The caller times what it ran (wall ms around glFinish, say) and records it.
// Where the two draw slightly different pictures, `margin` keeps the first unless the second is
// that many times faster: a machine's noise (another process, a loaded CI runner) then cannot
// turn the choice, and the same machine always draws the same picture.
#pragma once

#include "common/gpu_timer.hpp"  // median

#include <cstdio>
#include <string>
#include <vector>

namespace ocean {

class FasterOfTwo {
public:
    explicit FasterOfTwo(int trials_each = 3, double margin = 1.0) : trials_each_(trials_each), margin_(margin) {}

    bool deciding() const { return !decided_; }
    // Which to run now: the one tried fewer times (0 first), then the one chosen.
    int next() const {
        if (decided_) return chosen_;
        return ms_[1].size() < ms_[0].size() ? 1 : 0;
    }
    // What `which` took; after `trials_each` of both, the lower median wins, the second only if
    // `margin` times lower (0 on a tie).
    void record(int which, double ms) {
        if (decided_) return;
        ms_[which].push_back(ms);
        if (int(ms_[0].size()) < trials_each_ || int(ms_[1].size()) < trials_each_) return;
        chosen_ = median(ms_[1]) * margin_ < median(ms_[0]) ? 1 : 0;
        decided_ = true;
    }
    int chosen() const { return chosen_; }
    double median_ms(int which) const { return ms_[which].empty() ? 0.0 : median(ms_[which]); }
    // The decision in words, for the log: "FFTW 5.6 ms, GPU FFT 94.8 ms a frame (median of 3): FFTW".
    std::string verdict(const std::string& name0, const std::string& name1) const {
        char text[240];
        std::snprintf(text, sizeof text, "%s %.1f ms, %s %.1f ms a frame (median of %d): %s", name0.c_str(), median_ms(0),
                      name1.c_str(), median_ms(1), trials_each_, (chosen_ == 0 ? name0 : name1).c_str());
        return text;
    }

private:
    int trials_each_;
    double margin_;
    std::vector<double> ms_[2];
    bool decided_ = false;
    int chosen_ = 0;
};

}  // namespace ocean
