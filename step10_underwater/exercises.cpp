// step10_underwater's exercises (./ocean exercise step10_underwater N): Fresnel from below (GLSL,
// held to optics.hpp's reflectance_water_to_air), the depth at which a crest focuses the sun (C++,
// held to lens.cpp's crest_focal_depth, which no page gives: the learner derives it), and the same
// under a slanted sun (lens.cpp's slanted_crest_focal_depth, a variant no page shows). The
// exercise tool (exercises/) gathers every chapter's.
#include "exercises/exercise.hpp"

#include "step10_underwater/exercise_cases.hpp"
#include "step10_underwater/lens.hpp"
#include "step10_underwater/optics.hpp"

#include <glm/vec4.hpp>

#include <cmath>
#include <string>

namespace exercises {

namespace {

std::vector<double> focus_reference(int index) {
    return {step10::crest_focal_depth(step10::case_amplitude(index), step10::case_wavenumber(index))};
}

std::vector<double> slanted_reference(int index) {
    return {step10::slanted_crest_focal_depth(step10::case_amplitude(index), step10::case_wavenumber(index),
                                              step10::case_sun_zenith(index))};
}

// The program ./ocean check builds with the learner's lens.cpp: `call` printed for each case
// (index: the case; exercise_cases.hpp gives its wave and sun).
std::string lens_driver(const std::string& call) {
    return R"(#include "step10_underwater/exercise_cases.hpp"
#include "step10_underwater/lens.hpp"
#include <cstdio>
#include <cstdlib>
using namespace step10;
int main(int argc, char** argv) {
    const int cases = argc > 1 ? std::atoi(argv[1]) : 0;
    for (int index = 0; index < cases; ++index) std::printf("%.17g\n", )" + call + R"();
}
)";
}

std::vector<Exercise> chapter() {
    return {
        {"step10_underwater", 1, "Fresnel from below", "water.glsl", "float fresnel_from_water(float cos_i) {",
         "    // TODO (exercise 1): the share of the light, inside the water, that the surface reflects.\n"
         "    return 0.0;\n",
         "Write fresnel_from_water (water.glsl; README, section 2): light inside the water meets the surface\n"
         "at cos_i, the cosine of its angle from the normal. Return the share R that reflects, for\n"
         "unpolarised light: the mean of the s and p reflectances, from the angles on both sides (Snell's\n"
         "law, WATER_INDEX to 1). Past the critical angle no ray gets out: R is 1. With the starter's 0 the\n"
         "surface seen from below reflects nothing: the mirror around Snell's window goes black.\n"
         "./ocean check compares 2048 angles from straight up to grazing.",
         "Snell gives sin t = n sin i: when that passes 1 the light cannot leave. Otherwise write Fresnel's "
         "two amplitude ratios with n on the water's side, square them, and take their mean.",
         "sin_t2 = n^2 (1 - cos_i^2); R = 1 if sin_t2 >= 1; cos_t = sqrt(1 - sin_t2); "
         "rs = (n cos_i - cos_t) / (n cos_i + cos_t); rp = (cos_i - n cos_t) / (cos_i + n cos_t); R = (rs^2 + rp^2) / 2",
         {},
         [](const fs::path& work) {
             return check_values(
                 work, "water.glsl", "fresnel_from_water(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     return step10::reflectance_water_to_air(std::acos(std::min(a.x, 1.0)));
                 },
                 2e-3, 0, 1);
         }},
        // derived: the README gives the lens formula and leaves the crest's curvature to the learner
        {"step10_underwater", 2, "How deep a crest focuses", "lens.cpp",
         "double crest_focal_depth(double amplitude, double wavenumber) {",
         "    // TODO (exercise 2): metres below the crest of a cos(k x) at which the sun comes to a focus.\n"
         "    (void)amplitude, (void)wavenumber;\n"
         "    return 0;\n",
         "Write crest_focal_depth (C++, in lens.cpp; README, section 4): the sun straight overhead, a sine\n"
         "wave a cos(k x) on the water. Near its top the crest is a lens: find its radius of curvature from\n"
         "a and k, then where a refracting surface of that radius focuses parallel light in water of index\n"
         "kWaterIndex (optics.hpp). ./ocean check compares 300 waves, 1 cm to 1 m high, 0.5 to 200 m long.\n"
         "Then: how deep do 10 m waves 40 cm from trough to crest (a = 20 cm) focus, and why are the\n"
         "sharpest caustics in shallow water made by the shortest waves?",
         "A curve y = h(x) at a point where h' = 0 has radius of curvature 1 / |h''|. The lens formula is "
         "in section 4.",
         "R = 1 / (a k^2); depth = n R / (n - 1)",
         {},
         [](const fs::path& work) {
             return check_cpp(work, "lens.cpp",
                              lens_driver("crest_focal_depth(case_amplitude(index), case_wavenumber(index))"), 300,
                              focus_reference, 1e-12);
         }, kDerived},
        // derived: a variant no page shows; the test against the ray tracing is the learner's to run
        {"step10_underwater", 3, "How deep a low sun focuses", "lens.cpp",
         "double slanted_crest_focal_depth(double amplitude, double wavenumber, double sun_zenith) {",
         "    // TODO (exercise 3): metres below the crest at which a sun sun_zenith from the vertical comes to a focus.\n"
         "    (void)amplitude, (void)wavenumber, (void)sun_zenith;\n"
         "    return 0;\n",
         "Write slanted_crest_focal_depth (C++, in lens.cpp), exercise 2 with the sun sun_zenith radians from\n"
         "the vertical, shining along the wave. The light now meets the crest at an angle and leaves it at\n"
         "another (Snell): a curved refracting surface met obliquely focuses the light that bends in its\n"
         "curved plane at a distance along the refracted ray that an optics text gives (Coddington's\n"
         "equations, the tangential one; Born and Wolf, or Hecht, on astigmatism). The wave's crest is\n"
         "curved only that way, so that is the focal line: return how far below the crest it lies.\n"
         "./ocean check compares 300 waves under suns 0 to 70 degrees from the vertical. Then: at what\n"
         "depth do the caustics of the morning sun (60 degrees from the vertical) lie, for the 2 m waves\n"
         "that focus 8.1 m down at noon? step10's tests trace rays to check the formula (test_optics.cpp).",
         "Snell first: sin t = sin i / n. The tangential focus of parallel light: n cos^2 t / s = (n cos t - cos i) / R, "
         "s measured along the refracted ray, which goes down at t from the vertical.",
         "R = 1 / (a k^2); sin t = sin i / n; s = n R cos^2 t / (n cos t - cos i); depth = s cos t",
         {},
         [](const fs::path& work) {
             return check_cpp(work, "lens.cpp",
                              lens_driver("slanted_crest_focal_depth(case_amplitude(index), case_wavenumber(index), "
                                          "case_sun_zenith(index))"),
                              300, slanted_reference, 1e-12);
         }, kDerived},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
