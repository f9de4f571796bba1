// The passes of one step05 frame (backend gpu_fft), in the order they run, and the buffers and
// textures each reads and writes: the lesson's map of the data's path. figures.cpp draws
// step05_frame.png from this table, and tools.frame_passes holds the table's timed
// passes to the ones --bench measures, in order, so the figure cannot drift from the code.
#pragma once

#include <array>
#include <string_view>

namespace step05 {

struct FramePass {
    std::string_view timer;    // the --bench pass it is timed in
    std::string_view program;  // the shaders (or the GL call) that run
    std::string_view reads;    // resources, separated by ';'
    std::string_view writes;
};

// Resources: the SSBOs of ocean_simulation.hpp (binding points as the dispatch sets them) and its two
// RGBA32F 2D-array textures, one layer per cascade (step05 has one).
constexpr std::array<FramePass, 6> kFramePasses{{
    {"evolve", "evolve.comp (N/8 x N/8 x cascades groups of 8 x 8)", "h0 (SSBO, once);omega (SSBO, double, once)",
     "spectra (SSBO)"},
    {"fft", "fft.comp, rows (N/4 x 4 cascades groups of 4 lines x N/4)", "spectra (SSBO);twiddles (SSBO, once)", "fields (SSBO)"},
    {"fft", "fft.comp, columns, in place", "fields (SSBO);twiddles (SSBO, once)", "fields (SSBO)"},
    {"assemble", "assemble.comp, then box_mip.comp (both maps, 3 levels a dispatch)",
     "fields (SSBO);displacement (RGBA32F array);slopes (RGBA32F array)",
     "displacement (RGBA32F array);slopes (RGBA32F array)"},
    {"ocean", "ocean.vert (grid in chunks), ocean.frag", "displacement (RGBA32F array);slopes (RGBA32F array)",
     "screen (sRGB)"},
    {"ocean", "or, for view = height ... jacobian or spectrum, map_view.frag",
     "displacement (RGBA32F array);slopes (RGBA32F array);spectrum image (RGBA8, CPU-made)", "screen (sRGB)"},
}};

}  // namespace step05
