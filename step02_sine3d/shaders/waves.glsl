// Chapter 1.2.2's sum of directional sines (waves.hpp is the CPU reference). Each wave arrives
// as (d.x, d.z, w, a) plus its phase -t * phi, reduced modulo 2 pi on the CPU in double precision: crests travel
// along +d.
const int MAX_WAVES = 16;

uniform int u_wave_count;
uniform vec4 u_waves[MAX_WAVES];
uniform float u_wave_phases[MAX_WAVES];

float wave_height(vec2 xz) {
    float height = 0.0;
    for (int i = 0; i < u_wave_count; ++i) {
        vec4 wave = u_waves[i];
        height += wave.w * sin(dot(wave.xy, xz) * wave.z + u_wave_phases[i]);
    }
    return height;
}
