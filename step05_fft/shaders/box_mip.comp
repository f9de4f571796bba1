#version 450 core
// Up to four mip levels made in one dispatch (box_mipmaps.hpp): each texel the mean of the 2 x 2
// texels it covers in the level above, what glGenerateMipmap makes of a power-of-two texture, for
// every layer (or cube face: z) at once. glGenerateMipmap would do, but drivers turn it into a
// draw or a blit per level and per layer: on llvmpipe 42 small draws for step06's sky cube, most
// of its sky pass; on an NVIDIA H100 or H200 nine tenths of the simulation's GPU time. A dispatch
// per level (this shader's first form) still cost a GPU a few microseconds each, most of them
// waiting on the barrier between levels, so a workgroup now carries its tile down four levels in
// shared memory:
//     level l + 1: 16 x 16 texels a workgroup, each the mean of 2 x 2 texels of level l (an image)
//     level l + 2: 8 x 8, from the 16 x 16 in shared memory ... level l + 4: 2 x 2
// Each level is averaged from the level above as computed in float, before its rounding to the
// texture's format (the level as stored is one rounding from that; where the next dispatch starts,
// from level l + 4 as stored, one more).
layout(local_size_x = 16, local_size_y = 16) in;

#ifndef FORMAT
#define FORMAT rgba16f  // the format: rgba32f (the simulation's maps), rgba16f (the sky), rg32f (the foam), r32f
#endif
#ifndef IMAGE
#define IMAGE imageCube  // imageCube, image2DArray (z: the layer) or image2D
#endif
#ifndef LAYERED
#define LAYERED 1  // 0 for image2D
#endif

layout(FORMAT, binding = 0) readonly uniform IMAGE u_above;     // level l
layout(FORMAT, binding = 1) writeonly uniform IMAGE u_below_1;  // level l + 1
layout(FORMAT, binding = 2) writeonly uniform IMAGE u_below_2;  // level l + 2 (bound only if u_count >= 2)
layout(FORMAT, binding = 3) writeonly uniform IMAGE u_below_3;
layout(FORMAT, binding = 4) writeonly uniform IMAGE u_below_4;
uniform int u_size;   // texels per side of level l + 1
uniform int u_count;  // levels to make: 1 to 4

#if LAYERED
#define AT(xy) ivec3(xy, gl_GlobalInvocationID.z)
#else
#define AT(xy) ivec2(xy)
#endif

shared vec4 tile[16][16];  // the level just made, this workgroup's part of it

// Level l + k, k >= 2, from the 2^(5-k) x 2^(5-k) texels of level l + k - 1 in the tile: the
// threads of the top-left corner each average 2 x 2, and store their texel if the level has it.
// Every thread reaches every barrier (none returns early), as GLSL requires.
vec4 next_level(ivec2 local, int side) {
    barrier();  // the level above is in the tile
    vec4 mean = vec4(0.0);
    if (all(lessThan(local, ivec2(side)))) {
        ivec2 c = 2 * local;
        mean = 0.25 * (tile[c.y][c.x] + tile[c.y][c.x + 1] + tile[c.y + 1][c.x] + tile[c.y + 1][c.x + 1]);
    }
    barrier();  // every thread has read the level above
    if (all(lessThan(local, ivec2(side)))) tile[local.y][local.x] = mean;
    return mean;
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy), local = ivec2(gl_LocalInvocationID.xy);
    ivec2 corner = 2 * texel;
    vec4 mean = vec4(0.0);
    bool inside = all(lessThan(texel, ivec2(u_size)));  // level l + 1 smaller than a workgroup
    if (inside) {
        mean = 0.25 * (imageLoad(u_above, AT(corner)) + imageLoad(u_above, AT(corner + ivec2(1, 0))) +
                       imageLoad(u_above, AT(corner + ivec2(0, 1))) + imageLoad(u_above, AT(corner + ivec2(1, 1))));
        imageStore(u_below_1, AT(texel), mean);
    }
    tile[local.y][local.x] = mean;

    // Levels l + 2 to l + 4: this workgroup's texel of level l + k is at its corner, offset by
    // the workgroup's place, (16 >> (k - 1)) texels a workgroup.
    ivec2 group = ivec2(gl_WorkGroupID.xy);
    mean = next_level(local, 8);
    if (u_count >= 2 && all(lessThan(local, ivec2(8))) && all(lessThan(group * 8 + local, ivec2(u_size >> 1))))
        imageStore(u_below_2, AT(group * 8 + local), mean);
    mean = next_level(local, 4);
    if (u_count >= 3 && all(lessThan(local, ivec2(4))) && all(lessThan(group * 4 + local, ivec2(u_size >> 2))))
        imageStore(u_below_3, AT(group * 4 + local), mean);
    mean = next_level(local, 2);
    if (u_count >= 4 && all(lessThan(local, ivec2(2))) && all(lessThan(group * 2 + local, ivec2(u_size >> 3))))
        imageStore(u_below_4, AT(group * 2 + local), mean);
}
