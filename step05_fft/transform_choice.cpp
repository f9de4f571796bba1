#include "step05_fft/transform_choice.hpp"

#include <imgui.h>

#include <iostream>

namespace step05 {

const bool TransformChoice::kOffered = true;

void TransformChoice::declare(ocean::ParamRegistry& p) {
    backend_ = int(Backend::Auto);
    fft_form_ = int(GpuFftForm::Stockham4);
    p.add_choice("backend", &backend_, backend_names(),
                 "inverse transform: naive DFT on the GPU (N <= 64), GPU FFT, FFTW on the CPU, or auto "
                 "(the faster of the last two, timed on the first frames)");
    p.add_choice("fft", &fft_form_, gpu_fft_form_names(),
                 "the GPU FFT's form: plain radix 2 (a dispatch a stage) or radix 4 in Stockham's order "
                 "(every stage in shared memory); the same result");
}

void TransformChoice::simulate(SeaSimulation& simulation, double time, float choppiness, ocean::GpuTimers& timers) {
    simulation.set_gpu_fft_form(GpuFftForm(fft_form_));
    Backend chosen = Backend(backend_);
    if (chosen == Backend::Dft && simulation.resolution() > kMaxDftSize) {  // O(N^4): the GPU FFT instead
        if (!warned_dft_)
            std::cerr << "warning: the naive DFT is for resolution <= 64; using the GPU FFT at "
                      << simulation.resolution() << "\n";
        warned_dft_ = true;
        chosen = Backend::GpuFft;
    }
    if (chosen == Backend::Auto) {
        // While auto decides, frames alternate the backends, whose passes differ: one figure for
        // the whole simulation.
        ocean::GpuScope timed(timers, "simulation");
        simulation.simulate(time, chosen, choppiness);
    } else {
        simulation.simulate(time, chosen, choppiness, &timers);  // each pass timed
    }
    if (auto decision = simulation.take_auto_decision())
        std::cout << "backend auto " << *decision << std::endl;  // flushed: a log follows the run
}

std::vector<std::pair<std::string, double>> TransformChoice::bench_figures(SeaSimulation& simulation,
                                                                           double time) const {
    const BackendTimes times = time_backends(simulation, time, 9);
    for (const auto& line : times.lines()) std::cout << "bench: " << line << "\n";
    return times.figures();
}

bool TransformChoice::warming_up(const SeaSimulation* simulation) const {
    return Backend(backend_) == Backend::Auto && (simulation == nullptr || simulation->auto_deciding());
}

ocean::SplitVariants TransformChoice::split_variants(int resolution) const {
    const std::string left = resolution > kMaxDftSize
                                 ? "naive DFT (off above " + std::to_string(kMaxDftSize) + ": GPU FFT)"
                                 : "naive DFT";
    ocean::SplitVariants variants{left, "GPU FFT", {"backend=dft"}, {"backend=gpu_fft"}};
    variants.update_each_side = true;
    return variants;
}

void TransformChoice::ui(SeaSimulation& simulation, double time) {
    if (ImGui::Button("compare the backends")) table_ = time_backends(simulation, time, 3).lines();
    for (const auto& line : table_) ImGui::TextUnformatted(line.c_str());
}

}  // namespace step05
