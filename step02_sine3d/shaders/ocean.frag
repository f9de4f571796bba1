#version 450 core
// Just enough shading to see the shape; light and true normals are the next chapter.
// Colour follows height (deep troughs, pale crests). The optional facet shading takes each
// triangle's normal from screen-space derivatives of its position: cheap, and flat (one
// normal per triangle), where the waves' own derivatives would give every point its own.
#include "facet.glsl"

in vec3 v_world_position;
out vec4 out_color;

uniform float u_height_extent;  // metres: the largest possible crest
uniform bool u_facet_shading;
uniform bool u_wireframe;
uniform vec3 u_eye;

void main() {
    if (u_wireframe) {
        out_color = vec4(0.75, 0.9, 1.0, 1.0);
        return;
    }
    float h = clamp(0.5 + 0.5 * v_world_position.y / max(u_height_extent, 1e-4), 0.0, 1.0);
    vec3 color = mix(vec3(0.02, 0.12, 0.25), vec3(0.35, 0.75, 0.85), h);
    if (u_facet_shading) {
        vec3 facet = facet_normal(dFdx(v_world_position), dFdy(v_world_position));
        color *= 0.35 + 0.65 * max(dot(facet, normalize(vec3(0.4, 0.8, 0.3))), 0.0);
    }
    // Fade into the background colour with distance, so the plane's edge is soft.
    float fade = smoothstep(0.0, 1.0, exp(-0.004 * length(v_world_position - u_eye)));
    out_color = vec4(mix(vec3(0.06, 0.07, 0.09), color, fade), 1.0);
}
