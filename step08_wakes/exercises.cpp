// step08_wakes' exercises (./ocean exercise step08_wakes N): one Fourier mode's exact step (C++, held
// to mode_step.cpp's turn_mode), Kelvin's angle from the group velocity (C++, held to kelvin.cpp's
// kelvin_edge_angle) and a source with its image (C++, held to image_source.cpp's
// source_with_image). The exercise tool (exercises/) gathers every chapter's.
#include "exercises/exercise.hpp"

#include "step08_wakes/image_source.hpp"
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
const char* kKelvinDriver = R"(#include "step08_wakes/image_source.hpp"
#include "step08_wakes/kelvin.hpp"
#include <cstdio>
#include <cstdlib>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index)
        std::printf("%.17g\n", step08::kelvin_edge_angle(0.05 + 1.15 * index / 99.0));
}
)";

// Exercise 3's cases: a source under the surface (0.05 to 2 m down), a point of the water near it
// (within 3 m, under the surface), a random unit direction; all from one seed per case.
struct SourceCase {
    glm::dvec3 x, xi, n;
};
SourceCase source_case(int index) {
    std::mt19937 random(std::uint32_t(3000 + index));
    std::uniform_real_distribution<double> unit(-1, 1), zero_one(0, 1);
    SourceCase c;
    c.xi = {unit(random), -0.05 - 1.95 * zero_one(random), unit(random)};
    c.x = {c.xi.x + 3 * unit(random), -0.01 - 2.99 * zero_one(random), c.xi.z + 3 * unit(random)};
    c.n = {unit(random), unit(random), unit(random)};
    const double length = std::sqrt(c.n.x * c.n.x + c.n.y * c.n.y + c.n.z * c.n.z);
    c.n = length > 1e-3 ? c.n / length : glm::dvec3(0, 1, 0);
    return c;
}
std::vector<double> source_reference(int index) {
    const SourceCase c = source_case(index);
    const step08::SourceAt at = step08::source_with_image(c.x, c.xi, c.n);
    return {at.potential, at.along};
}
const char* kSourceDriver = R"(#include "step08_wakes/image_source.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index) {
        std::mt19937 random(std::uint32_t(3000 + index));
        std::uniform_real_distribution<double> unit(-1, 1), zero_one(0, 1);
        glm::dvec3 xi(unit(random), -0.05 - 1.95 * zero_one(random), unit(random));
        glm::dvec3 x(xi.x + 3 * unit(random), -0.01 - 2.99 * zero_one(random), xi.z + 3 * unit(random));
        glm::dvec3 n(unit(random), unit(random), unit(random));
        const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        n = length > 1e-3 ? n / length : glm::dvec3(0, 1, 0);
        const step08::SourceAt at = step08::source_with_image(x, xi, n);
        std::printf("%.17g %.17g\n", at.potential, at.along);
    }
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
        {"step08_wakes", 2, "Kelvin's angle from the group velocity", "kelvin.cpp",
         "double kelvin_edge_angle(double group_to_phase) {",
         "    // TODO (exercise 2): the wake's half-angle when energy travels at n times the phase speed.\n"
         "    (void)group_to_phase;\n"
         "    return 0;\n",
         "Write kelvin_edge_angle (C++, in kelvin.cpp; section 5): a boat sails at U; the waves it made at\n"
         "P, t seconds ago, that keep pace with it have crests moving at U cos(theta) along theta, and\n"
         "carry their energy at n times that speed (n = c_g / c, the argument: 1/2 in deep water).\n"
         "Where does that energy lie now, for every theta? Find the curve, then the angle from the\n"
         "boat within which every such curve (for every t) is seen. Where none exists (the boat inside\n"
         "the curve), return pi / 2. With n = 1/2 you should find 19.47 degrees, the angle of the\n"
         "program's kelvin_lines (--set plan=true --set kelvin_lines=true). ./ocean check compares n\n"
         "from 0.05 to 1.2.",
         "The energy lies at P + n U t cos(theta) (cos theta, sin theta): a circle through P. Its centre "
         "and radius give the angle of the tangent from the boat, which is U t ahead of P.",
         "sin(alpha) = (n / 2) / (1 - n / 2); alpha = asin of it for n < 1, pi / 2 otherwise",
         {"--set", "kelvin_lines=true"},
         [](const fs::path& work) {
             return check_cpp(work, "kelvin.cpp", kKelvinDriver, 100, kelvin_reference, 1e-12);
         }},
        {"step08_wakes", 3, "A source and its image", "image_source.cpp",
         "SourceAt source_with_image(glm::dvec3 x, glm::dvec3 xi, glm::dvec3 n) {",
         "    // TODO (exercise 3): the potential and the flow along n of a unit source and its image.\n"
         "    (void)x, (void)xi, (void)n;\n"
         "    return {};\n",
         "Write source_with_image (C++, in image_source.cpp; section 4, a hull under the surface): a\n"
         "source at xi under the surface y = 0 (y is up) puts out 1 m^3 of water a second. Its image at\n"
         "(xi.x, -xi.y, xi.z) has the strength kImageStrength (-1: a sink; use the constant, which the\n"
         "README's 'What to try' sets to +1), so that the potential is 0 on the surface, as it is at\n"
         "the instant of a sudden motion. Return the potential of both at the point x (the water's\n"
         "velocity is +grad phi, so a unit source alone gives -1 / (4 pi r)), and their flow along the\n"
         "unit vector n there (value 0 of a case is the potential, value 1 the flow). The hull of\n"
         "sources sums this over its panels: with the starter's zeros it carries no water with it (no\n"
         "added mass). ./ocean check compares 300 random points, sources and directions.",
         "A source's water goes out evenly through every sphere round it: at distance r, 1 / (4 pi r^2) "
         "m/s, pointing away from it, the gradient of -1 / (4 pi r). The image is the same with its own "
         "strength, from its own place: add the two.",
         "d = x - xi, d' = x - (xi.x, -xi.y, xi.z); potential = -1 / (4 pi |d|) - kImageStrength / (4 pi |d'|); "
         "along = n . d / (4 pi |d|^3) + kImageStrength n . d' / (4 pi |d'|^3)",
         {},
         [](const fs::path& work) {
             return check_cpp(work, "image_source.cpp", kSourceDriver, 300, source_reference, 1e-12);
         }},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
