// step06_foam_sky: the open sea under a sky.
// Notes sections 5, 5.1-5.6.
// New since step05: four cascades of step05's simulation, each with its own tile and band of
// wavenumbers, transformed together; GPU tessellation of patches around the camera with frustum
// culling, shaded once per pixel (deferred: gbuffer.hpp); foam where the surface folds, kept and
// faded with time; water shading with subsurface scatter, GGX or Beckmann specular and the sky's
// reflection through Fresnel; a sky cubemap with sun and drifting clouds; height fog, bloom and a
// filmic tonemapper, in HDR.
// Controls: as step02 (drag, wheel, C for the fly camera); every term and pass in the panel.
#include "step06_foam_sky/foam_sky.hpp"

OCEAN_MAIN(step06::FoamSky)
