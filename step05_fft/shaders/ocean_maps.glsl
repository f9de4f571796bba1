// Sampling the simulation's textures (one layer per cascade; step05 has one) and what the choppy
// surface P(p) = (p.x + l Dx, h, p.z + l Dz) needs from them: its normal, from its two tangents,
// and the Jacobian of its horizontal map (README section 4; the maps hold every derivative both
// need). With l = 0 the normal is step03's.
uniform sampler2DArray u_displacement;  // (l Dx, h, l Dz, l dDx/dz)
uniform sampler2DArray u_slopes;        // (dh/dx, dh/dz, l dDx/dx, l dDz/dz)

// Where rest position p falls in a tile of side patch_size: texel i holds the sea at x_i = i L / N
// (as the CPU reference and --export have it), and GL puts texel i's centre at uv = (i + 0.5) / N,
// so the half texel makes the two agree (without it the surface is drawn L / 2N off).
vec2 map_uv(vec2 p, float patch_size) {
    return p / patch_size + 0.5 / float(textureSize(u_displacement, 0).x);
}

vec3 choppy_normal(vec4 displacement, vec4 slopes) {
    vec3 along_x = vec3(1.0 + slopes.z, slopes.x, displacement.w);
    vec3 along_z = vec3(displacement.w, slopes.y, 1.0 + slopes.w);
    vec3 n = cross(along_z, along_x);
    // Where the surface folds edge-on the tangents are parallel and n vanishes: normalize(0) is
    // NaN, a black pixel. Up is as good a guess as any there.
    float length2 = dot(n, n);
    return length2 > 1e-24 ? n * inversesqrt(length2) : vec3(0.0, 1.0, 0.0);
}

// J, the determinant of the horizontal map's derivatives: how much the map stretches a small square
// of water; below 0 the surface folds over itself.
float jacobian(vec4 displacement, vec4 slopes) {
    return (1.0 + slopes.z) * (1.0 + slopes.w) - displacement.w * displacement.w;
}
