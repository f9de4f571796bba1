#version 450 core
// The background: the sky cubemap along each pixel's view ray (linear HDR, like the sea).
in vec2 v_uv;
out vec4 out_colour;

uniform samplerCube u_sky;
uniform mat4 u_inverse_view_projection;

void main() {
    vec4 far = u_inverse_view_projection * vec4(v_uv * 2.0 - 1.0, 1.0, 1.0);
    vec4 near = u_inverse_view_projection * vec4(v_uv * 2.0 - 1.0, -1.0, 1.0);
    vec3 direction = normalize(far.xyz / far.w - near.xyz / near.w);
    out_colour = vec4(textureLod(u_sky, direction, 0.0).rgb, 1.0);
}
