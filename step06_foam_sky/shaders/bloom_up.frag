#version 450 core
// Bloom, up the chain: a 3x3 tent filter of the smaller level, added (blending ONE, ONE) onto
// the larger one, so each level carries the glow of all the levels below it.
in vec2 v_uv;
out vec4 out_colour;

uniform sampler2D u_source;
uniform vec2 u_source_texel;

void main() {
    vec2 o = u_source_texel;
    vec3 c = 4.0 * texture(u_source, v_uv).rgb;
    c += 2.0 * (texture(u_source, v_uv + vec2(o.x, 0.0)).rgb + texture(u_source, v_uv - vec2(o.x, 0.0)).rgb +
                texture(u_source, v_uv + vec2(0.0, o.y)).rgb + texture(u_source, v_uv - vec2(0.0, o.y)).rgb);
    c += texture(u_source, v_uv + o).rgb + texture(u_source, v_uv - o).rgb +
         texture(u_source, v_uv + vec2(o.x, -o.y)).rgb + texture(u_source, v_uv + vec2(-o.x, o.y)).rgb;
    out_colour = vec4(c / 16.0, 1.0);
}
