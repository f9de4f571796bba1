#version 450 core
// Renders the procedural sky into the six faces of a cubemap.
layout(local_size_x = 8, local_size_y = 8) in;
#include "sky.glsl"
#include "cube_faces.glsl"

layout(rgba16f, binding = 0) writeonly uniform imageCube u_sky_image;
uniform int u_size;

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);  // z: the face
    if (id.x >= u_size || id.y >= u_size) return;
    vec3 direction = cube_direction(id.z, (vec2(id.xy) + 0.5) / float(u_size));
    imageStore(u_sky_image, id, vec4(sky_radiance(direction), 1.0));
}
