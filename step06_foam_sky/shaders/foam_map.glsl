// Chapter 5.3's foam lives in world space, not in the cascades' tiles: foam must appear where the
// rendered surface folds, and that is the sum of the cascades, whose tiles never line up. So the
// foam is kept in a few square windows that follow the camera (a clipmap, as Crest does): level l
// covers u_foam_extent[l] metres around the camera with N x N texels, each level four times
// coarser than the one before. A window moves in whole texels and is addressed toroidally (cell c
// is texel c mod N), so the foam already made stays where it is in the world when the camera moves.
#include "step06_foam_sky/texture_units.h"
const int FOAM_LEVELS = 3;
layout(binding = UNIT_FOAM) uniform sampler2DArray u_foam;  // a layer per level: (active foam, foam as a whole)
uniform vec2 u_foam_centre[FOAM_LEVELS];    // metres: the middle of each window
uniform float u_foam_extent[FOAM_LEVELS];   // metres: the side of each window
