#version 450 core
// The template's picture: x across the screen, the wave's height as colour (deep blue in the
// troughs, pale at the crests). chapter.hpp is the CPU reference.
in vec2 v_uv;
out vec4 out_colour;

uniform float u_wavenumber;  // w = 2 pi / wavelength, radians per metre
uniform float u_amplitude;   // metres
uniform float u_phase;       // -w c t mod 2 pi, reduced on the CPU in double precision
uniform float u_x_span;      // metres across the screen

void main() {
    float x = v_uv.x * u_x_span;
    float h = u_amplitude * sin(u_wavenumber * x + u_phase);
    float t = u_amplitude > 0.0 ? 0.5 + 0.5 * h / u_amplitude : 0.5;
    vec3 colour = mix(vec3(0.02, 0.08, 0.2), vec3(0.6, 0.8, 0.9), t);
    out_colour = vec4(colour * (0.6 + 0.4 * v_uv.y), 1.0);
}
