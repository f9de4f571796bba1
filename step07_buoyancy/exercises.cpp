// step07_buoyancy's exercise (./ocean exercise step07_buoyancy 1): the Newton step that finds the
// water drawn above a point, held to sea_query.cpp's newton_step. tools/exercise gathers every
// chapter's (add_step's EXERCISES).
#include "tools/exercise.hpp"

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
         [](const fs::path& work) {
             return check_vector(
                 work, "sea_query.glsl", std::string("vec3(newton_step(a.xy, a.zw, ") + kSurface + "), 0.0)",
                 [](const glm::dvec4& a, const glm::dvec4& b) {
                     const glm::dvec2 x = step07::newton_step({a.x, a.y}, {a.z, a.w}, surface_of(b));
                     return glm::dvec3(x, 0.0);
                 },
                 1e-4, -0.4, 0.4, {}, 2);
         }},
    };
}

const Registration registered(chapter);

}  // namespace

}  // namespace exercises
