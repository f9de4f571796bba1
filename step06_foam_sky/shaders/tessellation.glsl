// Chapter 5.1: how finely to cut an edge of a patch (tessellation.hpp is the CPU formula). A
// segment should cover about the same part of the screen wherever the edge lies, and an edge's
// size on screen falls as 1 / distance: so the level (segments per edge) is
//     level = u_tess_scale * u_tess_patch_size / distance,  clamped to [1, 64] (GL's minimum maximum)
// with the distance from the eye to the edge's midpoint. Two patches that share an edge compute
// the same level from the same two corners, so no crack opens between them.
uniform vec3 u_eye;
uniform float u_tess_patch_size;     // metres
uniform float u_tess_scale;     // level = scale * patch_size / distance

float edge_level(vec2 a, vec2 b) {
    vec3 midpoint = vec3(0.5 * (a.x + b.x), 0.0, 0.5 * (a.y + b.y));
    float distance = max(length(midpoint - u_eye), 1e-3);
    return clamp(u_tess_scale * u_tess_patch_size / distance, 1.0, 64.0);
}
