// step07_buoyancy's exercises (./ocean exercise step07_buoyancy N): the Newton step that finds the
// water drawn above a point (GLSL, held to sea_query.cpp's newton_step), Archimedes over a hull's
// cells (C++, held to hull_forces.cpp's buoyancy), and a sphere's heave period (C++, held to
// hull_forces.cpp's sphere_heave_period). The exercise tool (exercises/) gathers every chapter's
// (add_step's EXERCISES).
#include "exercises/exercise.hpp"

#include "step07_buoyancy/exercise_cases.hpp"
#include "step07_buoyancy/hull_forces.hpp"
#include "step07_buoyancy/sea_query.hpp"

#include <random>
#include <string>

namespace exercises {

namespace {

// The check's surface at x, from the random inputs: the displacement (b.x, 0, b.y), dDx/dz = b.z,
// dDx/dx = b.w, dDz/dz = 0.3 b.z, all within +-0.4 (det J >= 0.37: Newton's branch everywhere).
const char* kSurface = "vec4(b.x, 0.0, b.y, b.z), vec4(0.0, 0.0, b.w, 0.3 * b.z)";

step07::SurfaceAt surface_of(const glm::dvec4& b) {
    step07::SurfaceAt s;
    s.displacement = {b.x, 0.0, b.y};
    s.d_dx = {b.w, 0.0, b.z};        // d/dx of (lambda chi_x, eta, lambda chi_z)
    s.d_dz = {b.z, 0.0, 0.3 * b.z};  // d/dz
    return s;
}

// Exercise 2's check: compiled with the learner's hull_forces.cpp, it prints the force and torque
// of each case (exercise_cases.hpp).
const char* kBuoyancyDriver = R"(#include "step07_buoyancy/exercise_cases.hpp"
#include <cstdio>
#include <cstdlib>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int i = 0; i < cases; ++i) {
        const step07::HullCase c = step07::hull_case(i);
        const step07::Wrench w = step07::buoyancy(c.cells, c.rotation, c.centre, c.water_lines);
        std::printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", w.force.x, w.force.y, w.force.z, w.torque.x, w.torque.y, w.torque.z);
    }
}
)";

std::vector<double> buoyancy_reference(int index) {
    const step07::HullCase c = step07::hull_case(index);
    const step07::Wrench w = step07::buoyancy(c.cells, c.rotation, c.centre, c.water_lines);
    return {w.force.x, w.force.y, w.force.z, w.torque.x, w.torque.y, w.torque.z};
}

// Exercise 3's cases: a sphere of radius 0.2 to 3 m floating at a draft of 0.05 to 1.9 radii, with a
// drag from 0 to 0.6/s (underdamped everywhere: the weakest spring, at 1.9 radii on a 3 m sphere,
// is 0.47/s^2 against at most 0.09), all from one seed per case.
struct HeaveCase {
    double radius = 0, draft = 0, drag = 0;
};
HeaveCase heave_case(int index) {
    std::mt19937 random(std::uint32_t(7000 + index));
    std::uniform_real_distribution<double> zero_one(0, 1);
    HeaveCase c;
    c.radius = 0.2 + 2.8 * zero_one(random);
    c.draft = c.radius * (0.05 + 1.85 * zero_one(random));
    c.drag = 0.6 * zero_one(random);
    return c;
}
std::vector<double> heave_reference(int index) {
    const HeaveCase c = heave_case(index);
    return {step07::sphere_heave_period(c.radius, c.draft, c.drag)};
}
const char* kHeaveDriver = R"(#include "step07_buoyancy/hull_forces.hpp"
#include <cstdio>
#include <cstdlib>
#include <random>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index) {
        std::mt19937 random(std::uint32_t(7000 + index));
        std::uniform_real_distribution<double> zero_one(0, 1);
        const double radius = 0.2 + 2.8 * zero_one(random);
        const double draft = radius * (0.05 + 1.85 * zero_one(random));
        const double drag = 0.6 * zero_one(random);
        std::printf("%.17g\n", step07::sphere_heave_period(radius, draft, drag));
    }
}
)";

std::vector<Exercise> chapter() {
    return {
        {"step07_buoyancy", 1, "The water above a point: a Newton step", "sea_query.glsl",
         "vec2 newton_step(vec2 x, vec2 p, vec4 displacement, vec4 slopes) {",
         "    // TODO (exercise 1): move x towards the rest position drawn above p.\n"
         "    return x;\n",
         "Write newton_step (section 2): the water resting at x is drawn at x + displacement.xz (x + lambda chi(x)).\n"
         "The water drawn above the world point p rests at a root of F(x) = x + lambda chi(x) - p. Newton's method\n"
         "replaces F near x by its tangent, F(x + dx) ~ F(x) + J dx, with J the 2 x 2 matrix of F's\n"
         "derivatives, and takes the dx that zeroes it. Build J from what the maps hold (slopes.z = lambda dchi_x/dx,\n"
         "slopes.w = lambda dchi_z/dz, displacement.w = lambda dchi_x/dz = lambda dchi_z/dx), solve the 2 x 2 system, and return the\n"
         "new x. Where det J <= 0.05 the surface folds and the step means nothing: return the fixed point\n"
         "p - displacement.xz instead. The step runs with 2000 queries on the GPU (queries=2000,\n"
         "query_device=gpu): with the starter the yellow dots are the heights at p, not above p: they float\n"
         "above the wave flanks, by up to 2/3 A on a steep wave, and touch the water at crests and troughs.",
         "The step must shrink the miss x + displacement.xz - p: subtract J^-1 miss, do not add it. J's diagonal "
         "starts at 1 (the x of x + lambda chi), and displacement.w is the off-diagonal term on both sides.",
         "miss = x + displacement.xz - p; J = [a b; b d], a = 1 + slopes.z, b = displacement.w, d = 1 + slopes.w; "
         "det = a d - b^2; if det <= 0.05 return p - displacement.xz; "
         "else return x - vec2(d miss.x - b miss.y, -b miss.x + a miss.y) / det",
         {"--set", "queries=2000", "--set", "query_device=gpu"},
         [](const fs::path& work) {
             return check_vector(
                 work, "sea_query.glsl", std::string("vec3(newton_step(a.xy, a.zw, ") + kSurface + "), 0.0)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     const glm::dvec2 x = step07::newton_step({a.x, a.y}, {a.z, a.w}, surface_of(b));
                     return glm::dvec3(x, 0.0);
                 },
                 1e-4, -0.4, 0.4, {}, 2);
         }},
        {"step07_buoyancy", 2, "Archimedes over a hull: force and torque", "hull_forces.cpp",
         "Wrench buoyancy(const std::vector<HullCell>& cells, const glm::dmat3& rotation, glm::dvec3 centre_of_mass,",
         "                const std::vector<double>& water_lines) {\n"
         "    // TODO (exercise 2): the water's push on every cell, and its torque about the centre of mass.\n"
         "    (void)cells, (void)rotation, (void)centre_of_mass, (void)water_lines;\n"
         "    return {};\n",
         "Write buoyancy (C++, in hull_forces.cpp; section 7): the water's push on a hull made of cells, and\n"
         "its torque about the centre of mass. Archimedes: a cell is pushed up by the weight of the water it\n"
         "displaces, the share of it under water (wet_share, from its centre's height, water_lines[i] and\n"
         "vertical_half_extent) times its volume. The push acts at the middle of the displaced water: find\n"
         "where each cell's wet part lies (the cell's centre is centre_of_mass + rotation * offset, and the\n"
         "wet part starts at its bottom), then sum the forces and their torques about the centre of mass.\n"
         "Without it the raft and the boat sink (the buoy floats on its cap). ./ocean check compiles your file\n"
         "with a small program and compares 200 hulls.",
         "The torque's arm runs from the centre of mass to the middle of the wet part, or to the cell's centre: "
         "either point gives the same torque under a vertical force; the low side's wetter cells right a "
         "heeled hull. A dry cell gives nothing, a drowned one "
         "rho_w g V; the force is vertical, so its torque has no y component.",
         "for each cell i: arm = rotation * offset, half = vertical_half_extent(rotation, cell), "
         "wet = wet_share(water_lines[i], centre_of_mass.y + arm.y, half); "
         "force = (0, kWaterDensity * ocean::kGravity * wet * volume, 0), acting at "
         "at = arm + (0, -half + wet * half, 0) (the wet part's middle); total.force += force; "
         "total.torque += cross(at, force)",
         {},
         [](const fs::path& work) {
             return check_cpp(work, "hull_forces.cpp", kBuoyancyDriver, 200, buoyancy_reference, 1e-9);
         }},
        // derived: the lesson linearises Archimedes for a box only; the sphere's spring comes from its cap
        {"step07_buoyancy", 3, "A sphere's heave period", "hull_forces.cpp",
         "double sphere_heave_period(double radius, double draft, double linear_drag) {",
         "    // TODO (exercise 3): the period of the sphere's small heave about its rest.\n"
         "    (void)radius, (void)draft, (void)linear_drag;\n"
         "    return 0;\n",
         "Write sphere_heave_period (C++, in hull_forces.cpp; motion.md, section 10): the program's buoy is a sphere\n"
         "of this radius, floating at rest with the water `draft` above its lowest point. Raised a little\n"
         "and let go on still water, it heaves up and down. Section 10 finds a box's heave period: it\n"
         "writes Newton's law for the height above the rest, with Archimedes' push, the weight and the\n"
         "drag (per kilogram of water displaced, linear_drag, which at rest is the body's mass), and\n"
         "keeps the terms of first order in the height. Do the same for the sphere, with its spherical\n"
         "cap (spherical_cap_volume): how much more water does it displace when it sinks a little\n"
         "further? Return the period in seconds of the damped oscillation (infinity if the drag leaves\n"
         "none). ./ocean check compiles your file with a small program and compares 200 spheres, radius\n"
         "0.2 to 3 m, drafts from 0.05 to 1.9 radii; tests/test_floating_body.cpp holds the program's\n"
         "own buoy, raised 2 cm, to your formula.",
         "g / d is the box's: its water line cuts the same area at every draft, so its volume is that area "
         "times d. A sphere's spring is rho_w g times the area its water line cuts at this draft, its mass "
         "rho_w times its cap's volume, and the drag still takes c^2 / 4 off omega^2.",
         "S = pi d (2 r - d) (the disc at the water line, dV/dd), V = pi d^2 (3 r - d) / 3; "
         "omega^2 = g S / V - c^2 / 4 = 3 g (2 r - d) / (d (3 r - d)) - c^2 / 4; "
         "period = 2 pi / sqrt(omega^2), infinity if omega^2 <= 0",
         {},
         [](const fs::path& work) {
             return check_cpp(work, "hull_forces.cpp", kHeaveDriver, 200, heave_reference, 1e-9);
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
