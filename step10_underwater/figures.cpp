// step10's teaching figures, computed by the chapter's own code (optics.hpp, caustics_reference.hpp,
// lens.hpp): fresnel_both_ways.png, the share of light the surface reflects from either side, and
// caustic_floor.png, the floor under one wave at depths around the crests' focus.
#include "step10_underwater/figures.hpp"

#include "common/constants.hpp"
#include "step10_underwater/caustics_reference.hpp"
#include "step10_underwater/lens.hpp"
#include "step10_underwater/optics.hpp"

#include <cmath>

namespace step10 {

namespace {

using figures::Figure;
const char* const kFolder = "step10_underwater";
constexpr double kDegree = ocean::kPi / 180;

// R against the angle from the normal, light going down into the water and up out of it: from
// below it climbs to 1 at the critical angle, 48.6 degrees, where Snell's window ends.
Figure fresnel_both_ways() {
    Figure f("fresnel_both_ways", kFolder);
    f.data << "# angle from the normal (degrees), R from the air, R from the water\n";
    for (double degrees = 0; degrees <= 90.0001; degrees += 0.25)
        f.data << degrees << ' ' << fresnel_reflectance(degrees * kDegree, 1.0, kWaterIndex) << ' '
               << reflectance_water_to_air(degrees * kDegree) << '\n';
    const double critical = critical_angle() / kDegree;
    f.script << "set title \"The share of light the surface reflects, from either side (optics.hpp)\"\n"
             << "set xlabel \"angle from the normal (degrees)\"\nset ylabel \"reflectance R\"\n"
             << "set xrange [0:90]\nset yrange [0:1.05]\nset xtics 0,10,90\nset key top left\n"
             << "set arrow from " << critical << ",0 to " << critical << ",1.05 nohead ls 5\n"
             << "set label sprintf(\"critical angle %.1f°\", " << critical << ") at " << critical + 1
             << ",0.55\n"
             << "plot 'fresnel_both_ways.dat' using 1:2 with lines ls 1 title \"from the air, going in\", \\\n"
             << "     '' using 1:3 with lines ls 2 title \"from the water, going out\"\n";
    return f;
}

// The floor under h = a cos(k x) (a = 5 cm, 2 m waves, the sun overhead), relative to the sun's
// light on a level plane, over one wavelength at four depths; and the pattern's contrast against
// depth, peaking at the crests' focal depth n / ((n - 1) a k^2) and falling past it.
Figure caustic_floor() {
    Figure f("caustic_floor", kFolder);
    CausticSea sea;
    sea.bins = 400;
    sea.rays = 400000;
    const double focus = crest_focal_depth(sea);
    const double fractions[] = {0.25, 0.5, 1.0, 2.0};
    for (double fraction : fractions) {
        sea.depth = fraction * focus;
        const SeabedIrradiance floor = seabed_irradiance(sea);
        f.data << "# depth " << sea.depth << " m: x (m, 0 under a crest), irradiance\n";
        const double wavelength = ocean::kTwoPi / sea.wavenumber;
        const std::size_t bins = floor.irradiance.size();
        for (std::size_t j = 0; j < bins; ++j) {  // from the trough at -wavelength / 2, the crest in the middle
            const std::size_t i = (j + bins / 2) % bins;
            double x = (double(i) + 0.5) * wavelength / double(bins);
            if (x > wavelength / 2) x -= wavelength;
            f.data << x << ' ' << floor.irradiance[i] << '\n';
        }
        f.data << "\n\n";
    }
    f.data << "# depth over the focal depth, contrast (std / mean)\n";
    for (double fraction = 0.05; fraction <= 3.0001; fraction += 0.05) {
        sea.depth = fraction * focus;
        f.data << fraction << ' ' << seabed_irradiance(sea).contrast() << '\n';
    }
    f.script << "set terminal pngcairo size 1000,440 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'caustic_floor.png'\n"
             << "set multiplot layout 1,2 title sprintf(\"The floor under one wave, 2 m long, a = 5 cm, the sun overhead: "
                "its crests focus %.1f m down (caustics\\\\_reference.hpp)\", "
             << focus << ")\n"
             << "set title \"the light across one wave, at four depths\"\n"
             << "set xlabel \"across the wave (m; a crest at 0)\"\nset ylabel \"irradiance (sun on a level plane = 1)\"\n"
             << "set logscale y\nset yrange [0.1:100]\nset xrange [-1:1]\nset key top right\n"
             << "plot 'caustic_floor.dat' index 0 with lines ls 3 title \"f / 4\", \\\n"
             << "     '' index 1 with lines ls 1 title \"f / 2\", \\\n"
             << "     '' index 2 with lines ls 2 title \"f\", \\\n"
             << "     '' index 3 with lines ls 4 title \"2 f\"\n"
             << "unset logscale y\nset autoscale y\n"
             << "set title \"contrast against depth\"\nset xlabel \"depth / focal depth f\"\n"
             << "set ylabel \"std / mean\"\nset xrange [0:3]\nset key top right\n"
             << "set arrow from 1,graph 0 to 1,graph 1 nohead ls 5\n"
             << "plot '' index 4 with lines ls 1 title \"the floor's contrast\"\n"
             << "unset multiplot\n";
    return f;
}

}  // namespace

figures::FigureMakers teaching_figures() { return {fresnel_both_ways, caustic_floor}; }

}  // namespace step10

int main(int argc, char** argv) { return figures::run_main(argc, argv, step10::teaching_figures()); }
