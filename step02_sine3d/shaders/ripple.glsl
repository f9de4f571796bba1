// A ring of waves spreading from a point (waves.hpp's ripple_height is the CPU reference), the
// step's `ripple_*` parameters: where step02's waves measure how far along d a point lies, the
// ripple measures how far from its centre. It arrives as (c.x, c.z, w, a), a its amplitude one
// wavelength from the centre, and its phase -t * phi, reduced modulo 2 pi on the CPU: crests
// travel outwards.
uniform vec4 u_ripple;
uniform float u_ripple_phase;

float ripple_height(vec2 xz) {
    float r = distance(xz, u_ripple.xy);
    float wavelength = 6.2831853 / u_ripple.z;
    // The energy a crest carries, a^2 per unit area, spreads round a circle 2 pi r long: a falls as
    // 1 / sqrt(r) beyond one wavelength; nearer, where the bobbing source itself is, it stays a.
    float spread = sqrt(wavelength / max(r, wavelength));
    return u_ripple.w * spread * sin(r * u_ripple.z + u_ripple_phase);
}
