// Numbers drawn by a fragment shader, for axis labels and colour legends: seven-segment digits,
// '-' and '.', each a few line segments whose coverage comes from the pixel's distance to them
// (anti-aliased, no font texture). number_coverage(value, decimals, pixel, centre, size) is all a
// shader needs: the coverage, 0 to 1, of `value` written at `centre`, in pixels.

// Which of the segments a (top), b, c (right, top to bottom), d (bottom), e, f (left, bottom to
// top) and g (middle) each digit lights: bit 0 = a ... bit 6 = g.
const int DIGIT_SEGMENTS[10] = int[10](0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x6F);
const int GLYPH_MINUS = 10, GLYPH_POINT = 11;

// 1 within half_width of the segment a-b, fading to 0 one pixel further (p, a, b in pixels).
float segment_coverage(vec2 p, vec2 a, vec2 b, float half_width) {
    vec2 pa = p - a, ba = b - a;
    float h = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-6), 0.0, 1.0);
    return clamp(half_width + 0.5 - length(pa - ba * h), 0.0, 1.0);
}

// Glyph c (0-9, GLYPH_MINUS, GLYPH_POINT) in a cell of `size` pixels, p relative to its
// bottom-left corner.
float glyph_coverage(int c, vec2 p, vec2 size) {
    float w = size.x, h = size.y, stroke = max(0.6, size.y / 14.0);
    vec2 tl = vec2(0.0, h), tr = vec2(w, h), ml = vec2(0.0, 0.5 * h), mr = vec2(w, 0.5 * h);
    vec2 bl = vec2(0.0), br = vec2(w, 0.0);
    if (c == GLYPH_MINUS) return segment_coverage(p, ml, mr, stroke);
    if (c == GLYPH_POINT) return segment_coverage(p, vec2(0.5 * w, 0.0), vec2(0.5 * w, 0.0), 1.5 * stroke);
    int s = DIGIT_SEGMENTS[clamp(c, 0, 9)];
    float coverage = 0.0;
    if ((s & 1) != 0) coverage = max(coverage, segment_coverage(p, tl, tr, stroke));
    if ((s & 2) != 0) coverage = max(coverage, segment_coverage(p, tr, mr, stroke));
    if ((s & 4) != 0) coverage = max(coverage, segment_coverage(p, mr, br, stroke));
    if ((s & 8) != 0) coverage = max(coverage, segment_coverage(p, bl, br, stroke));
    if ((s & 16) != 0) coverage = max(coverage, segment_coverage(p, ml, bl, stroke));
    if ((s & 32) != 0) coverage = max(coverage, segment_coverage(p, tl, ml, stroke));
    if ((s & 64) != 0) coverage = max(coverage, segment_coverage(p, ml, mr, stroke));
    return coverage;
}

// `value` rounded to `decimals` decimals (at most 4, and |value| below 1e6), its characters in
// cells of `size` pixels, centred on `centre`: the coverage at `pixel`. Each pixel finds the one
// character under it, so a label costs the same whatever its length.
float number_coverage(float value, int decimals, vec2 pixel, vec2 centre, vec2 size) {
    float scaled = floor(abs(value) * pow(10.0, float(decimals)) + 0.5);  // the digits, as an integer
    bool negative = value < 0.0 && scaled > 0.0;
    int integer_digits = 1;
    for (float whole = floor(scaled / pow(10.0, float(decimals))); whole >= 10.0 && integer_digits < 6; whole = floor(whole / 10.0))
        ++integer_digits;
    int sign = negative ? 1 : 0, point = decimals > 0 ? 1 : 0;
    int count = sign + integer_digits + point + decimals;
    float advance = 1.55 * size.x;
    vec2 origin = centre - 0.5 * vec2(float(count - 1) * advance + size.x, size.y);
    vec2 local = pixel - origin;
    int k = int(floor((local.x + 0.25 * size.x) / advance));
    if (k < 0 || k >= count || local.y < -2.0 || local.y > size.y + 2.0) return 0.0;
    vec2 p = local - vec2(float(k) * advance, 0.0);
    if (k < sign) return glyph_coverage(GLYPH_MINUS, p, size);
    int position = k - sign;  // among the digits and the point
    if (point == 1 && position == integer_digits) return glyph_coverage(GLYPH_POINT, p, size);
    int digit = position > integer_digits ? position - 1 : position;  // 0: the most significant
    float power = float(integer_digits + decimals - 1 - digit);
    return glyph_coverage(int(mod(floor(scaled / pow(10.0, power)), 10.0)), p, size);
}

// The decimals a label step needs (1, 2, 5 x 10^n): none for 5, one for 0.5, two for 0.05.
int decimals_for(float step) { return max(0, int(-floor(log(step) / log(10.0) + 1e-4))); }

// The power of ten that divides an axis of `span` units into 4 to 40 parts: a plot's grid spacing.
float grid_spacing(float span) { return pow(10.0, floor(log(span / 4.0) / log(10.0))); }

// A round step between labels for an axis of `span` units: 1, 2 or 5 grid spacings, 4 to 10 labels.
float label_step(float span) {
    float spacing = grid_spacing(span);
    float lines = span / spacing;
    return spacing * (lines > 20.0 ? 5.0 : lines > 10.0 ? 2.0 : 1.0);
}
