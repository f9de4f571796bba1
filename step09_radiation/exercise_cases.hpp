// The cases step09's exercises are checked on, written once: exercises.cpp computes the chapter's
// answers on them, and the small program `./ocean check` compiles with the learner's file
// includes this header to compute the learner's on the same cases (each from one seed).
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <random>

namespace step09 {

// Exercise 1's cases: a source under the surface (0.05 to 2 m down), a point of the water near it
// (within 3 m, under the surface), a random unit direction.
struct SourceCase {
    glm::dvec3 x, xi, n;
};
inline SourceCase source_case(int index) {
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

// Exercise 2's cases: a source 0.05 to 2 m down, a point of the surface 0 to 5 m across from the
// point above it.
struct SurfaceCase {
    double across = 0, depth = 0;
};
inline SurfaceCase surface_case(int index) {
    std::mt19937 random(std::uint32_t(4000 + index));
    std::uniform_real_distribution<double> zero_one(0, 1);
    const double across = 5 * zero_one(random);  // drawn first: the order is the cases'
    return {across, 0.05 + 1.95 * zero_one(random)};
}

}  // namespace step09
