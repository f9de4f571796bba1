#version 450 core
// Moves each grid vertex by the simulated displacement (l Dx, h, l Dz). The maps tile: the
// texture coordinate is the rest position over the patch size, and the textures repeat.
#include "ocean_maps.glsl"

layout(location = 0) in vec2 a_rest_xz;

uniform mat4 u_view_projection;
uniform float u_patch_size;

out vec3 v_world_position;
out vec2 v_uv;

void main() {
    v_uv = map_uv(a_rest_xz, u_patch_size);
    vec4 displacement = textureLod(u_displacement, vec3(v_uv, 0.0), 0.0);
    v_world_position = vec3(a_rest_xz.x, 0.0, a_rest_xz.y) + displacement.xyz;
    gl_Position = u_view_projection * vec4(v_world_position, 1.0);
}
