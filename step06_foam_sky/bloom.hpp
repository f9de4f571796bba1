// The bloom chain on the CPU in double precision: PostProcess::bloom's reference (post.cpp,
// bloom_down.frag, bloom_up.frag), texel by texel, with GL's bilinear filter and clamp-to-edge.
//
//   level 0 = above_threshold(tent(scene)), a quarter of the screen each way: 9 bilinear taps two
//             screen pixels apart, weights (1 2 1) x (1 2 1) / 16, a 6 x 6 tent;
//   level k = 13 taps of level k - 1 (Jimenez 2014: five overlapping 4 x 4 boxes), half its size;
//   then from the smallest up, level k - 1 += a 3 x 3 tent of level k.
// Every filter's weights sum to one, so a level's mean is the mean of the one above it (away from
// the edges), and after the way up level 0 holds the glow of every scale.
#pragma once

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace step06 {

struct BloomImage {
    int width = 0, height = 0;
    std::vector<glm::dvec3> texels;  // row by row, from the bottom (GL's order)

    BloomImage(int w, int h) : width(w), height(h), texels(std::size_t(w) * std::size_t(h)) {}
    glm::dvec3& at(int x, int y) { return texels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const glm::dvec3& at(int x, int y) const { return texels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// GL_LINEAR at texture coordinate uv, GL_CLAMP_TO_EDGE: the four texels around uv weighted by
// their distance from it, texel centres at (i + 0.5) / size.
inline glm::dvec3 sample_bilinear(const BloomImage& image, glm::dvec2 uv) {
    const double u = uv.x * image.width - 0.5, v = uv.y * image.height - 0.5;
    const double x0 = std::floor(u), y0 = std::floor(v), fx = u - x0, fy = v - y0;
    const auto texel = [&](double x, double y) {
        return image.at(std::clamp(int(x), 0, image.width - 1), std::clamp(int(y), 0, image.height - 1));
    };
    return (1 - fy) * ((1 - fx) * texel(x0, y0) + fx * texel(x0 + 1, y0)) +
           fy * ((1 - fx) * texel(x0, y0 + 1) + fx * texel(x0 + 1, y0 + 1));
}

// What is brighter than the threshold, with a quadratic knee half the threshold wide on either
// side: nothing below threshold - knee, brightness - threshold above threshold + knee, and between
// them (brightness - threshold + knee)^2 / (4 knee), which meets both with the same slope. Scales
// the colour, so its hue stays; at most 64 a channel (one sun texel must not become a square).
inline glm::dvec3 bloom_above_threshold(glm::dvec3 c, double threshold) {
    const double brightness = std::max(c.r, std::max(c.g, c.b)), knee = 0.5 * threshold;
    double soft = std::clamp(brightness - threshold + knee, 0.0, 2.0 * knee);
    soft = soft * soft / (4.0 * knee + 1e-5);
    c *= std::max(soft, brightness - threshold) / std::max(brightness, 1e-5);
    return glm::min(c, glm::dvec3(64.0));
}

// The sizes PostProcess::resize gives the levels: a quarter of the screen (at least a texel),
// then halves, as many levels as kBloomLevels allows and the quarter's longer side can halve.
inline std::vector<glm::ivec2> bloom_level_sizes(glm::ivec2 screen, int max_levels) {
    const glm::ivec2 quarter = glm::max(screen / 4, glm::ivec2(1));
    const int levels = std::min(max_levels, 1 + int(std::floor(std::log2(double(std::max(quarter.x, quarter.y))))));
    std::vector<glm::ivec2> sizes;
    for (int level = 0; level < levels; ++level) sizes.push_back(glm::max(quarter / (1 << level), glm::ivec2(1)));
    return sizes;
}

// One full-screen pass into a target of `size`: `shade` gets each fragment's v_uv.
template <class Shade>
BloomImage bloom_pass(glm::ivec2 size, const Shade& shade) {
    BloomImage out(size.x, size.y);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) out.at(x, y) = shade(glm::dvec2((x + 0.5) / size.x, (y + 0.5) / size.y));
    return out;
}

inline BloomImage bloom_first_level(const BloomImage& scene, glm::ivec2 size, double threshold) {
    const glm::dvec2 texel(1.0 / scene.width, 1.0 / scene.height);
    return bloom_pass(size, [&](glm::dvec2 uv) {
        const auto tap = [&](double x, double y) { return sample_bilinear(scene, uv + glm::dvec2(x, y) * texel); };
        const glm::dvec3 middle = tap(0, 0), sides = tap(-2, 0) + tap(2, 0) + tap(0, -2) + tap(0, 2),
                         corners = tap(-2, -2) + tap(2, -2) + tap(-2, 2) + tap(2, 2);
        return bloom_above_threshold(0.25 * middle + 0.125 * sides + 0.0625 * corners, threshold);
    });
}

inline BloomImage bloom_down(const BloomImage& source, glm::ivec2 size) {
    const glm::dvec2 texel(1.0 / source.width, 1.0 / source.height);
    return bloom_pass(size, [&](glm::dvec2 uv) {
        const auto tap = [&](double x, double y) { return sample_bilinear(source, uv + glm::dvec2(x, y) * texel); };
        const glm::dvec3 centre = tap(0, 0), inner = tap(-1, -1) + tap(1, -1) + tap(-1, 1) + tap(1, 1),
                         edges = tap(0, -2) + tap(-2, 0) + tap(2, 0) + tap(0, 2),
                         corners = tap(-2, -2) + tap(2, -2) + tap(-2, 2) + tap(2, 2);
        return 0.125 * centre + 0.125 * inner + 0.0625 * edges + 0.03125 * corners;
    });
}

// The 3 x 3 tent of `smaller`, one of its texels apart, added onto `larger`.
inline void bloom_up_add(const BloomImage& smaller, BloomImage& larger) {
    const glm::dvec2 o(1.0 / smaller.width, 1.0 / smaller.height);
    const BloomImage tent = bloom_pass({larger.width, larger.height}, [&](glm::dvec2 uv) {
        const auto tap = [&](double x, double y) { return sample_bilinear(smaller, uv + glm::dvec2(x, y) * o); };
        return (4.0 * tap(0, 0) + 2.0 * (tap(1, 0) + tap(-1, 0) + tap(0, 1) + tap(0, -1)) + tap(1, 1) + tap(-1, -1) +
                tap(1, -1) + tap(-1, 1)) /
               16.0;
    });
    for (std::size_t i = 0; i < larger.texels.size(); ++i) larger.texels[i] += tent.texels[i];
}

// The chain below a given first level (of sizes[0]): down to each of `sizes`, then back up.
inline std::vector<BloomImage> bloom_chain_below(BloomImage first, const std::vector<glm::ivec2>& sizes) {
    std::vector<BloomImage> levels{std::move(first)};
    for (std::size_t k = 1; k < sizes.size(); ++k) levels.push_back(bloom_down(levels[k - 1], sizes[k]));
    for (std::size_t k = levels.size() - 1; k > 0; --k) bloom_up_add(levels[k], levels[k - 1]);
    return levels;
}

// Every level, down then up: levels[0] is what the tonemapper adds to the scene.
inline std::vector<BloomImage> bloom_chain(const BloomImage& scene, double threshold, int max_levels) {
    const std::vector<glm::ivec2> sizes = bloom_level_sizes({scene.width, scene.height}, max_levels);
    return bloom_chain_below(bloom_first_level(scene, sizes[0], threshold), sizes);
}

}  // namespace step06
