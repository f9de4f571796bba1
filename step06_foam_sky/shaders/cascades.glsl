// The four cascades' textures (step05's simulation, one layer each) and what the surface is at a
// rest position p: the sum of the cascades, each sampled at p over its own tile size.
#include "step05_fft/shaders/ocean_maps.glsl"
#include "extra_waves.glsl"

const int CASCADES = 4;
uniform float u_patch_sizes[CASCADES];  // metres
uniform vec2 u_tile_phases[CASCADES];   // each tile's phase at the world origin (cascades.hpp)
uniform bool u_cascade_enabled[CASCADES];

// Rest position p (metres from the world origin near the camera, CascadeView) in cascade c's layer
// (map_uv: with the half-texel offset). The tile's phase at the origin was reduced on the CPU in
// double: p / L stays small and keeps float's precision however far the camera goes.
vec3 cascade_uv(vec2 p, int c) { return vec3(map_uv(p, u_patch_sizes[c]) + u_tile_phases[c], float(c)); }

// (l Dx, h, l Dz, l dDx/dz) summed over the cascades, at mip level `lod` (any stage).
vec4 total_displacement(vec2 p, float lod) {
    vec4 sum = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c)
        if (u_cascade_enabled[c]) sum += textureLod(u_displacement, cascade_uv(p, c), lod);
    return sum;
}

// The mip level of cascade c that averages a footprint of `footprint` metres.
float cascade_lod(int c, float footprint) {
    return max(0.0, log2(footprint * float(textureSize(u_displacement, 0).x) / u_patch_sizes[c]));
}

// (l Dx, h, l Dz, l dDx/dz) summed over the cascades as a sample `footprint` metres wide sees
// them: a vertex of a mesh whose vertices are footprint / 2 apart can carry no wave shorter than
// the footprint (two vertices a wavelength), so each cascade is read at the mip level that
// averages the footprint, and one whose whole tile is under two footprints not at all.
vec4 cascade_displacement_at(int c, vec2 p, float footprint) {
    if (!u_cascade_enabled[c] || footprint >= 0.5 * u_patch_sizes[c]) return vec4(0.0);
    return textureLod(u_displacement, cascade_uv(p, c), cascade_lod(c, footprint));
}
vec4 displacement_at(vec2 p, float footprint) {
    vec4 sum = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c) sum += cascade_displacement_at(c, p, footprint);
#if EXTRA_WAVES
    sum += extra_displacement_at(p);
#endif
    return sum;
}

// The summed surface at p as seen by a sample `footprint` metres wide (compute shaders: foam,
// export): each cascade at the whole mip level nearest that footprint, and none whose tile is
// under two footprints (its mipmapped mean is zero), as the fragment shader does. A whole level,
// not a blend of the two around the footprint: its box is within a factor of 1.4 of the
// footprint either way, and a fetch that lands on a whole level reads one level where a blend
// reads two (a quarter of foam.frag's time on llvmpipe, docs/performance.md). Every texel of a
// foam level has the same footprint, so the level is the same all over it: no seam.
void surface_at(vec2 p, float footprint, out vec4 displacement, out vec4 slopes) {
    displacement = vec4(0.0);
    slopes = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c) {
        if (!u_cascade_enabled[c] || footprint >= 0.5 * u_patch_sizes[c]) continue;
        float lod = floor(cascade_lod(c, footprint) + 0.5);  // nearest, halves up (as the tests' reference)
        displacement += textureLod(u_displacement, cascade_uv(p, c), lod);
        slopes += textureLod(u_slopes, cascade_uv(p, c), lod);
    }
#if EXTRA_WAVES
    displacement += extra_displacement_at(p);
    slopes += extra_slopes_at(p);
#endif
}
