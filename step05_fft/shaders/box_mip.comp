#version 450 core
// One mip level made from the level above it (box_mipmaps.hpp): each texel the mean of the 2 x 2
// texels it covers, what glGenerateMipmap makes of a power-of-two texture, for every layer (or
// cube face: z) at once. glGenerateMipmap would do, but drivers turn it into a draw or a blit per
// level and per layer: on llvmpipe 42 small draws for step06's sky cube, most of its sky pass; on
// an NVIDIA H100 or H200 nine tenths of the simulation's GPU time.
layout(local_size_x = 8, local_size_y = 8) in;

#ifndef FORMAT
#define FORMAT rgba16f  // the format: rgba32f (the simulation's maps), rgba16f (the sky), rg32f (the foam), r32f
#endif
#ifndef IMAGE
#define IMAGE imageCube  // imageCube, image2DArray (z: the layer) or image2D
#endif
#ifndef LAYERED
#define LAYERED 1  // 0 for image2D
#endif

layout(FORMAT, binding = 0) readonly uniform IMAGE u_above;   // level l - 1
layout(FORMAT, binding = 1) writeonly uniform IMAGE u_below;  // level l
uniform int u_size;  // texels per side of level l

#if LAYERED
#define AT(xy) ivec3(xy, gl_GlobalInvocationID.z)
#else
#define AT(xy) ivec2(xy)
#endif

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (texel.x >= u_size || texel.y >= u_size) return;
    ivec2 corner = 2 * texel;
    vec4 sum = imageLoad(u_above, AT(corner)) + imageLoad(u_above, AT(corner + ivec2(1, 0))) +
               imageLoad(u_above, AT(corner + ivec2(0, 1))) + imageLoad(u_above, AT(corner + ivec2(1, 1)));
    imageStore(u_below, AT(texel), 0.25 * sum);
}
