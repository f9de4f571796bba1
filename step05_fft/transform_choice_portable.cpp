// The portable profile's TransformChoice (transform_choice.hpp): one transform, the fragment
// passes', timed whole; nothing to declare, compare or wait for.
#include "step05_fft/transform_choice.hpp"

namespace step05 {

const bool TransformChoice::kOffered = false;

void TransformChoice::declare(ocean::ParamRegistry& /*p*/) {}

void TransformChoice::simulate(SeaSimulation& simulation, double time, float choppiness, ocean::GpuTimers& timers) {
    ocean::GpuScope timed(timers, "simulation");
    simulation.simulate(time, choppiness);
}

std::vector<std::pair<std::string, double>> TransformChoice::bench_figures(SeaSimulation& /*simulation*/,
                                                                           double /*time*/) const {
    return {};
}

bool TransformChoice::warming_up(const SeaSimulation* /*simulation*/) const { return false; }

ocean::SplitVariants TransformChoice::split_variants(int /*resolution*/) const { return {}; }

void TransformChoice::ui(SeaSimulation& /*simulation*/, double /*time*/) {}

}  // namespace step05
