// A small, portable generator (splitmix64): the same seed gives the same numbers on every machine,
// which std::uniform_real_distribution does not promise. step04 seeds its waves' directions with
// it, step06 its foam pattern.
#pragma once

#include <cstdint>

namespace ocean {

// The next number in [0, 1) from `state`, which it advances.
inline double uniform01(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return double(z >> 11) * (1.0 / 9007199254740992.0);  // 53 bits -> [0, 1)
}

}  // namespace ocean
