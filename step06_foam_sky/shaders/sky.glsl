// Chapter 5.5's sky, as a function of direction: a gradient from horizon to zenith with a
// scattering glow around the sun, and clouds that drift with the wind. sky_cube.frag renders it
// into a cubemap once a frame; everything else samples the cubemap. The sun's disc is not in the
// cubemap: the water reflects the sun through its specular term, and a disc in the reflected sky
// would count it twice. sky.frag adds the disc (sun_disc) to the background only.
uniform vec3 u_to_sun;          // unit
uniform vec3 u_sun_radiance;    // linear, the disc's brightness
uniform vec3 u_zenith_colour;   // linear
uniform vec3 u_horizon_colour;  // linear
uniform float u_cloud_cover;    // 0..1
uniform vec2 u_cloud_offset;    // metres the clouds have drifted
uniform float u_sun_size;       // angular radius, radians
uniform float u_sun_disc_gain;  // disc radiance / sunlight

// A random number in [0, 1) for each lattice point, from integers alone (PCG's output function:
// Jarzynski and Olano, "Hash Functions for GPU Rendering", 2020), so every GPU draws the same
// clouds. The usual fract(sin(dot(p, ...)) * 43758.5453) depends on how the GPU computes sin of
// arguments in the ten thousands: an H100 and llvmpipe drew different skies with it.
// sky.hpp's lattice_hash is the CPU reference.
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float lattice_hash(ivec2 i) { return float(pcg_hash(uint(i.x) + pcg_hash(uint(i.y))) >> 8u) / 16777216.0; }

float value_noise(vec2 p) {
    vec2 f = fract(p);
    ivec2 i = ivec2(floor(p));
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(lattice_hash(i), lattice_hash(i + ivec2(1, 0)), u.x),
               mix(lattice_hash(i + ivec2(0, 1)), lattice_hash(i + ivec2(1, 1)), u.x), u.y);
}

float clouds(vec2 p) {
    float sum = 0.0, amplitude = 0.5;
    for (int i = 0; i < 5; ++i) {
        sum += amplitude * value_noise(p);
        p = p * 2.03 + vec2(17.0, 9.0);
        amplitude *= 0.5;
    }
    return sum;
}

vec3 sky_radiance(vec3 direction) {
    float up = direction.y;
    float cos_sun = dot(direction, u_to_sun);
    // Gradient, brighter towards the horizon; below it, the horizon colour darkens (what a
    // reflection pointing down would see: more sea than sky).
    vec3 colour = up >= 0.0 ? mix(u_horizon_colour, u_zenith_colour, pow(up, 0.45))
                            : u_horizon_colour * mix(1.0, 0.35, clamp(-up * 4.0, 0.0, 1.0));
    // Forward scattering around the sun: a tight aureole (a few degrees: a wider one blows out a
    // quarter of the sky) and a faint wide glow, in units of the sunlight (the disc is
    // u_sun_disc_gain times brighter than the light it casts).
    vec3 sunlight = u_sun_radiance / u_sun_disc_gain;
    colour += sunlight * (1.0 * pow(max(cos_sun, 0.0), 512.0) + 0.06 * pow(max(cos_sun, 0.0), 8.0));
    // Clouds on a plane 1000 m up, projected along the view ray, fading towards the horizon.
    if (up > 0.0 && u_cloud_cover > 0.0) {
        vec2 p = (direction.xz / up * 1000.0 + u_cloud_offset) / 900.0;
        float density = smoothstep(1.0 - u_cloud_cover, 1.0 - u_cloud_cover + 0.35, clouds(p));
        density *= smoothstep(0.0, 0.15, up);
        vec3 lit = mix(u_horizon_colour * 1.6, vec3(1.0), 0.5) * (0.6 + 0.4 * max(cos_sun, 0.0));
        colour = mix(colour, lit, density * 0.85);
    }
    return colour;
}

// The sun disc, with a soft edge one tenth of its radius wide.
vec3 sun_disc(vec3 direction) {
    return u_sun_radiance * smoothstep(cos(u_sun_size * 1.1), cos(u_sun_size), dot(direction, u_to_sun));
}
