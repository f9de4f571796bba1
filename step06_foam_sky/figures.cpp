// step06's teaching figures, computed by the chapter's own code (cascades.hpp, short_waves.hpp,
// shading.hpp, the pass table), so that the lessons' pictures show what the step does:
// cascade_bands.png (sea.md), glitter_slopes.png and fresnel.png (light.md), step06_frame.png
// (README). The spectrum figures' sea is step05's (figure_sea).
#include "step06_foam_sky/figures.hpp"

#include "common/constants.hpp"
#include "step05_fft/figures.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/frame_passes.hpp"
#include "step06_foam_sky/shading.hpp"
#include "step06_foam_sky/short_waves.hpp"
#include "tools/frame_path.hpp"

#include <algorithm>
#include <cmath>

namespace step06 {

namespace {

using figures::Figure;
constexpr double kPi = ocean::kPi;
const char* const kFolder = "step06_foam_sky";

// step06's four cascades over the spectrum they share: each tile carries one band of wavenumbers.
Figure cascade_bands() {
    Figure f("cascade_bands", kFolder);
    const step05::SpectrumParams p = step05::figure_sea();
    const auto sizes = step06::cascade_patch_sizes(p);
    const auto bands = step06::cascade_bands(sizes, p.resolution);
    f.data << "# k  k F(k) (the height variance per log k)  k^3 F(k) (the slope variance per log k)\n";
    for (int i = 0; i <= 800; ++i) {
        const double k = std::pow(10.0, -3 + 5.0 * i / 800.0), energy = k * step05::omnidirectional_k(p, k);
        f.data << k << ' ' << energy << ' ' << k * k * energy << '\n';
    }
    const char* colours[] = {"#1f5fa8", "#d9822b", "#3a9a5b", "#a33b8f"};
    f.script << "set title \"step06: four cascades share one spectrum, each tile carries one band (cascades.hpp)\"\n"
             << "set xlabel \"wavenumber k (rad/m)\"\nset ylabel \"k F(k) (m²): height variance per log k\"\n"
             << "set y2label \"k³ F(k): slope variance per log k\"\nset y2tics\nset ytics nomirror\n"
             << "set logscale x\nset xrange [1e-3:1e2]\nset format x \"10^{%L}\"\nset key bottom right\n";
    for (int c = 0; c < step06::kCascades; ++c) {
        const double low = std::max(bands[std::size_t(c)].low, 1e-3), high = bands[std::size_t(c)].high;
        f.script << "set object " << c + 1 << " rect from " << low << ", graph 0 to " << high
                 << ", graph 1 fc rgb '" << colours[c] << "' fs transparent solid 0.15 noborder\n"
                 << "set label " << c + 1 << " \"cascade " << c << "\\n" << std::lround(sizes[std::size_t(c)])
                 << " m tile\" at " << std::sqrt(low * high) << ", graph " << (c % 2 == 0 ? 0.9 : 0.78)
                 << " center tc rgb '" << colours[c] << "'\n";
    }
    f.script << "plot 'cascade_bands.dat' using 1:2 with lines ls 1 lc rgb 'black' title \"height: k F(k), wind 14 m/s, 100 km\", \\\n"
             << "     '' using 1:3 axes x1y2 with lines ls 5 lc rgb '#aa3333' lw 2 title \"slopes: k³ F(k) (right axis): the light\"\n";
    return f;
}

// The sun's glitter: the sea's mean square slope against the wind, step06's (its cascades, and
// with the short waves beyond them) and what Cox and Munk photographed.
Figure glitter_slopes() {
    Figure f("glitter_slopes", kFolder);
    f.data << "# U10  cascades  cascades+short waves  upwind  crosswind  Cox-Munk total  upwind  crosswind\n";
    for (int i = 0; i <= 18; ++i) {
        step05::OceanParams params;
        step06::use_default_sea(params);
        params.spectrum.wind_speed = 2 + i;
        const step05::SpectrumParams& p = params.spectrum;  // step06's default sea at this wind
        const step06::SlopeVariance sea = step06::sea_slope_variance(p);
        const step06::SlopeVariance shorts = step06::short_wave_slope_variance_beyond(p);
        const step06::SlopeVariance cm = step06::cox_munk(p.wind_speed);
        f.data << p.wind_speed << ' ' << sea.total() - shorts.total() << ' ' << sea.total() << ' ' << sea.upwind << ' '
               << sea.crosswind << ' ' << cm.total() << ' ' << cm.upwind << ' ' << cm.crosswind << '\n';
    }
    f.script << "set title \"The glitter's slopes: step06's sea against Cox and Munk's photographs\"\n"
             << "set xlabel \"wind speed at 10 m (m/s)\"\nset ylabel \"mean square slope\"\nset xrange [2:20]\n"
             << "set key top left\nset yrange [0:0.17]\n"
             << R"gp(plot 'glitter_slopes.dat' using 1:6 with lines ls 5 lw 3 lc rgb '#888888' title "Cox and Munk (1954), total", \
     '' using 1:7 with lines ls 5 lc rgb '#d9822b' dt 2 title "Cox and Munk, upwind", \
     '' using 1:8 with lines ls 5 lc rgb '#1f5fa8' dt 2 title "Cox and Munk, crosswind", \
     '' using 1:3 with linespoints ls 1 lc rgb 'black' title "step06: cascades + short waves", \
     '' using 1:4 with points ls 2 lc rgb '#d9822b' title "step06, upwind", \
     '' using 1:5 with points ls 3 lc rgb '#1f5fa8' title "step06, crosswind", \
     '' using 1:2 with linespoints ls 4 lc rgb '#aa3333' title "the cascades alone: the short waves left out"
)gp";
    return f;
}

// Schlick's Fresnel against the exact equations for water, and the notes' slip.
Figure fresnel() {
    Figure f("fresnel", kFolder);
    const double f0 = step06::normal_incidence_reflectance(step06::kWaterIndex);
    f.data << "# angle from the normal (degrees)  exact  Schlick  notes (1 - cos)^5\n";
    for (int i = 0; i <= 900; ++i) {
        const double degrees = 90.0 * i / 900.0, c = std::cos(degrees * kPi / 180);
        f.data << degrees << ' ' << step06::fresnel_dielectric(c, step06::kWaterIndex) << ' '
               << step06::fresnel_schlick(c, f0) << ' ' << std::pow(1 - c, 5) << '\n';
    }
    f.script << R"gp(set title "How much light water reflects: Fresnel for n = 1.333 (shading.hpp)"
set xlabel "angle between the view and the normal (degrees)"
set ylabel "reflectance F"
set xrange [0:90]
set yrange [0:1]
set key top left
set label "F0 = 0.02: looking straight down, water reflects 2 %" at 5, 0.12
plot 'fresnel.dat' using 1:2 with lines ls 1 title "exact (Fresnel's equations, unpolarised)", \
     '' using 1:3 with lines ls 2 title "Schlick, F0 + (1 − F0)(1 − cos θ)^5 (the renderer's)", \
     '' using 1:4 with lines ls 5 title "the notes' (1 − cos θ)^5: forgets F0"
)gp";
    return f;
}

// One frame's data path, drawn from the chapter's pass table (frame_passes.hpp).
Figure step06_frame() {
    return figures::frame_path("step06_frame", kFolder,
                               "step06: one frame's passes and what each reads and writes (frame_passes.hpp)", kFramePasses);
}

}  // namespace

figures::FigureMakers teaching_figures() { return {cascade_bands, glitter_slopes, fresnel, step06_frame}; }

}  // namespace step06

// step06_foam_sky_figures OUT_DIR writes the figures; --timers prints what --bench must time.
int main(int argc, char** argv) {
    return figures::run_main(argc, argv, step06::teaching_figures(), figures::timed_passes(step06::kFramePasses));
}
