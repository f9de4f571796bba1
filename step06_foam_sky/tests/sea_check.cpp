// sea_check: step06's sea measured from what it exported (--export), as physics_check measures a
// sea: from the PFM maps and export.txt, knowing nothing of the spectrum or the shaders.
//
//   sea_check whitecaps DIR...
//       the whitecap fraction of each export (foam > 0.3 on its grid, after >= 10 s of simulated
//       foam) against Monahan and O'Muircheartaigh's W = 3.84e-6 U^3.41 (U the export's
//       wind_speed, m/s): within a factor of 2 where W >= 0.2 %, below 0.2 % where W is.
//   sea_check same_sea FAR_DIR NEAR_DIR NEAR_DIR...
//       the sea far from the origin (1000 km) is the sea near it: height rms, slope rms along x
//       and z, mean Jacobian and the share below J = 0.7 of FAR_DIR's export within noise of the
//       NEAR_DIRs' (three standard deviations of theirs, at least 5 % of their mean).
// Prints the figures; exit 0 when they hold, 1 otherwise (and 2 on bad input).
#include "tests/export_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using ocean_test::Export;
using ocean_test::read_export;

int whitecaps(const std::vector<std::string>& dirs) {
    int failures = 0;
    for (const auto& dir : dirs) {
        const Export e = read_export(dir);
        const auto foam = e.map(dir, e.values.at("file.foam"));
        double covered = 0;
        for (double f : foam) covered += f > 0.3;
        covered /= double(foam.size());
        const double wind = std::stod(e.values.at("wind_speed"));
        const double monahan = 3.84e-6 * std::pow(wind, 3.41);
        const bool ok = monahan < 0.002 ? covered < 0.002 : covered >= monahan / 2 && covered <= monahan * 2;
        std::printf("%-40s U = %4.1f m/s: whitecaps %6.2f %% of the sea, Monahan %6.2f %% (%s)\n", dir.c_str(), wind,
                    100 * covered, 100 * monahan, monahan < 0.002 ? "must be < 0.2 %" : "within a factor of 2");
        failures += ok ? 0 : 1;
    }
    return failures == 0 ? 0 : 1;
}

// The statistics a sailor would compare between two stretches of sea: height rms, slope rms along
// x and z, the mean Jacobian and the share of the surface squeezed below J = 0.7.
std::vector<double> sea_statistics(const std::string& dir) {
    const Export e = read_export(dir);
    const auto h = e.map(dir, "height.pfm"), sx = e.map(dir, "slope_x.pfm"), sz = e.map(dir, "slope_z.pfm"),
               j = e.map(dir, "jacobian.pfm");
    auto rms = [](const std::vector<double>& v) {
        double mean = 0, square = 0;
        for (double x : v) mean += x / double(v.size());
        for (double x : v) square += (x - mean) * (x - mean) / double(v.size());
        return std::sqrt(square);
    };
    double mean_j = 0, squeezed = 0;
    for (double x : j) mean_j += x / double(j.size()), squeezed += (x < 0.7) / double(j.size());
    return {rms(h), rms(sx), rms(sz), mean_j, squeezed};
}

int same_sea(const std::string& far, const std::vector<std::string>& near) {
    const char* names[] = {"height rms (m)", "slope rms, x", "slope rms, z", "mean Jacobian", "share J < 0.7"};
    const std::vector<double> there = sea_statistics(far);
    std::vector<std::vector<double>> here;
    for (const auto& dir : near) here.push_back(sea_statistics(dir));
    int failures = 0;
    for (std::size_t k = 0; k < there.size(); ++k) {
        double mean = 0, spread = 0;
        for (const auto& s : here) mean += s[k] / double(here.size());
        for (const auto& s : here) spread += (s[k] - mean) * (s[k] - mean) / double(here.size() - 1);
        // Within noise: three standard deviations of the stretches near the origin, and never
        // less than 5 % of the mean (a few stretches can happen to agree closely).
        const double limit = std::max(3 * std::sqrt(spread), 0.05 * std::abs(mean));
        const bool ok = std::abs(there[k] - mean) <= limit;
        std::printf("%-16s far %.4f, near the origin %.4f +- %.4f (limit %.4f)%s\n", names[k], there[k], mean,
                    std::sqrt(spread), limit, ok ? "" : "  FAIL");
        failures += ok ? 0 : 1;
    }
    return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string mode = argc > 1 ? argv[1] : "";
        if (mode == "whitecaps" && argc >= 3) return whitecaps(std::vector<std::string>(argv + 2, argv + argc));
        if (mode == "same_sea" && argc >= 5) return same_sea(argv[2], std::vector<std::string>(argv + 3, argv + argc));
        std::fprintf(stderr, "usage: sea_check whitecaps DIR... | same_sea FAR_DIR NEAR_DIR NEAR_DIR...\n");
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sea_check: %s\n", e.what());
        return 2;
    }
}
