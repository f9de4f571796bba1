// Chapter 10, why the sea is blue from below: light loses itself along its path through the water
// (Beer-Lambert), each colour at its own rate, and sunlight scattered into the line of sight
// fills in what was lost with the water's own colour. Three channels (r, g, b) in glm::dvec3,
// coefficients per metre, in double precision: the reference the shaders are held to.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <string>

namespace step10 {

// The wavelength (nm) each channel stands for: near the dominant wavelengths of the sRGB
// primaries (red ~612, green ~549, blue ~465 nm), rounded to the 2.5 nm grid of Pope and Fry's
// table so no value is interpolated. Not 680 nm for red: sRGB's red primary looks orange-red,
// and water absorbs nearly twice as much at 680 as at 612, which would make the sea too cyan.
constexpr glm::dvec3 kChannelWavelength{612.5, 550.0, 465.0};

// Pure water's absorption a_w (1/m) at those wavelengths. Source: R. M. Pope and E. S. Fry,
// "Absorption spectrum (380-700 nm) of pure water. II. Integrating cavity measurements",
// Applied Optics 36(33), 8710-8723 (1997), as transcribed (in 1/cm) by the OMLC compendium
// (https://omlc.org/spectra/water/abs/pope97.html) and redistributed in the GitHub repository
// raphidoc/aw, file inst/extdata/pope_1997.csv: 612.5 nm 0.002665, 550 nm 0.000565,
// 465 nm 0.0001011 per cm; times 100 for per metre. Red is absorbed 26 times faster than blue.
constexpr glm::dvec3 kPureWaterAbsorption{0.2665, 0.0565, 0.01011};

// Pure sea water's molecular scattering b_w (1/m) at `wavelength` nm: Morel (1974), as summarized
// by Mobley (Light and Water, 1994) and coded in the GitHub repository belasi01/Riops,
// R/spectral.bw.R: b_w = 16.06 * 4.72e-4 * (400 / wavelength)^4.32. Steeper than Rayleigh's
// lambda^-4 because water's index itself grows towards the blue. About 0.0029 /m at 500 nm:
// a hundred times weaker than red absorption, but it is what makes deep clear water glow blue.
double pure_water_scattering(double wavelength);
glm::dvec3 pure_water_scattering();  // at kChannelWavelength

// Morel's phase function for pure water, 1 + q cos^2(theta), normalised to 1 over the sphere.
// The 16.06 above is b_w / beta_w(90 deg), the integral of 1 + q cos^2 over the sphere,
// 4 pi (1 + q / 3); so q = 3 (16.06 / (4 pi) - 1) = 0.834 (Rayleigh's dipole would give q = 1;
// water's molecules are not perfect dipoles, which lifts the side scattering).
double water_phase(double cos_theta);

// Henyey and Greenstein's phase function (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^1.5), normalised
// to 1 over the sphere, with mean cosine g. Particles in the sea scatter mostly forward.
double henyey_greenstein_phase(double cos_theta, double g);

// A water body: pure water plus what is in it. The added coefficients are CHOSEN to give the
// look of each kind of water, not measured: particles scatter about equally at all colours and
// mostly forward (g = 0.9, chosen to give a strong forward peak; not fitted to a measurement),
// chlorophyll and dissolved organic matter absorb the blue first, which turns coastal water green.
struct WaterType {
    const char* name;
    glm::dvec3 added_absorption;   // 1/m, on top of kPureWaterAbsorption
    glm::dvec3 particle_scattering;  // 1/m, on top of pure_water_scattering()
    double particle_g;             // Henyey-Greenstein mean cosine of the particles
};

constexpr WaterType kPureSeaWater{"pure_sea_water", {0, 0, 0}, {0, 0, 0}, 0.9};
constexpr WaterType kClearOcean{"clear_ocean", {0.005, 0.005, 0.01}, {0.03, 0.03, 0.03}, 0.9};
constexpr WaterType kCoastal{"coastal", {0.05, 0.06, 0.25}, {0.5, 0.5, 0.5}, 0.9};
// The program's `water_type` choices, in order.
constexpr std::array<WaterType, 3> kWaterTypes = {kClearOcean, kCoastal, kPureSeaWater};
// The water type of that name, or null.
const WaterType* water_type_named(const std::string& name);

glm::dvec3 absorption(const WaterType& water);  // a
glm::dvec3 scattering(const WaterType& water);  // b
glm::dvec3 extinction(const WaterType& water);  // c = a + b: what a beam loses per metre

// The fraction of a beam that crosses `path_length` metres unscattered and unabsorbed: exp(-c L).
glm::dvec3 transmittance(const WaterType& water, double path_length);

// The phase function of the mixture, per channel: each scatterer weighted by its share of b.
glm::dvec3 phase(const WaterType& water, double cos_theta);

// The sun's direct beam at `depth` metres under a flat surface, as irradiance on a plane facing
// it, for a sun of irradiance `sun` (same plane, above the water) at `elevation` radians: what
// the Fresnel transmittance lets in, attenuated along the refracted slant path depth / cos(refracted).
glm::dvec3 sunlight_at_depth(const WaterType& water, const glm::dvec3& sun, double elevation, double depth);

// In-scattering along a line of sight that stays at one depth (the sun's beam the same all along
// it). Along the ray towards the eye, dL/ds = -c L + J: the beam loses c L per metre and gains
// J = b p(theta) E_sun, the sunlight E_sun scattered by b into the ray, spread by the phase
// function p over the scattering angle theta. J constant, so L relaxes exponentially towards
// L_inf = J / c = (b / c) p(theta) E_sun: the water's own radiance, what an endless view sees.
// cos_theta: the cosine between the sun's direction of travel in the water and the direction
// from the water towards the eye (1: looking straight into the refracted sun). Single scattering:
// light scattered twice is left out, a good account while b L is small.
glm::dvec3 in_scatter_limit(const WaterType& water, double cos_theta, const glm::dvec3& sun_at_depth);

// What the eye sees of a surface of radiance `surface` through `path_length` metres of water:
// L = L0 e^{-cL} + L_inf (1 - e^{-cL}), the solution of the equation above.
glm::dvec3 seen_through_water(const WaterType& water, const glm::dvec3& surface, double path_length,
                              const glm::dvec3& limit);

}  // namespace step10
