// step09_radiation's exercises (./ocean exercise step09_radiation N): a source with its image (C++,
// held to image_source.cpp's source_with_image) and the water they put through the surface (C++,
// held to image_source.cpp's flow_through_surface, which no page gives: the learner derives it). The
// exercise tool (exercises/) gathers every chapter's.
#include "exercises/exercise.hpp"

#include "step09_radiation/exercise_cases.hpp"
#include "step09_radiation/image_source.hpp"

#include <string>

namespace exercises {

namespace {

// The cases (exercise_cases.hpp), the chapter's answers on them, and the program that prints the
// learner's on the same cases.
std::vector<double> source_reference(int index) {
    const step09::SourceCase c = step09::source_case(index);
    const step09::SourceAt at = step09::source_with_image(c.x, c.xi, c.n);
    return {at.potential, at.along};
}
const char* kSourceDriver = R"(#include "step09_radiation/exercise_cases.hpp"
#include "step09_radiation/image_source.hpp"
#include <cstdio>
#include <cstdlib>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index) {
        const step09::SourceCase c = step09::source_case(index);
        const step09::SourceAt at = step09::source_with_image(c.x, c.xi, c.n);
        std::printf("%.17g %.17g\n", at.potential, at.along);
    }
}
)";

std::vector<double> surface_reference(int index) {
    const step09::SurfaceCase c = step09::surface_case(index);
    return {step09::flow_through_surface(c.across, c.depth)};
}
const char* kSurfaceDriver = R"(#include "step09_radiation/exercise_cases.hpp"
#include "step09_radiation/image_source.hpp"
#include <cstdio>
#include <cstdlib>
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index) {
        const step09::SurfaceCase c = step09::surface_case(index);
        std::printf("%.17g\n", step09::flow_through_surface(c.across, c.depth));
    }
}
)";

std::vector<Exercise> chapter() {
    return {
        {"step09_radiation", 1, "A source and its image", "image_source.cpp",
         "SourceAt source_with_image(glm::dvec3 x, glm::dvec3 xi, glm::dvec3 n) {",
         "    // TODO (exercise 1): the potential and the flow along n of a unit source and its image.\n"
         "    (void)x, (void)xi, (void)n;\n"
         "    return {};\n",
         "Write source_with_image (C++, in image_source.cpp; the primer, a source and its image): a\n"
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
        // derived: the README does not give this answer
        {"step09_radiation", 2, "The water a source puts through the surface", "image_source.cpp",
         "double flow_through_surface(double across, double depth) {",
         "    // TODO (exercise 2): the upward speed of the water through y = 0 from a unit source and its image.\n"
         "    (void)across, (void)depth;\n"
         "    return 0;\n",
         "Write flow_through_surface (C++, in image_source.cpp; the primer's method, a variant it does not\n"
         "work out): a unit source `depth` metres under the surface, with its image (kImageStrength, from\n"
         "the same file). How fast does the water go up through the surface y = 0 at a point `across`\n"
         "metres from the point straight above the source? This is the water the sources put through\n"
         "each cell; the code gets the same water mode by mode (README, section 11). Derive it from the\n"
         "potential of exercise 1, then check it: over the whole surface, how much water goes through,\n"
         "for the sink image, and for a rigid lid (kImageStrength = +1)? ./ocean check compares 300\n"
         "points, 0.05 to 2 m deep, 0 to 5 m across.",
         "Differentiate the potential of both in y and set y = 0: the source and its image are the same "
         "distance away, so their two terms have one form. The sink image's whole surface should carry "
         "the source's 1 m^3/s; the rigid lid's none.",
         "r = sqrt(across^2 + depth^2); flow = (1 - kImageStrength) depth / (4 pi r^3)",
         {},
         [](const fs::path& work) {
             return check_cpp(work, "image_source.cpp", kSurfaceDriver, 300, surface_reference, 1e-12);
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
