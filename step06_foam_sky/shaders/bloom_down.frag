#version 450 core
// Bloom, down the chain: each level is half the previous, averaged over 4 bilinear taps (16
// texels). The first pass keeps only what is brighter than the threshold (a soft knee), so only
// the sun, its glint and bright foam bloom.
in vec2 v_uv;
out vec4 out_colour;

uniform sampler2D u_source;
uniform vec2 u_source_texel;  // 1 / source size
uniform bool u_first;
uniform float u_threshold;

void main() {
    vec2 o = 0.5 * u_source_texel;
    vec3 c = 0.25 * (texture(u_source, v_uv + vec2(-o.x, -o.y)).rgb + texture(u_source, v_uv + vec2(o.x, -o.y)).rgb +
                     texture(u_source, v_uv + vec2(-o.x, o.y)).rgb + texture(u_source, v_uv + vec2(o.x, o.y)).rgb);
    if (u_first) {
        float brightness = max(c.r, max(c.g, c.b));
        float knee = 0.5 * u_threshold;
        float soft = clamp(brightness - u_threshold + knee, 0.0, 2.0 * knee);
        soft = soft * soft / (4.0 * knee + 1e-5);
        c *= max(soft, brightness - u_threshold) / max(brightness, 1e-5);
        c = min(c, vec3(64.0));  // one sun texel must not become a huge square
    }
    out_colour = vec4(c, 1.0);
}
