// What ocean.vert (per-vertex lighting) and ocean.frag (per-pixel lighting) both compute at a
// point of the sea: its normal, by the chosen method, and the colour of the chosen view.
#include "wave_gradient.glsl"
#include "lighting.glsl"

uniform int u_normal_method;  // 0: analytic derivatives, 1: finite differences (the seed's)
uniform float u_fd_step;      // metres
uniform int u_view;           // VIEW_* below
uniform float u_angle_scale;  // degrees shown as full red in VIEW_NORMAL_DIFFERENCE

const int VIEW_LIT = 0, VIEW_AMBIENT = 1, VIEW_DIFFUSE = 2, VIEW_SPECULAR = 3, VIEW_NORMALS = 4,
          VIEW_NORMAL_DIFFERENCE = 5;

vec3 surface_height_gradient(vec2 xz) {
    return u_normal_method == 1 ? finite_difference_gradient(xz, u_fd_step) : wave_height_gradient(xz);
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
    if (u_view == VIEW_NORMALS) return 0.5 * normal + 0.5;
    if (u_view == VIEW_NORMAL_DIFFERENCE) {
        vec3 analytic = surface_normal(wave_height_gradient(xz).yz);
        vec3 finite = surface_normal(finite_difference_gradient(xz, u_fd_step).yz);
        float degrees_apart = degrees(acos(clamp(dot(analytic, finite), -1.0, 1.0)));
        return heat(degrees_apart / u_angle_scale);
    }
    LightTerms t = light_terms(normal, normalize(eye - world_position));
    if (u_view == VIEW_AMBIENT) return t.ambient;
    if (u_view == VIEW_DIFFUSE) return t.diffuse;
    if (u_view == VIEW_SPECULAR) return t.specular;
    return t.ambient + t.diffuse + t.specular;
}
