// Chapter 7.2 on the GPU (sea_query.cpp's newton_step is the CPU reference): one step towards the
// rest position x drawn above the world point p, from the summed surface at x in the maps' layout,
// displacement (l Dx, h, l Dz, l dDx/dz) and slopes (dh/dx, dh/dz, l dDx/dx, l dDz/dz): Newton's
// method on x + l D(x) = p (README section 2). Where the surface folds, Newton's step is
// meaningless and the fixed-point step takes its place.
vec2 newton_step(vec2 x, vec2 p, vec4 displacement, vec4 slopes) {
    vec2 miss = x + displacement.xz - p;
    float a = 1.0 + slopes.z, b = displacement.w, d = 1.0 + slopes.w;
    float det = a * d - b * b;  // dDz/dx = dDx/dz: J is symmetric
    if (det <= 0.05) return p - displacement.xz;
    return x - vec2(d * miss.x - b * miss.y, -b * miss.x + a * miss.y) / det;
}
