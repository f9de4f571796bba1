// The passes of one step06 frame, in the order they run, and the buffers and textures each reads
// and writes: the lesson's map of the data's path. figures.cpp draws
// step06_frame.png from this table, and tools.frame_passes holds the table's timed
// passes to the ones --bench measures, in order, so the figure cannot drift from the code.
#pragma once

#include "step05_fft/frame_passes.hpp"

#include <array>

namespace step06 {

using step05::FramePass;

// A pass that reads one level of a texture to draw the next (the mipmaps, the bloom's chain), or
// two textures in turn (the foam's ping-pong), both reads and writes it: RW in the figure.
// The G-buffer's world target carries the mesh's l dDx/dz, so the shading reads the slopes only.
// Texture units as the SeaRenderer binds them (texture_units.h): 0-1 the cascades' maps, 3 foam, 4 sky,
// 5 the bubble pattern, 6-7 the G-buffer, 9 the fog's horizon table (unit 8 is free).
constexpr std::array<FramePass, 8> kFramePasses{{
    {"simulation", "step05's evolve.comp, fft.comp x 2, assemble.comp, box_mip.comp",
     "h0, omega (SSBOs, once);displacement (4 layers);slopes (4 layers)", "displacement (4 layers);slopes (4 layers)"},
    {"foam", "foam.frag (foam_step.glsl): 3 clipmap levels, ping-pong; box_mip.comp", "displacement (4 layers);slopes (4 layers);foam (rg32f, 3 levels)",
     "foam (rg32f, 3 levels)"},
    {"sky", "sky_cube.frag (6 faces) or sky_equirect.frag; box_mip.comp; sky_horizon.frag", "sky (cubemap)",
     "sky (cubemap);horizon (256 x 1)"},
    {"ocean", "ocean.vert, ocean.tesc, ocean.tese, ocean.frag: the G-buffer", "displacement (4 layers)",
     "G-buffer (world RGBA32F, rest RGBA32UI);depth"},
    {"ocean", "ocean_shade.frag where depth < far: ocean_shade.glsl",
     "G-buffer (world RGBA32F, rest RGBA32UI);depth;slopes (4 layers);foam (rg32f, 3 levels);bubble pattern;sky (cubemap);horizon (256 x 1)",
     "scene (RGBA16F, HDR)"},
    {"background", "sky.frag where depth = far: sky and sun disc", "depth;sky (cubemap)", "scene (RGBA16F, HDR)"},
    {"bloom", "bloom_down.frag down the levels, bloom_up.frag back up", "scene (RGBA16F, HDR);bloom (quarter size, 5 levels)",
     "bloom (quarter size, 5 levels)"},
    {"tonemap", "tonemap.frag: exposure, ACES or AgX, sRGB", "scene (RGBA16F, HDR);bloom (quarter size, 5 levels)",
     "screen (sRGB)"},
}};

}  // namespace step06
