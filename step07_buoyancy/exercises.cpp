// step07_buoyancy's exercises (./ocean exercise step07_buoyancy N): the Newton step that finds the
// water drawn above a point (GLSL, held to sea_query.cpp's newton_step), and Archimedes over a
// hull's cells (C++, held to hull_forces.cpp's buoyancy). tools/exercise gathers every chapter's
// (add_step's EXERCISES).
#include "tools/exercise.hpp"

#include "step07_buoyancy/exercise_cases.hpp"
#include "step07_buoyancy/hull_forces.hpp"
#include "step07_buoyancy/sea_query.hpp"

#include <string>

namespace exercises {

namespace {

// The check's surface at x, from the random inputs: the displacement (b.x, 0, b.y), dDx/dz = b.z,
// dDx/dx = b.w, dDz/dz = 0.3 b.z, all within +-0.4 (det J >= 0.37: Newton's branch everywhere).
const char* kSurface = "vec4(b.x, 0.0, b.y, b.z), vec4(0.0, 0.0, b.w, 0.3 * b.z)";

step07::SurfaceAt surface_of(const glm::dvec4& b) {
    step07::SurfaceAt s;
    s.displacement = {b.x, 0.0, b.y};
    s.d_dx = {b.w, 0.0, b.z};        // d/dx of (l Dx, h, l Dz)
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

std::vector<Exercise> chapter() {
    return {
        {"step07_buoyancy", 1, "The water above a point: a Newton step", "sea_query.glsl",
         "vec2 newton_step(vec2 x, vec2 p, vec4 displacement, vec4 slopes) {",
         "    // TODO (exercise 1): move x towards the rest position drawn above p.\n"
         "    return x;\n",
         "Write newton_step: the water resting at x is drawn at x + (l Dx, l Dz) = x + displacement.xz. Find\n"
         "the x drawn above p: with miss = x + displacement.xz - p and J = [1 + l dDx/dx, l dDx/dz; l dDz/dx,\n"
         "1 + l dDz/dz] (slopes.z, displacement.w, slopes.w; J is symmetric), return x - J^-1 miss. Where\n"
         "det J <= 0.05 the surface folds: return the fixed point p - displacement.xz instead. Without it,\n"
         "with queries=2000 and query_device=gpu, the yellow dots float above the troughs and sink into the\n"
         "crests: they are the heights at p, not above p.",
         "The inverse of [a b; b d] is [d -b; -b a] / (a d - b b). Check the sign: the step must reduce the "
         "miss, so x - J^-1 miss, not plus. displacement.w is l dDx/dz, the off-diagonal term.",
         "", {},
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
         "Write buoyancy (C++, in hull_forces.cpp): for each cell, its centre is centre_of_mass + rotation *\n"
         "offset; the share under water is wet_share(water_lines[i], that centre's y, vertical_half_extent(...));\n"
         "it is pushed up by kWaterDensity * ocean::kGravity * share * volume, at the middle of its submerged\n"
         "part (half the wet height above the cell's bottom, on the vertical through its centre). Sum the\n"
         "forces, and the torques (arm x force, the arm from the centre of mass). Without it nothing floats:\n"
         "every body sinks. ./ocean check compiles your file with a small program and compares 200 hulls.",
         "The torque's arm is where the force acts, from the centre of mass: rotation * offset, moved down to "
         "the middle of the wet part (y - half + share * half, not the cell's centre). The force is vertical, "
         "so its torque has no y component. Check a dry cell (share 0) gives nothing and a drowned one "
         "rho_w g V.",
         "", {},
         [](const fs::path& work) {
             return check_cpp(work, "hull_forces.cpp", kBuoyancyDriver, 200, buoyancy_reference, 1e-9);
         }},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
