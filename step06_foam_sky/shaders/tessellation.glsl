// Chapter 5.1: how finely to cut an edge of a patch (tessellation.hpp is the CPU formula; sea.md,
// section 2). A segment should cover about the same part of the screen wherever the edge lies, so
// the level (segments per edge) follows the edge's size on screen, within [1, 64] (GL's minimum
// maximum). Two patches that share an edge must compute the same level from it, so no crack
// opens between them.
uniform vec3 u_eye;
uniform float u_tess_patch_size;     // metres
uniform float u_tess_scale;     // how finely to cut: the level scales with it (dimensionless)

float edge_level(vec2 a, vec2 b) {
    vec3 midpoint = vec3(0.5 * (a.x + b.x), 0.0, 0.5 * (a.y + b.y));
    float distance = max(length(midpoint - u_eye), 1e-3);
    return clamp(u_tess_scale * u_tess_patch_size / distance, 1.0, 64.0);
}
