#version 450 core
// Every pixel the surface does not cover, seen from inside the water: the seabed or the water's
// own light. Drawn just in front of the far plane, where the sea's mesh left the depth cleared, so
// that step06's sky (drawn at the far plane behind it) stays out of the water.
#include "underwater_view.glsl"

in vec2 v_uv;
out vec4 out_colour;
uniform mat4 u_inverse_view_projection;  // from the sea's world origin
uniform vec3 u_eye;

void main() {
    vec4 far = u_inverse_view_projection * vec4(v_uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 d = normalize(far.xyz / far.w - u_eye);
    // A ray upwards that missed the mesh (beyond its patches): the surface stands in, far away.
    float reach = d.y > 1e-4 ? max(-u_eye.y, 0.0) / d.y : 1e4;
    out_colour = vec4(u_below_exposure * water_ray(u_eye, d, reach), 1.0);
}
