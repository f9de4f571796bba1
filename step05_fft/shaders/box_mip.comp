#version 450 core
// Several mip levels made in one dispatch (box_mipmaps.hpp): each texel the mean of the 2 x 2
// texels it covers in the level above, what glGenerateMipmap makes of a power-of-two texture, for
// every layer (or cube face: z) at once, of one texture or of two alike (MAPS). glGenerateMipmap
// would do, but drivers turn it into a draw or a blit per level and per layer: on llvmpipe 42
// small draws for a sky's cube map, most of the pass that draws it; on an NVIDIA H100 or H200 nine tenths
// of the simulation's GPU time. A dispatch per level (this shader's first form) still cost a GPU
// 5 to 7 microseconds each, most of them waiting on the barrier between levels, so a workgroup now
// carries its tile down LEVELS levels in shared memory:
//     level l + 1: 16 x 16 texels a workgroup, each the mean of 2 x 2 texels of level l (an image)
//     level l + 2: 8 x 8, from the 16 x 16 in shared memory ... level l + 4: 2 x 2
// Each level is averaged from the level above as computed in float, before its rounding to the
// texture's format (the level as stored is one rounding from that; where the next dispatch starts,
// from its first level as stored, one more). GL guarantees a compute shader 8 image units: one
// texture takes 1 + 4 (LEVELS 4), two take 2 + 2 x 3 (LEVELS 3).
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
#ifndef MAPS
#define MAPS 1  // textures made together (the same kind, size and format)
#endif
#ifndef LEVELS
#define LEVELS 4  // levels a dispatch makes at most: 1 to 4
#endif

layout(FORMAT, binding = 0) readonly uniform IMAGE u_above[MAPS];                // level l of map m
layout(FORMAT, binding = MAPS) writeonly uniform IMAGE u_below[LEVELS * MAPS];  // [k MAPS + m]: level l + 1 + k
uniform int u_size;   // texels per side of level l + 1
uniform int u_count;  // levels to make this dispatch: 1 to LEVELS (the units past it are not written)

#if LAYERED
#define AT(xy) ivec3(xy, gl_GlobalInvocationID.z)
#else
#define AT(xy) ivec2(xy)
#endif

shared vec4 tile[MAPS][16][16];  // the level just made, this workgroup's part of it

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy), local = ivec2(gl_LocalInvocationID.xy);
    ivec2 group = ivec2(gl_WorkGroupID.xy), corner = 2 * texel;
    bool inside = all(lessThan(texel, ivec2(u_size)));  // level l + 1 may be smaller than a workgroup
    for (int m = 0; m < MAPS; ++m) {
        vec4 mean = vec4(0.0);
        if (inside) {
            mean = 0.25 * (imageLoad(u_above[m], AT(corner)) + imageLoad(u_above[m], AT(corner + ivec2(1, 0))) +
                           imageLoad(u_above[m], AT(corner + ivec2(0, 1))) +
                           imageLoad(u_above[m], AT(corner + ivec2(1, 1))));
            imageStore(u_below[m], AT(texel), mean);
        }
        tile[m][local.y][local.x] = mean;
    }

    // Level l + 1 + k, from the 2 side x 2 side texels of the level above in the tile: the threads
    // of the top-left corner each average 2 x 2. This workgroup's part of that level starts at
    // group * side. Every thread reaches every barrier (none returns early), as GLSL requires.
    for (int k = 1; k < LEVELS; ++k) {
        int side = 16 >> k;
        bool averages = all(lessThan(local, ivec2(side)));
        vec4 mean[MAPS];
        barrier();  // the level above is in the tile
        ivec2 c = 2 * min(local, ivec2(side - 1));  // within the tile for every thread
        for (int m = 0; m < MAPS; ++m)
            mean[m] = 0.25 * (tile[m][c.y][c.x] + tile[m][c.y][c.x + 1] + tile[m][c.y + 1][c.x] + tile[m][c.y + 1][c.x + 1]);
        barrier();  // every thread has read the level above
        ivec2 at = group * side + local;
        bool stores = averages && k < u_count && all(lessThan(at, ivec2(u_size >> k)));
        for (int m = 0; m < MAPS; ++m) {
            if (averages) tile[m][local.y][local.x] = mean[m];
            if (stores) imageStore(u_below[k * MAPS + m], AT(at), mean[m]);
        }
    }
}
