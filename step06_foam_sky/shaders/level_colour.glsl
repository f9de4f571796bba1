// The tessellation level as a colour: 1 blue, 8 green, 64 red (wireframe and view=tessellation).
vec3 level_colour(float level) {
    float t = clamp(log2(level) / 6.0, 0.0, 1.0);
    return t < 0.5 ? mix(vec3(0.1, 0.2, 1.0), vec3(0.1, 0.9, 0.2), t * 2.0) : mix(vec3(0.1, 0.9, 0.2), vec3(1.0, 0.1, 0.1), (t - 0.5) * 2.0);
}
