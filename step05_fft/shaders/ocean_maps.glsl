// Sampling the simulation's textures (one layer per cascade; step05 has one) and the normal of
// the choppy surface. The surface point of rest position p is P(p) = (p.x + l Dx, h, p.z + l Dz),
// so its tangents are dP/dx = (1 + l dDx/dx, dh/dx, l dDz/dx) and dP/dz = (l dDx/dz, dh/dz,
// 1 + l dDz/dz), with dDz/dx = dDx/dz, and N = dP/dz x dP/dx. With l = 0 this is step03's
// normalize(-dh/dx, 1, -dh/dz).
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

// J = (1 + l dDx/dx)(1 + l dDz/dz) - (l dDx/dz)^2: below 0 the surface folds over itself.
float jacobian(vec4 displacement, vec4 slopes) {
    return (1.0 + slopes.z) * (1.0 + slopes.w) - displacement.w * displacement.w;
}
