// The water seen from inside it (water_light.hpp is the CPU reference of each function):
//   - Fresnel from the water side, where the light meets the surface from below: past the critical
//     angle asin(1 / n) = 48.6 degrees nothing gets out (total internal reflection);
//   - the water's extinction c = a + b per channel (absorption and scattering, 1/m): a path of
//     length L keeps exp(-c L) of its light (Beer and Lambert);
//   - the light it scatters towards the eye (single scattering of a parallel beam, in closed form).
const float WATER_INDEX = 1.333;
const float PI = 3.14159265358979;

uniform vec3 u_absorption;           // a, 1/m, per channel
uniform vec3 u_water_scattering;     // b of the water's molecules (Morel), 1/m
uniform vec3 u_particle_scattering;  // and of what is in it, 1/m
uniform float u_particle_g;          // the particles' Henyey-Greenstein mean cosine (forward: g > 0)
uniform float u_seabed_depth;  // metres below the mean level
uniform vec3 u_seabed_albedo;
uniform vec3 u_sun_in_water;   // the sun's beam below the surface: its direction (down, refracted)
uniform vec3 u_sun_beam;       // and its irradiance across the beam just below a flat surface
uniform vec3 u_sky_down;       // the sky's light through the surface, irradiance on a level plane

vec3 scattering() { return u_water_scattering + u_particle_scattering; }
vec3 extinction() { return u_absorption + scattering(); }

// Unpolarised Fresnel reflectance for light inside the water meeting the surface at cos_i (the
// cosine from the normal, on the water side): the mean of the s and p parts.
float fresnel_from_water(float cos_i) {
    float sin_t2 = WATER_INDEX * WATER_INDEX * (1.0 - cos_i * cos_i);
    if (sin_t2 >= 1.0) return 1.0;  // total internal reflection
    float cos_t = sqrt(1.0 - sin_t2);
    float rs = (WATER_INDEX * cos_i - cos_t) / (WATER_INDEX * cos_i + cos_t);
    float rp = (cos_i - WATER_INDEX * cos_t) / (cos_i + WATER_INDEX * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// Where scattered light goes, per steradian (each integrates to 1 over the sphere): the water's
// molecules as Morel measured, 1 + q cos^2 (q = 0.834), and particles mostly forward (Henyey and
// Greenstein's), mixed in proportion to their scattering.
float water_phase(float cos_theta) {
    const float q = 0.834;
    return (1.0 + q * cos_theta * cos_theta) / (4.0 * PI * (1.0 + q / 3.0));
}
float henyey_greenstein(float cos_theta, float g) {
    float d = 1.0 + g * g - 2.0 * g * cos_theta;
    return (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
}
vec3 phase(float cos_theta) {
    return (u_water_scattering * water_phase(cos_theta) + u_particle_scattering * henyey_greenstein(cos_theta, u_particle_g)) /
           scattering();
}

// The light one beam (travelling along `beam`, downwards, with irradiance `across` across it just
// below the surface) scatters towards an eye at depth z_eye looking along d, from the first t metres
// of the eye's ray. At s metres along the ray the point is z_eye - s d.y deep; the beam has crossed
// that depth over z / mu (mu = -beam.y), the scattered light crosses s back to the eye:
//   L = b p(theta) across exp(-c z_eye / mu) (1 - exp(-k t)) / k,   k = c (1 - d.y / mu).
vec3 beam_inscatter(float z_eye, vec3 d, float t, vec3 beam, vec3 across, vec3 p) {
    vec3 c = extinction();
    float mu = max(-beam.y, 1e-3);
    vec3 k = c * (1.0 - d.y / mu);
    vec3 along = vec3(t);  // k -> 0: the integral is t
    for (int i = 0; i < 3; ++i)
        if (abs(k[i]) * t > 1e-4) along[i] = (1.0 - exp(-k[i] * t)) / k[i];
    return scattering() * p * across * exp(-c * z_eye / mu) * along;
}

// Both beams: the sun's, and the sky's light taken as a beam from straight above, scattered evenly.
vec3 inscatter(float z_eye, vec3 d, float t) {
    return beam_inscatter(z_eye, d, t, u_sun_in_water, u_sun_beam, phase(dot(u_sun_in_water, -d))) +
           beam_inscatter(z_eye, d, t, vec3(0.0, -1.0, 0.0), u_sky_down, vec3(1.0 / (4.0 * PI)));
}

// The seabed's radiance at a point: Lambertian, lit by the sun's beam (its irradiance on the level
// bed, times `caustic`, the pattern the waves focus) and the sky's, each attenuated on its way down.
vec3 seabed_radiance(float caustic) {
    vec3 c = extinction();
    float mu = max(-u_sun_in_water.y, 1e-3);
    vec3 sun = u_sun_beam * mu * exp(-c * u_seabed_depth / mu) * caustic;
    vec3 sky = u_sky_down * exp(-c * u_seabed_depth);
    return u_seabed_albedo / PI * (sun + sky);
}
