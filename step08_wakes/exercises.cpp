// step08_wakes' exercises (./ocean exercise step08_wakes N): one Fourier mode's exact step (C++, held
// to mode_step.cpp's turn_mode) and Kelvin's angle from the group velocity (C++, held to kelvin.cpp's
// kelvin_edge_angle). The exercise tool (exercises/) gathers every chapter's.
#include "exercises/exercise.hpp"

#include "step08_wakes/kelvin.hpp"
#include "step08_wakes/mode_step.hpp"

#include <cmath>
#include <random>
#include <string>

namespace exercises {

namespace {

// Exercise 1's cases: a mode, K (a tenth of them 0, the mean level), dt from 1/240 to 1/2 s, a
// pressure and a source (a third of the cases without each), all from one seed per case.
struct ModeCase {
    step08::Mode mode;
    double K = 0, dt = 0;
    step08::Complex pressure, source;
};
ModeCase mode_case(int index) {
    std::mt19937 random(std::uint32_t(1000 + index));
    std::uniform_real_distribution<double> unit(-1, 1), zero_one(0, 1);
    ModeCase c;
    c.mode = {{unit(random), unit(random)}, {unit(random), unit(random)}};
    c.K = index % 10 == 0 ? 0 : std::exp(std::log(0.01) + zero_one(random) * std::log(1e4));  // 0.01 to 100 rad/m
    c.dt = 1.0 / 240 + zero_one(random) * (0.5 - 1.0 / 240);
    if (index % 3 != 1) c.pressure = {unit(random), unit(random)};
    if (index % 3 != 2) c.source = {0.1 * unit(random), 0.1 * unit(random)};
    return c;
}

std::vector<double> mode_reference(int index) {
    const ModeCase c = mode_case(index);
    const step08::Mode m = step08::turn_mode(c.mode, c.K, c.dt, c.pressure, c.source);
    return {m.eta.real(), m.eta.imag(), m.phi.real(), m.phi.imag()};
}

// The same cases, in the check's program (compiled with the learner's mode_step.cpp).
const char* kModeDriver = R"(#include "step08_wakes/mode_step.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index) {
        std::mt19937 random(std::uint32_t(1000 + index));
        std::uniform_real_distribution<double> unit(-1, 1), zero_one(0, 1);
        step08::Mode mode;
        mode.eta = {unit(random), unit(random)};
        mode.phi = {unit(random), unit(random)};
        const double K = index % 10 == 0 ? 0 : std::exp(std::log(0.01) + zero_one(random) * std::log(1e4));
        const double dt = 1.0 / 240 + zero_one(random) * (0.5 - 1.0 / 240);
        step08::Complex pressure, source;
        if (index % 3 != 1) pressure = {unit(random), unit(random)};
        if (index % 3 != 2) source = {0.1 * unit(random), 0.1 * unit(random)};
        const step08::Mode m = step08::turn_mode(mode, K, dt, pressure, source);
        std::printf("%.17g %.17g %.17g %.17g\n", m.eta.real(), m.eta.imag(), m.phi.real(), m.phi.imag());
    }
}
)";

// Exercise 2's cases: ratios c_g / c from 0.05 to 1.2 (beyond 1: no edge).
double ratio_of(int index) { return 0.05 + 1.15 * index / 99.0; }
std::vector<double> kelvin_reference(int index) { return {step08::kelvin_edge_angle(ratio_of(index))}; }
const char* kKelvinDriver = R"(#include "step08_wakes/kelvin.hpp"
#include <cstdio>
#include <cstdlib>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index)
        std::printf("%.17g\n", step08::kelvin_edge_angle(0.05 + 1.15 * index / 99.0));
}
)";

std::vector<Exercise> chapter() {
    return {
        {"step08_wakes", 1, "One mode's exact step", "mode_step.cpp",
         "Mode turn_mode(Mode mode, double K, double dt, Complex pressure, Complex source) {",
         "    // TODO (exercise 1): turn the mode by omega dt about its constant solution.\n"
         "    (void)K, (void)dt, (void)pressure, (void)source;\n"
         "    return mode;\n",
         "Write turn_mode (C++, in mode_step.cpp; section 2): one Fourier mode of the wave field, its height\n"
         "eta and potential phi, advanced dt seconds under d eta/dt = K phi + s and d phi/dt = -g eta - P,\n"
         "with the pressure P and the source s held constant over the step. First find the constant\n"
         "solution (the one that does not change: set both derivatives to zero). What is left over\n"
         "is a free oscillation: solve it (it turns at omega = sqrt(g K)) and add the constant solution\n"
         "back. K = 0, the mean level, has no oscillation: integrate it directly. Without it the\n"
         "field stands still: no wake, no rings. ./ocean check compiles your file with a small program and\n"
         "compares 300 random modes, time steps from 1/240 to 1/2 s.",
         "Check your step on energy: with P = s = 0, g |eta|^2 + K |phi|^2 must not change. eta's "
         "oscillation has amplitude K / omega times phi's, and phi's g / omega times eta's, with the sign "
         "that makes a raised surface push its potential down. K = 0: eta grows by s dt, phi by "
         "-(g eta + P) dt - g s dt^2 / 2.",
         "omega = sqrt(g K); rest_eta = -P / g, rest_phi = -s / K; e = eta - rest_eta, f = phi - rest_phi; "
         "eta' = rest_eta + e cos(omega dt) + (K / omega) f sin(omega dt); "
         "phi' = rest_phi + f cos(omega dt) - (g / omega) e sin(omega dt)",
         {},
         [](const fs::path& work) { return check_cpp(work, "mode_step.cpp", kModeDriver, 300, mode_reference, 1e-9); }},
        // derived: the README does not give this answer
        {"step08_wakes", 2, "Kelvin's angle from the group velocity", "kelvin.cpp",
         "double kelvin_edge_angle(double group_to_phase) {",
         "    // TODO (exercise 2): the wake's half-angle when energy travels at r times the phase speed.\n"
         "    (void)group_to_phase;\n"
         "    return 0;\n",
         "Write kelvin_edge_angle (C++, in kelvin.cpp; section 3): a boat sails at U; the waves it made at\n"
         "O, t seconds ago, that keep pace with it have crests moving at U cos(theta) along theta, and\n"
         "carry their energy at r times that speed (r = c_g / c, the argument: 1/2 in deep water).\n"
         "Here r is the same for every wave: a model of a dispersive medium, not shallow water (over\n"
         "water h deep r = (1 + 2kh / sinh 2kh) / 2 varies with each wave's k, and the waves made at O\n"
         "no longer share one curve). Where does that energy lie now, for every theta? Find the curve,\n"
         "then the angle from the boat within which every such curve (for every t) is seen. Where none\n"
         "exists (the boat inside the curve), return pi / 2. With r = 1/2 you should find 19.47\n"
         "degrees, the angle of the program's kelvin_lines (--set plan=true --set kelvin_lines=true).\n"
         "./ocean check compares r from 0.05 to 1.2.",
         "The energy lies at O + r U t cos(theta) (cos theta, sin theta): a circle through O. Its centre "
         "and radius give the angle of the tangent from the boat, which is U t ahead of O.",
         "sin(alpha) = (r / 2) / (1 - r / 2); alpha = asin of it for r < 1, pi / 2 otherwise",
         {"--set", "kelvin_lines=true"},
         [](const fs::path& work) {
             return check_cpp(work, "kelvin.cpp", kKelvinDriver, 100, kelvin_reference, 1e-12);
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
