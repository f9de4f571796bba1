// step04's teaching figure, computed by the chapter's own fbm.hpp: domain_warp.png, the height
// along one line of the default sea at warp 0, 4 and 8.
#include "step04_fbm/figures.hpp"

#include "step04_fbm/fbm.hpp"

namespace step04 {

namespace {

using figures::Figure;
const char* const kFolder = "step04_fbm";

// step04's domain warp, along one line of its default sea (two cascades of 20 exp-sine waves,
// a0 = 1.2 m, at t = 3 s): the height at warp 0, 4 (the default) and 8, from fbm.hpp. Each wave is
// read at a point the waves before it pushed downhill, so the crests move and lean; the sum of
// independent sines becomes a pattern whose waves interact.
Figure domain_warp() {
    Figure f("domain_warp", kFolder);
    step04::CascadeSettings first;
    first.wave_count = 20;
    first.base_amplitude = 1.2;
    const auto cascades = step04::make_cascades(first, 2, 0.37);
    f.data << "# x  height at warp 0, 4, 8 (z = 0, t = 3 s)\n";
    for (int i = 0; i <= 800; ++i) {
        const double x = i * 0.1;
        f.data << x;
        for (double warp : {0.0, 4.0, 8.0})
            f.data << ' ' << step04::height_gradient(cascades, step04::Shape::ExpSine, warp, x, 0.0, 3.0).height;
        f.data << '\n';
    }
    f.script << R"gp(set title "step04: domain warping along one line of the default sea (z = 0, t = 3 s)"
set xlabel "x (m)"
set ylabel "height (m)"
set key top left horizontal
set yrange [-0.6:2.5]
plot 'domain_warp.dat' using 1:2 with lines ls 5 title "warp 0: a plain sum of waves", \
     '' using 1:3 with lines ls 1 title "warp 4 (default)", \
     '' using 1:4 with lines ls 2 title "warp 8"
)gp";
    return f;
}

}  // namespace

figures::FigureMakers teaching_figures() { return {domain_warp}; }

}  // namespace step04

int main(int argc, char** argv) { return figures::run_main(argc, argv, step04::teaching_figures()); }
