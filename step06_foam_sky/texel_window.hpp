// A square window of whole texels around a point, moving with it in whole texels: the foam's
// clipmap (foam.hpp) is made of them. Because the window moves by whole texels, a texel always holds the same point of the world:
// what it shows does not swim as the camera moves.
#pragma once

#include <glm/common.hpp>
#include <glm/vec2.hpp>

namespace step06 {

// Where a window lies: its first cell (in texels, from the world origin) and the texel size. Cell
// c covers [c t, (c + 1) t) and its texel holds the value at the centre (c + 0.5) t.
struct TexelWindow {
    glm::ivec2 origin{0};
    double texel_size = 1;
    int n = 0;
    glm::dvec2 centre() const { return (glm::dvec2(origin) + 0.5 * n) * texel_size; }
    glm::dvec2 cell_centre(int i, int j) const {
        return (glm::dvec2(origin + glm::ivec2(i, j)) + 0.5) * texel_size;
    }
    // The cell whose corner is `world_origin` (a multiple of kOriginStep: a whole number of cells).
    glm::ivec2 cell_of(glm::dvec2 world_origin) const {
        return glm::ivec2(glm::round(world_origin / texel_size));
    }
};

// The n x n window of `texel_size` texels around `centre` (x, z).
inline TexelWindow window_around(glm::dvec2 centre, double texel_size, int n) {
    TexelWindow w;
    w.n = n;
    w.texel_size = texel_size;
    w.origin = glm::ivec2(glm::floor(centre / texel_size)) - n / 2;
    return w;
}

}  // namespace step06
