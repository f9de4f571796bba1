// What the cascades combined around the camera could resolve, at best (README, "Why the cascades
// are not combined around the camera"; combined_levels.hpp is the same formula on the CPU).
// Crest sums every cascade once a frame into nested square levels centred on the camera, each
// twice the extent of the one inside it and each `texels` x `texels`, the innermost at the finest
// cascade's texel. A point lies in the smallest level whose half-extent reaches it (the square's
// distance, max(|x|, |z|)), and nothing fetched from that level is finer than its texel.
float combined_level_texel(vec2 offset_from_centre, float texels, float finest_texel) {
    float reach = max(abs(offset_from_centre.x), abs(offset_from_centre.y));
    // max(.., 1): the innermost level, and no log2(0) at the centre.
    float level = ceil(log2(max(2.0 * reach / (texels * finest_texel), 1.0)));
    return finest_texel * exp2(level);
}
