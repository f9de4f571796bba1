#version 450 core
// Fills one face of the sky's cubemap from an equirectangular image (--set sky_image=FILE):
// longitude along x (0 at +x, growing towards +z), latitude along y (top row = straight up).
#include "cube_faces.glsl"

uniform sampler2D u_equirect;  // linear radiance
uniform int u_face;            // 0 to 5: +X, -X, +Y, -Y, +Z, -Z
uniform int u_size;

layout(location = 0) out vec4 radiance;

const float PI = 3.14159265358979;

void main() {
    vec3 d = cube_direction(u_face, gl_FragCoord.xy / float(u_size));
    vec2 uv = vec2(atan(d.z, d.x) / (2.0 * PI) + 0.5, acos(clamp(d.y, -1.0, 1.0)) / PI);
    radiance = vec4(textureLod(u_equirect, uv, 0.0).rgb, 1.0);
}
