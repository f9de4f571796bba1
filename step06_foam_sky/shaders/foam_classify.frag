#version 450 core
// Deferred shading, between the G-buffer and the shading (foam_sky.hpp's shade_sea): marks in the
// stencil the pixels of the sea where foam shows, so that only they run the foam's pattern and
// light. Most of the sea has no foam, and a shader pays for code it skips with a branch wherever
// neighbouring pixels run together (llvmpipe runs both sides of every branch), but not for pixels
// the stencil test turns away before it starts. So the sea is shaded twice: ocean_shade.frag
// compiled without foam where the stencil is 0, and with it where this shader let it be 1.
#include "step06_foam_sky/texture_units.h"
#include "cascades_visible.glsl"

layout(binding = UNIT_GBUFFER_REST) uniform usampler2D u_gbuffer_rest;  // as ocean_shade.frag reads it

void main() {
    uvec4 packed_rest = texelFetch(u_gbuffer_rest, ivec2(gl_FragCoord.xy), 0);
    vec2 rest_xz = uintBitsToFloat(packed_rest.xy);
    SurfaceFootprint footprint = SurfaceFootprint(unpackHalf2x16(packed_rest.z), unpackHalf2x16(packed_rest.w));
    // The same amounts, from the same footprint, as the shading's total_foam: the two agree.
    if (!foam_shows(foam_amounts(rest_xz, footprint))) discard;
}
