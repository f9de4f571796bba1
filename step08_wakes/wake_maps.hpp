// Chapter 8, the wake drawn on step06's sea. The renderer draws a sea as step05's two maps,
// (l Dx, h, l Dz, l dDx/dz) and (dh/dx, dh/dz, l dDx/dx, l dDz/dz): the wave field becomes the same
// two maps over its own grid, step06's extra waves, which its shaders add to the cascades
// (extra_waves.glsl). They read nothing past the grid's edge: the absorbing layer has calmed the
// field there, so the wake fades into the sea without a seam.
//
// The field holds heights only. Its horizontal motion follows from them as it does for every
// linear wave (step05's choppy waves): a mode of height eta^(k) moves the water sideways by
// D^(k) = i (k / |k|) eta^(k), so that a crest h = A cos(k.x) is drawn with D = -k^ A sin(k.x)
// (step05's Gerstner form, which pulls the points towards the crest). Every map is then the
// transform of the heights times a factor: i kx for dh/dx, -kx kx / |k| for dDx/dx, and so on;
// four inverse FFTs (two real maps in each complex one) make all eight. The Jacobian of the wake's
// choppy displacement falls below one on its steep crests, and step06's foam forms there.
#pragma once

#include "step06_foam_sky/extra_waves.hpp"
#include "step08_wakes/wave_field.hpp"

namespace step08 {

// The field's maps with choppiness l (step05's: how far the crests are pulled together), in
// double then rounded to float, laid out as step06::ExtraWaves takes them. The transform's Nyquist
// row and column are left out: their horizontal motion is not a real field (i kx is odd there).
// `heights_drawn` (n * n), if given, is drawn in place of the field's own heights, on its grid: a
// program that hides part of the surface (under a hull) draws what it shows.
step06::ExtraWaveMaps wake_maps(const WaveField& field, double choppiness,
                                const std::vector<double>* heights_drawn = nullptr);

}  // namespace step08
