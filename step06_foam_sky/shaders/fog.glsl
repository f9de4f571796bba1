// Height fog (the notes' 5.5; fog.hpp is the CPU reference): thick near the sea, thinning with
// altitude. For a density rho(y) = u_fog_density exp(-u_fog_falloff y), the optical depth along
// the segment from the eye to p has a closed form (Quilez's "better fog"); the fog takes the sky's
// horizon colour, so the sea melts into the sky at the horizon.
#include "exp_mean.glsl"

uniform float u_fog_density;  // per metre at sea level
uniform float u_fog_falloff;  // per metre of height

vec3 apply_fog(vec3 colour, vec3 eye, vec3 p, vec3 fog_colour) {
    vec3 ray = p - eye;
    float distance = length(ray);
    float dy = ray.y;
    float k = u_fog_falloff;
    // the density at the eye's height times the mean of e^{-k s dy} along the segment
    float depth = u_fog_density * exp(-k * eye.y) * distance * mean_of_exp(k * dy);
    return mix(fog_colour, colour, exp(-depth));
}
