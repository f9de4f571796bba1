#version 450 core
// A batch of height queries on the GPU, against the maps the sea is drawn from (level 0 of every
// cascade, as the vertices near the camera read them): for each point p, the rest position under
// it by Newton's steps (sea_query.glsl), then the height and the normal there. The answers go back
// to the CPU a frame later (gpu_queries.hpp), 16 bytes a query instead of the maps' megabytes.
layout(local_size_x = 64) in;
#include "step06_foam_sky/shaders/cascades.glsl"
#include "sea_query.glsl"

layout(std430, binding = 0) readonly buffer Points { vec2 points[]; };   // metres from the world origin near the camera
layout(std430, binding = 1) writeonly buffer Answers { vec4 answers[]; };  // (height, normal.x, normal.z, |miss|)
uniform int u_count;
uniform int u_steps;

// Level 0 of a map, bilinear with GL's rule (texel centres at (i + 1/2) / N, repeating), the
// weights in float. GL leaves the precision of its filter's weights to the GPU, and some use 8 bits
// (an H100 does): a picture never shows it, but on a steep wave it moved a query by 3 mm and kept
// Newton's steps from settling within 1 mm. The maps' sides are powers of two, so & wraps (-1 included).
vec4 bilinear(sampler2DArray maps, vec3 uv) {
    ivec2 size = textureSize(maps, 0).xy;
    vec2 t = fract(uv.xy) * vec2(size) - 0.5;
    ivec2 i0 = ivec2(floor(t));
    vec2 f = t - vec2(i0);
    ivec2 i1 = (i0 + 1) & (size - 1);
    i0 &= size - 1;
    int layer = int(uv.z);
    vec4 a = texelFetch(maps, ivec3(i0.x, i0.y, layer), 0), b = texelFetch(maps, ivec3(i1.x, i0.y, layer), 0);
    vec4 c = texelFetch(maps, ivec3(i0.x, i1.y, layer), 0), d = texelFetch(maps, ivec3(i1.x, i1.y, layer), 0);
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

void surface(vec2 x, out vec4 displacement, out vec4 slopes) {
    displacement = vec4(0.0);
    slopes = vec4(0.0);
    for (int c = 0; c < CASCADES; ++c) {
        if (!u_cascade_enabled[c]) continue;
        displacement += bilinear(u_displacement, cascade_uv(x, c));
        slopes += bilinear(u_slopes, cascade_uv(x, c));
    }
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(u_count)) return;
    vec2 p = points[i], x = p;
    vec4 displacement, slopes;
    surface(x, displacement, slopes);
    for (int step = 0; step < u_steps; ++step) {
        x = newton_step(x, p, displacement, slopes);
        surface(x, displacement, slopes);
    }
    vec3 n = choppy_normal(displacement, slopes);
    answers[i] = vec4(displacement.y, n.x, n.z, length(x + displacement.xz - p));
}
