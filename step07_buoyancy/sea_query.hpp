// Chapter 7.2: the height of the sea above a world point p. The point drawn above p rests at the
// x that solves
//     x + D(x) = p        (D: the horizontal displacement (l Dx, l Dz) at rest position x)
// and the height there is h(x). Reading h(p) instead is wrong by about the slope times |D|: for a
// steep wave, most of the wave's height (sea_query's tests show it).
//
// Two ways to solve it:
//   fixed point   x <- p - D(x)          each step shrinks the error by |dD/dx| (kA for one
//                                        wave): four steps leave a quarter of it at kA = 0.7;
//   Newton        x <- x - J^-1 (x + D(x) - p),   J = I + dD/dx,
//                                        the derivatives the maps already hold: the error squares
//                                        each step, 1e-4 m in three or four at kA = 0.7.
// det J is the Jacobian the foam reads: where it reaches zero the surface folds, three rest
// points are drawn above p, and no method finds "the" one. There Newton falls back on the fixed
// point (which drifts to one of them) and the answer says it did not converge.
#pragma once

#include "step07_buoyancy/sea_surface.hpp"

#include <vector>

namespace step07 {

enum class Inversion { None, FixedPoint, Newton };

struct SeaPoint {
    glm::dvec2 rest{0.0};      // the x drawn above p
    double height = 0;         // metres above the mean level
    glm::dvec3 normal{0, 1, 0};
    int iterations = 0;        // updates of x
    bool converged = true;     // |x + D(x) - p| below the tolerance
};

struct QueryOptions {
    Inversion method = Inversion::Newton;
    int max_iterations = 8;
    double tolerance = 1e-6;  // metres, horizontally
};

SeaPoint query(const Surface& sea, glm::dvec2 p, const QueryOptions& options = {});

// One Newton step from x towards the rest position drawn above p, given the surface at x; the
// fixed point p - D(x) where det J <= 0.05 (folding). shaders/sea_query.glsl's newton_step is the
// same on the GPU (its exercise is held to this one).
glm::dvec2 newton_step(glm::dvec2 x, glm::dvec2 p, const SurfaceAt& s);

// Many queries at once, on every core (the answers in the points' order).
std::vector<SeaPoint> query_many(const Surface& sea, const std::vector<glm::dvec2>& points, const QueryOptions& options = {});

// The unit normal of the displaced surface at a rest position: dP/dz x dP/dx (ocean_maps.glsl's
// choppy_normal), P(x) = x + D(x).
glm::dvec3 surface_normal(const SurfaceAt& s);

// The water's velocity `depth` metres (>= 0) under the surface point resting at `rest`: how far the
// water there moved between two states of the sea `dt` seconds apart (Surface::displacement_below).
// For a Gerstner wave this is the orbital velocity, A omega e^(-k depth).
glm::dvec3 water_velocity(const Surface& before, const Surface& now, double dt, glm::dvec2 rest,
                          double depth = 0);

}  // namespace step07
