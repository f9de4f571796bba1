// The texture units of step06's shading and background passes, named once for C++ and GLSL:
// main.cpp binds each texture to its unit, and each shader's sampler starts on it
// (layout(binding = ...)), so no sampler is left on unit 0 beside the cascades' 2D arrays (GL
// refuses a draw where two sampler types share a unit). Units 0 and 1 hold the cascades' maps
// (step05's OceanSimulation::bind_maps). Plain #defines: the one form both languages read.
#ifndef STEP06_TEXTURE_UNITS_H
#define STEP06_TEXTURE_UNITS_H
#define UNIT_FOAM 3           // the foam clipmap (foam_map.glsl's u_foam): whitecaps and residual foam
#define UNIT_SKY 4            // the sky cubemap (u_sky)
#define UNIT_FOAM_PATTERN 5   // the bubble pattern (u_foam_pattern)
#define UNIT_GBUFFER_WORLD 6  // the G-buffer's surface points (u_gbuffer_world)
#define UNIT_GBUFFER_REST 7   // the G-buffer's rest positions and footprints (u_gbuffer_rest)
#define UNIT_STREAK_LINES 8   // the streaks' line cover (u_streak_lines)
#define UNIT_SKY_HORIZON 9    // the fog's colour around the horizon (sky_horizon.glsl's u_sky_horizon)
#define UNIT_EXTRA_DISPLACEMENT 10  // the extra waves on a grid of their own (extra_waves.glsl): displacement
#define UNIT_EXTRA_SLOPES 11        // and slopes
#endif
