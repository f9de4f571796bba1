// Two floats as 16-bit halves in one uint (the G-buffer's screen derivatives, gbuffer.hpp):
// packHalf2x16 and unpackHalf2x16 where GLSL has them (4.20 and up, ES 3.00); written out from the
// bits for GLSL 4.10 (macOS), with the same rounding: to the nearest half, ties to even.
#if __VERSION__ >= 420 || defined(GL_ES)
uint pack_halves(vec2 v) { return packHalf2x16(v); }
vec2 unpack_halves(uint bits) { return unpackHalf2x16(bits); }
#else
// A float's bits to a half's: sign, exponent rebiased from 127 to 15, mantissa cut from 23 bits to
// 10. Too large: infinity; too small for a normal half: a subnormal (mantissa shifted further)
// or zero.
uint half_bits(float f) {
    uint x = floatBitsToUint(f);
    uint sign = (x >> 16) & 0x8000u;
    int exponent = int((x >> 23) & 0xffu) - 127 + 15;
    uint mantissa = x & 0x7fffffu;
    if (exponent >= 31) return sign | 0x7c00u;
    uint shift = 13u;
    if (exponent <= 0) {
        if (exponent < -10) return sign;
        mantissa |= 0x800000u;  // the leading 1 becomes a stored bit
        shift = uint(14 - exponent);
        exponent = 0;
    }
    uint h = (uint(exponent) << 10) + (mantissa >> shift);
    uint rest = mantissa & ((1u << shift) - 1u), halfway = 1u << (shift - 1u);
    if (rest > halfway || (rest == halfway && (h & 1u) != 0u)) h += 1u;  // a carry moves the exponent up
    return sign | h;
}
float half_value(uint h) {
    uint exponent = (h >> 10) & 0x1fu, mantissa = h & 0x3ffu;
    float magnitude = exponent == 0u  ? float(mantissa) * exp2(-24.0)
                      : exponent == 31u ? uintBitsToFloat(0x7f800000u)
                                        : uintBitsToFloat(((exponent + 112u) << 23) | (mantissa << 13));
    return (h & 0x8000u) != 0u ? -magnitude : magnitude;
}
uint pack_halves(vec2 v) { return half_bits(v.x) | (half_bits(v.y) << 16); }
vec2 unpack_halves(uint bits) { return vec2(half_value(bits & 0xffffu), half_value(bits >> 16)); }
#endif
