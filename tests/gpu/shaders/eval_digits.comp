#version 450 core
// Evaluates common/shaders/digits.glsl's glyphs at the midpoints of the seven segments, for the
// digits test: result[d * 7 + s] is glyph d's coverage at segment s's midpoint (a b c d e f g).
layout(local_size_x = 1) in;
#include "common/shaders/digits.glsl"

layout(std430, binding = 0) writeonly buffer Out { float result[]; };

void main() {
    vec2 size = vec2(12.0, 20.0);
    vec2 midpoints[7] = vec2[7](vec2(6.0, 20.0), vec2(12.0, 15.0), vec2(12.0, 5.0), vec2(6.0, 0.0),
                                vec2(0.0, 5.0), vec2(0.0, 15.0), vec2(6.0, 10.0));
    for (int d = 0; d < 12; ++d)
        for (int s = 0; s < 7; ++s) result[d * 7 + s] = glyph_coverage(d, midpoints[s], size);
    // The layout of "-12.5": five cells 1.55 x 12 = 18.6 pixels apart, centred on (100, 50), so the
    // first cell's bottom-left corner is at (56.8, 40).
    vec2 centre = vec2(100.0, 50.0), corner = vec2(56.8, 40.0);
    result[84] = number_coverage(-12.5, 1, corner + vec2(0.0 * 18.6 + 6.0, 10.0), centre, size);  // cell 0: '-'
    result[85] = number_coverage(-12.5, 1, corner + vec2(3.0 * 18.6 + 6.0, 0.0), centre, size);   // cell 3: '.'
    result[86] = number_coverage(-12.5, 1, corner + vec2(3.0 * 18.6 + 6.0, 20.0), centre, size);  // '.' has no top
    result[87] = number_coverage(-12.5, 1, corner + vec2(4.0 * 18.6 + 0.0, 15.0), centre, size);  // cell 4: '5' lights f
    result[88] = number_coverage(-12.5, 1, corner + vec2(4.0 * 18.6 + 12.0, 15.0), centre, size); // but not b
    result[89] = number_coverage(-12.5, 1, vec2(100.0, 200.0), centre, size);                     // far away
}
