// figure_data OUT_DIR: the numbers behind the teaching figures (./ocean figures). Each chapter
// makes its own figures with its own code (STEP/figures.cpp), so a figure cannot drift from what
// the step does; this tool asks every chapter for them and writes, for each figure NAME,
// OUT_DIR/FOLDER/NAME.dat (columns of numbers) and NAME.gp (the gnuplot script that draws NAME.png
// from them), FOLDER being where the picture belongs in the repository (figure.hpp).
// ./ocean figures runs gnuplot on the scripts.
// figure_data --timers STEP: the timed passes of a step's pass table, in order, each once: what
// --bench must list (tests/smoke/frame_passes.sh).
#include "step02_sine3d/figures.hpp"
#include "step03_lighting/figures.hpp"
#include "step04_fbm/figures.hpp"
#include "step05_fft/figures.hpp"
#include "step05_fft/frame_passes.hpp"
#include "step06_foam_sky/figures.hpp"
#include "step06_foam_sky/frame_passes.hpp"
#include "step07_buoyancy/figures.hpp"
#include "step08_wakes/figures.hpp"
#include "tools/figure.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

template <class Passes>
int print_timers(const Passes& passes) {
    std::vector<std::string> printed;
    for (const auto& pass : passes)
        if (std::find(printed.begin(), printed.end(), std::string(pass.timer)) == printed.end()) {
            printed.emplace_back(pass.timer);
            std::printf("%s\n", printed.back().c_str());
        }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--timers") {
        if (std::string(argv[2]) == "step05_fft") return print_timers(step05::kFramePasses);
        if (std::string(argv[2]) == "step06_foam_sky") return print_timers(step06::kFramePasses);
        return std::fprintf(stderr, "figure_data: no pass table for %s\n", argv[2]), 2;
    }
    if (argc != 2) return std::fprintf(stderr, "usage: figure_data OUT_DIR | figure_data --timers STEP\n"), 2;
    const std::filesystem::path dir = argv[1];
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) return std::fprintf(stderr, "figure_data: cannot make %s: %s\n", argv[1], error.message().c_str()), 1;
    const std::vector<figures::FigureMakers> chapters{step02::teaching_figures(), step03::teaching_figures(),
                                                      step04::teaching_figures(), step05::teaching_figures(),
                                                      step06::teaching_figures(), step07::teaching_figures(),
                                                      step08::teaching_figures()};
    std::size_t count = 0;
    for (const auto& chapter : chapters)
        for (const auto make : chapter) {
            if (auto failure = make().write(dir)) return std::fprintf(stderr, "figure_data: %s\n", failure->c_str()), 1;
            ++count;
        }
    std::printf("figure_data: %zu figures' data and scripts in %s\n", count, argv[1]);
    return 0;
}
