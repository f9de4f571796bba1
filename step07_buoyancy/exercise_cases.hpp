// The cases exercise 2's check runs (exercises.cpp): a small hull at a random tilt, half in the
// water, with its water lines. Header-only and deterministic, so that the check's program
// (compiled with the learner's hull_forces.cpp) and the reference (in the exercise tool) see the same.
#pragma once

#include "step07_buoyancy/hull_forces.hpp"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace step07 {

struct HullCase {
    std::vector<HullCell> cells;
    glm::dmat3 rotation{1.0};
    glm::dvec3 centre{0.0};
    std::vector<double> water_lines;
};

inline HullCase hull_case(int index) {
    std::uint64_t state = 0x9E3779B97F4A7C15ull * std::uint64_t(index + 1);
    const auto uniform = [&state](double low, double high) {  // splitmix64
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return low + (high - low) * double((z ^ (z >> 31)) >> 11) / 9007199254740992.0;
    };
    HullCase c;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)) + glm::dvec3(0, 0, 1e-6));
    c.rotation = glm::mat3_cast(glm::angleAxis(uniform(0, 1.2), axis));
    c.centre = {uniform(-5, 5), uniform(-0.6, 0.6), uniform(-5, 5)};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 2; ++k) {
                HullCell cell;
                cell.size = {0.5, 0.4, 0.6};
                cell.offset = (glm::dvec3(i, j, k) - glm::dvec3(0.5, 1.0, 0.5)) * cell.size;
                cell.volume = cell.size.x * cell.size.y * cell.size.z;
                c.cells.push_back(cell);
                c.water_lines.push_back(uniform(-0.3, 0.3));  // a rough sea under a small hull
            }
    return c;
}

}  // namespace step07
