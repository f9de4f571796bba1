// step08's teaching figure: kelvin_construction.png, README section 5's construction of the
// Kelvin angle from the group velocity (pure geometry: the circles where the energy of the waves
// made t seconds ago has gone, and the edge that touches them all at arcsin(1/3)).
#include "step08_wakes/figures.hpp"

#include "common/constants.hpp"

#include <cmath>

namespace step08 {

namespace {

using figures::Figure;
const char* const kFolder = "step08_wakes";

// step08's Kelvin angle by the group velocity (README section 5): a boat at the origin sailing
// towards +x at U was at P = (-U t, 0) t seconds ago. The waves it made there that keep pace with
// it (phase speed c = U cos theta, theta from the track) carry their energy at the group
// velocity c / 2 along theta: after t it lies at P + (U t / 2) cos theta (cos theta, sin theta), on
// a circle of radius U t / 4 centred at (-3 U t / 4, 0). Every such circle is seen from the boat
// within arcsin((U t / 4) / (3 U t / 4)) = arcsin(1/3) of the track.
Figure kelvin_construction() {
    Figure f("kelvin_construction", kFolder);
    const double kelvin = std::asin(1.0 / 3);
    for (const double behind : {1.0, 0.6}) {  // U t, in units of the larger
        f.data << "# energy of the waves made at (-" << behind << ", 0): x, y for theta from -90 to 90 degrees\n";
        for (int d = -90; d <= 90; d += 2) {
            const double theta = d * ocean::kPi / 180, r = 0.5 * behind * std::cos(theta);
            f.data << -behind + r * std::cos(theta) << ' ' << r * std::sin(theta) << '\n';
        }
        f.data << "\n\n";
    }
    // Where the edge touches the larger circle: the waves there travel at 35.26 degrees (tan = 1/sqrt 2).
    const double cusp = std::atan(1 / std::sqrt(2.0)), r = 0.5 * std::cos(cusp);
    f.data << "# the cusp waves made at (-1, 0): from there to where their energy is\n"
           << -1 << ' ' << 0 << '\n' << -1 + r * std::cos(cusp) << ' ' << r * std::sin(cusp) << "\n\n\n";
    f.data << "# the wake's edge: from the boat at arcsin(1/3) behind\n0 0\n" << -1.15 << ' ' << 1.15 * std::tan(kelvin)
           << "\n\n0 0\n" << -1.15 << ' ' << -1.15 * std::tan(kelvin) << '\n';
    f.script << "set terminal pngcairo size 900,620 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'kelvin_construction.png'\nset bmargin 10\n"
             << "set title \"Kelvin's angle: where the energy of the waves made at O has gone, t seconds later\"\n"
             << "set xlabel \"along the track, in units of U t (the boat at 0, sailing to the right)\"\n"
             << "set ylabel \"across (U t)\"\nset size ratio -1\nset xrange [-1.2:0.1]\nset yrange [-0.45:0.45]\n"
             << "set key outside bottom center horizontal font \",10\"\n"
             << "set label 1 \"O\" at -1.02,-0.04 right\nset label 2 \"boat\" at 0.02,-0.04\n"
             << "set label 3 \"19.47°\" at -0.3,0.035\n"
             << "plot 'kelvin_construction.dat' index 0 with lines ls 1 title \"waves made at O, t ago: energy at (U t / 2) cos θ along θ\", \\\n"
             << "     '' index 1 with lines ls 2 title \"made 0.6 t ago: the same circle, 0.6 times as large\", \\\n"
             << "     '' index 2 with linespoints ls 3 pt 7 ps 0.8 title \"the cusp waves, θ = 35.26°\", \\\n"
             << "     '' index 3 with lines ls 5 title \"the edge: sin α = (U t / 4) / (3 U t / 4) = 1/3\"\n";
    return f;
}

}  // namespace

figures::FigureMakers teaching_figures() { return {kelvin_construction}; }

}  // namespace step08

int main(int argc, char** argv) { return figures::run_main(argc, argv, step08::teaching_figures()); }
