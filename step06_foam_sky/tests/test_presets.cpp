// step06's presets against the sea they make: the significant wave height of each preset's
// spectrum, read from the preset files, against the observed growth of wind seas (the JONSWAP
// growth law, the CEM formula) and the fully developed sea, by hand (step05's spectrum_heights.hpp).
#include "step05_fft/spectrum.hpp"
#include "step05_fft/tests/spectrum_heights.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

using namespace step05;

// A preset file's wind_speed and fetch, the two lines of it the spectrum needs.
void preset_wind_and_fetch(const std::string& name, double& wind, double& fetch) {
    std::ifstream preset(std::string(OCEAN_SOURCE_DIR) + "/step06_foam_sky/presets/" + name + ".preset");
    ASSERT_TRUE(preset) << name;
    wind = fetch = 0;
    for (std::string line; std::getline(preset, line);) {
        if (line.rfind("wind_speed =", 0) == 0) wind = std::stod(line.substr(12));
        if (line.rfind("fetch =", 0) == 0) fetch = std::stod(line.substr(7));
    }
    ASSERT_GT(wind * fetch, 0) << name << " names its wind and fetch";
}

TEST(Step06Presets, TheStormyPresetIsAtMostFullyDeveloped) {
    // A gale of 22 m/s over 800 km (gF/U^2 = 1.62e4, just short of 1.70e4): as fitted, JONSWAP
    // holds 13.69 m there, past the fully developed sea's 10.87 m; capped, the spectrum gives PM's.
    double wind = 0, fetch = 0;
    preset_wind_and_fetch("stormy", wind, fetch);
    const double hs = spectrum_height(wind, fetch, 3.3, JonswapEnergy::Fitted);
    std::printf("stormy: Hs %.3f m from the spectrum, %.3f m fully developed\n", hs,
                fully_developed_height(wind));
    EXPECT_LE(hs, fully_developed_height(wind) * (1 + 1e-4));
    EXPECT_NEAR(fully_developed_height(22), 10.866, 1e-3);  // 0.220235 * 484 / 9.81
}

TEST(Step06Presets, HeightsOfTheShippedPresets) {
    // The numbers step05's spectrum page shows for each of this chapter's presets: Hs of the spectrum the sea
    // is made from (energy = fit, capped), of JONSWAP as fitted without the cap (by hand:
    // alpha = 0.076 F~^-0.22, omega_p = 22 (g/U) F~^(-1/3), F~ = gF/U^2), of the JONSWAP growth
    // law, of the CEM formula, and of the fully developed sea. Read from the preset files, so
    // the README's table is what the presets do.
    std::printf(
        "preset   U m/s   F km    gF/U^2   Hs sea   Hs fit uncapped   Hs growth law   Hs CEM   Hs PM\n");
    for (const char* name : {"calm", "breezy", "stormy"}) {
        double wind = 0, fetch = 0;
        preset_wind_and_fetch(name, wind, fetch);
        const double dimensionless = kGravity * fetch / (wind * wind);
        const double uncapped = 4 * std::sqrt(0.076 * std::pow(dimensionless, -0.22) *
                                              jonswap_variance_per_alpha(
                                                  22 * kGravity / wind * std::cbrt(1 / dimensionless), 3.3));
        const double sea = spectrum_height(wind, fetch, 3.3, JonswapEnergy::Fitted);
        const double growth = 4 * std::sqrt(growth_law_variance(wind, fetch));
        const double cem = cem_significant_height(wind, fetch);
        const double pm = fully_developed_height(wind);
        std::printf("%-8s %5.0f %6.0f %9.0f %8.3f %17.3f %15.3f %8.3f %7.3f\n", name, wind, fetch / 1000,
                    dimensionless, sea, uncapped, growth, cem, pm);
        // The two observed-growth formulas agree within 20 % over this range; the sea sits above
        // them and at most at the fully developed one.
        EXPECT_NEAR(cem / growth, 1.0, 0.2) << name;
        EXPECT_GT(sea, growth) << name;
        EXPECT_LE(sea, pm * (1 + 1e-4)) << name;
        EXPECT_GE(uncapped, sea * (1 - 1e-4)) << name << ": the cap only lowers";
        const double switched = spectrum_height(wind, fetch, 3.3, JonswapEnergy::GrowthLaw);
        EXPECT_NEAR(switched / growth, 1.0, 1e-4) << name;
    }
}

}  // namespace
