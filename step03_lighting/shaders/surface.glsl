// What ocean.vert (per-vertex lighting) and ocean.frag (per-pixel lighting) both compute at a
// point of the sea: its normal, by the chosen method, and the colour of the chosen view.
//
// The method and the view are compile-time choices (#define, set by the step for each variant),
// not uniforms. On a GPU a branch on a uniform is uniform control flow: every pixel takes the same
// side and the other is skipped, but the shader still carries every path and the registers of its
// largest. A software rasteriser such as llvmpipe runs both sides of such a branch, and then every
// pixel would pay for the finite differences and the comparison view even when they are off
// (measured on llvmpipe at 1280x720: 330 ms a frame with uniforms, 52 ms with variants).
#include "wave_gradient.glsl"
#include "lighting.glsl"

#ifndef NORMAL_METHOD
#define NORMAL_METHOD 0  // 0: analytic derivatives, 1: finite differences (the notes')
#endif
#ifndef VIEW
#define VIEW 0           // VIEW_* below
#endif
#ifndef SPECULAR
#define SPECULAR 0       // 0: Blinn-Phong (light_terms), 1: Phong (phong_specular)
#endif

uniform float u_fd_step;      // metres
uniform float u_angle_scale;  // degrees shown as full red in VIEW_NORMAL_DIFFERENCE

#define VIEW_LIT 0
#define VIEW_AMBIENT 1
#define VIEW_DIFFUSE 2
#define VIEW_SPECULAR 3
#define VIEW_NORMALS 4
#define VIEW_NORMAL_DIFFERENCE 5

vec3 surface_height_gradient(vec2 xz) {
#if NORMAL_METHOD == 1
    return finite_difference_gradient(xz, u_fd_step);
#else
    return wave_height_gradient(xz);
#endif
}

// Black -> blue -> yellow -> red as t goes 0 -> 1.
vec3 heat(float t) {
    t = clamp(t, 0.0, 1.0);
    return t < 0.33 ? mix(vec3(0.0), vec3(0.1, 0.3, 1.0), t / 0.33)
         : t < 0.66 ? mix(vec3(0.1, 0.3, 1.0), vec3(1.0, 0.9, 0.1), (t - 0.33) / 0.33)
                    : mix(vec3(1.0, 0.9, 0.1), vec3(1.0, 0.1, 0.05), (t - 0.66) / 0.34);
}

// Linear colour of the chosen view at rest position xz, seen from `eye`.
vec3 surface_colour(vec2 xz, vec3 normal, vec3 world_position, vec3 eye) {
#if VIEW == VIEW_NORMALS
    return 0.5 * normal + 0.5;
#elif VIEW == VIEW_NORMAL_DIFFERENCE
    vec3 analytic = surface_normal(wave_height_gradient(xz).yz);
    vec3 finite = surface_normal(finite_difference_gradient(xz, u_fd_step).yz);
    float degrees_apart = degrees(acos(clamp(dot(analytic, finite), -1.0, 1.0)));
    return heat(degrees_apart / u_angle_scale);
#else
    LightTerms t = light_terms(normal, normalize(eye - world_position));
#if SPECULAR == 1
    t.specular = u_sun_color * phong_specular(normal, normalize(eye - world_position));
#endif
#if VIEW == VIEW_AMBIENT
    return t.ambient;
#elif VIEW == VIEW_DIFFUSE
    return t.diffuse;
#elif VIEW == VIEW_SPECULAR
    return t.specular;
#else
    return t.ambient + t.diffuse + t.specular;
#endif
#endif
}
