// Chapter 1's sum of sines, shared by the plot and the GPU test. Each wave arrives as
// (w, a, phase, 0): angular wavenumber w = 2 pi / wavelength, amplitude a, and the phase
// -t * phi already reduced modulo 2 pi on the CPU in double precision (crests travel towards +x).
const int MAX_WAVES = 8;

uniform int u_wave_count;
uniform vec4 u_waves[MAX_WAVES];

float wave_height(int i, float x) {
    vec4 wave = u_waves[i];
    return wave.y * sin(x * wave.x + wave.z);
}

float wave_slope(int i, float x) {
    vec4 wave = u_waves[i];
    return wave.y * wave.x * cos(x * wave.x + wave.z);
}

// d2/dx2 of wave i's height: how fast its slope turns, the curvature where slopes are gentle
// (the plot's show_curvature draws the sum's).
float wave_curvature(int i, float x) {
    float w = u_waves[i].x;
    return -u_waves[i].y * w * w * sin(x * w + u_waves[i].z);
}

float sum_of_sines(float x) {
    float height = 0.0;
    for (int i = 0; i < u_wave_count; ++i) height += wave_height(i, x);
    return height;
}

float sum_of_sines_slope(float x) {
    float slope = 0.0;
    for (int i = 0; i < u_wave_count; ++i) slope += wave_slope(i, x);
    return slope;
}

float sum_of_sines_curvature(float x) {
    float curvature = 0.0;
    for (int i = 0; i < u_wave_count; ++i) curvature += wave_curvature(i, x);
    return curvature;
}
