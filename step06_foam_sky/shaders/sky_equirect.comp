#version 450 core
// Fills the cubemap from an equirectangular image (--set sky_image=FILE): longitude along x
// (0 at +x, growing towards +z), latitude along y (top row = straight up).
layout(local_size_x = 8, local_size_y = 8) in;
#include "cube_faces.glsl"

layout(rgba16f, binding = 0) writeonly uniform imageCube u_sky_image;
uniform sampler2D u_equirect;  // linear radiance
uniform int u_size;

const float PI = 3.14159265358979;

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (id.x >= u_size || id.y >= u_size) return;
    vec3 d = cube_direction(id.z, (vec2(id.xy) + 0.5) / float(u_size));
    vec2 uv = vec2(atan(d.z, d.x) / (2.0 * PI) + 0.5, acos(clamp(d.y, -1.0, 1.0)) / PI);
    imageStore(u_sky_image, id, vec4(textureLod(u_equirect, uv, 0.0).rgb, 1.0));
}
