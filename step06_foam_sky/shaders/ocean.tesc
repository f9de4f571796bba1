#version 450 core
// Chapter 5.1: how finely to cut each patch. Each edge's level falls with the distance from the
// camera to its midpoint (edge_level, tessellation.glsl); neighbouring patches share edges and
// therefore levels, so no cracks open. Patches outside the view frustum (their box widened by
// the largest displacement) get level 0, which discards them.
layout(vertices = 4) out;

in vec2 tc_rest_xz[];
out vec2 te_rest_xz[];

#include "tessellation.glsl"
uniform vec4 u_frustum[6];      // planes, normals pointing inwards: dot(plane.xyz, p) + plane.w >= 0 inside
uniform float u_max_displacement;  // metres: how far any point can move from rest

bool outside_frustum(vec2 lo, vec2 hi) {
    float r = u_max_displacement;
    vec3 box_min = vec3(lo.x - r, -r, lo.y - r), box_max = vec3(hi.x + r, r, hi.y + r);
    for (int i = 0; i < 6; ++i) {
        vec4 plane = u_frustum[i];
        vec3 farthest = mix(box_min, box_max, greaterThan(plane.xyz, vec3(0.0)));  // farthest along the inward normal
        if (dot(plane.xyz, farthest) + plane.w < 0.0) return true;
    }
    return false;
}

void main() {
    te_rest_xz[gl_InvocationID] = tc_rest_xz[gl_InvocationID];
    if (gl_InvocationID != 0) return;
    vec2 p0 = tc_rest_xz[0], p1 = tc_rest_xz[1], p2 = tc_rest_xz[2], p3 = tc_rest_xz[3];  // counter-clockwise
    if (outside_frustum(min(p0, p2), max(p0, p2))) {
        gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 0.0;
        gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
        return;
    }
    // Quad domain: outer 0 is the edge u = 0 (p0-p3), 1 is v = 0 (p0-p1), 2 is u = 1 (p1-p2), 3 is v = 1 (p3-p2).
    gl_TessLevelOuter[0] = edge_level(p0, p3);
    gl_TessLevelOuter[1] = edge_level(p0, p1);
    gl_TessLevelOuter[2] = edge_level(p1, p2);
    gl_TessLevelOuter[3] = edge_level(p3, p2);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[1], gl_TessLevelOuter[3]);
    gl_TessLevelInner[1] = max(gl_TessLevelOuter[0], gl_TessLevelOuter[2]);
}
