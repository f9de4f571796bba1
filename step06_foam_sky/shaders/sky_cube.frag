#version 450 core
// Renders the procedural sky into one face of a cubemap: Sky::render draws it once a face, into
// that face's framebuffer, a fragment a texel.
#include "sky.glsl"
#include "cube_faces.glsl"

uniform int u_face;  // 0 to 5: +X, -X, +Y, -Y, +Z, -Z
uniform int u_size;  // the face's side, texels

layout(location = 0) out vec4 radiance;

void main() {
    // gl_FragCoord.xy is the texel's centre, (x + 0.5, y + 0.5).
    vec3 direction = cube_direction(u_face, gl_FragCoord.xy / float(u_size));
    radiance = vec4(sky_radiance(direction), 1.0);
}
