#version 450 core
// Unpacks the transformed fields into the two textures the renderer samples, one layer per cascade:
//     displacement = (l Dx, h, l Dz, l dDx/dz)      slopes = (dh/dx, dh/dz, l dDx/dx, l dDz/dz)
// with l the choppiness. The Jacobian J = (1 + l dDx/dx)(1 + l dDz/dz) - (l dDx/dz)^2 follows from them.
layout(local_size_x = 8, local_size_y = 8) in;
#include "ocean_layout.glsl"

layout(std430, binding = 0) readonly buffer Fields { vec2 fields[]; };
layout(rgba32f, binding = 0) writeonly uniform image2DArray u_displacement;
layout(rgba32f, binding = 1) writeonly uniform image2DArray u_slopes;

uniform float u_choppiness;

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (id.x >= u_n || id.y >= u_n || id.z >= u_layer_count) return;
    int offset = id.y * u_n + id.x;
    vec2 height_dx = fields[field_base(id.z, 0) + offset];    // (h, Dx)
    vec2 dz_slope_x = fields[field_base(id.z, 1) + offset];   // (Dz, dh/dx)
    vec2 slope_z_dxx = fields[field_base(id.z, 2) + offset];  // (dh/dz, dDx/dx)
    vec2 dzz_dxz = fields[field_base(id.z, 3) + offset];      // (dDz/dz, dDx/dz)
    float l = u_choppiness;
    imageStore(u_displacement, id, vec4(l * height_dx.y, height_dx.x, l * dz_slope_x.x, l * dzz_dxz.y));
    imageStore(u_slopes, id, vec4(dz_slope_x.y, slope_z_dxx.x, l * slope_z_dxx.y, l * dzz_dxz.x));
}
