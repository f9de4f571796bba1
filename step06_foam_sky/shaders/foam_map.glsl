// Chapter 5.3's foam lives in world space, not in the cascades' tiles: foam must appear where the
// rendered surface folds, and that is the sum of the cascades, whose tiles never line up. So the
// foam is kept in a few square windows that follow the camera (a clipmap, as Crest does): level l
// covers u_foam_extent[l] metres around the camera with N x N texels, each level four times
// coarser than the one before. A window moves in whole texels and is addressed toroidally (cell c
// is texel c mod N), so the foam already made stays where it is in the world when the camera moves.
const int FOAM_LEVELS = 3;
uniform sampler2DArray u_foam;              // one layer per level
uniform vec2 u_foam_centre[FOAM_LEVELS];    // metres: the middle of each window
uniform float u_foam_extent[FOAM_LEVELS];   // metres: the side of each window

// Foam at rest position p: the finest level that holds p, blended into the next one over the
// outer tenth of its window, none beyond the largest window.
float foam_at(vec2 p) {
    float foam = 0.0;
    for (int level = FOAM_LEVELS - 1; level >= 0; --level) {
        vec2 offset = abs(p - u_foam_centre[level]);
        float inside = 0.5 * u_foam_extent[level] - max(offset.x, offset.y);  // metres from the edge
        float weight = clamp(inside / (0.1 * u_foam_extent[level]), 0.0, 1.0);
        // Sampled outside any branch: texture()'s derivatives need uniform control flow.
        float here = texture(u_foam, vec3(p / u_foam_extent[level], float(level))).r;
        foam = mix(foam, here, weight);
    }
    return foam;
}
