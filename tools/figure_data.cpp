// figure_data OUT_DIR: the numbers behind the teaching figures (./ocean figures), computed by the
// chapters' own code, so a figure cannot drift from what the steps do. For each figure NAME it
// writes NAME.dat (columns of numbers) and NAME.gp (the gnuplot script that draws NAME.png from
// them). ./ocean figures runs gnuplot on the scripts.
#include "common/camera.hpp"
#include "common/file_output.hpp"
#include "step02_sine3d/wave_params.hpp"
#include "step03_lighting/normals.hpp"
#include "step04_fbm/fbm.hpp"
#include "step05_fft/frame_passes.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/spectrum.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/frame_passes.hpp"
#include "step06_foam_sky/shading.hpp"
#include "step06_foam_sky/short_waves.hpp"
#include "step07_buoyancy/bodies.hpp"
#include "step07_buoyancy/sea_surface.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using step03::Vec3;
constexpr double kPi = ocean::kPi;

// The look every figure shares: a white page, a light grid, the repository's blues.
const char* kStyle = R"gp(set terminal pngcairo size 900,540 font "DejaVu Sans,12" linewidth 1.5
set grid lc rgb "#dddddd"
set key top right box opaque
set border lc rgb "#444444"
set style line 1 lc rgb "#1f5fa8" lw 2
set style line 2 lc rgb "#d9822b" lw 2
set style line 3 lc rgb "#3a9a5b" lw 2
set style line 4 lc rgb "#a33b8f" lw 2
set style line 5 lc rgb "#777777" lw 1.5 dt 2
)gp";

// A figure's two files, built in memory and written whole once the figure is made.
struct Figure {
    std::string name;
    std::ostringstream data, script;
    explicit Figure(const std::string& figure_name) : name(figure_name) {
        script << kStyle << "set output '" << name << ".png'\n";
    }
    // NAME.dat, then NAME.gp: the first one that cannot be written stops it, with its message.
    std::optional<std::string> write(const fs::path& dir) const {
        if (auto error = ocean::write_file(dir / (name + ".dat"), data.str())) return error;
        return ocean::write_file(dir / (name + ".gp"), script.str());
    }
};

// A spectrum of n x n modes on a 64 m tile holding one travelling wave of the given amplitude at
// grid index (i, j): h0 = amplitude / 2 there (the evolution adds its conjugate at -k, so the wave
// is a cosine of that amplitude) and omega from the deep-water dispersion relation.
step05::InitialSpectrum single_mode(int n, int i, int j, double amplitude) {
    step05::InitialSpectrum s;
    s.n = n;
    s.patch_size = 64;
    s.h0.assign(std::size_t(n) * std::size_t(n), 0.0);
    s.omega.assign(s.h0.size(), 0.0);
    s.density.assign(s.h0.size(), 0.0);
    const std::size_t at = std::size_t(j) * std::size_t(n) + std::size_t(i);
    s.h0[at] = amplitude / 2;
    s.omega[at] = step05::dispersion(std::hypot(step05::wavenumber(i, n, 64), step05::wavenumber(j, n, 64)), 1000);
    return s;
}

// step04's two wave shapes over two periods, and step05's choppy displacement of one mode at three
// steepnesses (lambda k A = 0.5, 0.9 and 1.3: past 1 the crest folds over itself).
std::vector<double> one_mode_profile(double steepness, std::vector<double>* x_out, std::vector<double>* jacobian,
                                     std::vector<double>* rest_x = nullptr);

Figure wave_profiles() {
    Figure f("wave_profiles");
    f.data << "# theta  sin  step04's sine (scaled)  exp(sin-1)-mean\n";
    for (int i = 0; i <= 400; ++i) {
        const double theta = -2 * kPi + 4 * kPi * i / 400.0;
        f.data << theta / kPi << ' ' << std::sin(theta) << ' ' << step04::wave_shape(step04::Shape::Sine, theta).value
               << ' ' << step04::wave_shape(step04::Shape::ExpSine, theta).value << '\n';
    }
    f.data << "\n\n# x  height, for lambda k A = 0.5, 0.9, 1.3 (one mode of step05's simulation)\n";
    std::vector<std::vector<double>> xs(3), hs(3);
    const double steepness[3] = {0.5, 0.9, 1.3};
    for (int s = 0; s < 3; ++s) hs[std::size_t(s)] = one_mode_profile(steepness[s], &xs[std::size_t(s)], nullptr);
    for (std::size_t i = 0; i < hs[0].size(); ++i)
        f.data << xs[0][i] << ' ' << hs[0][i] << ' ' << xs[1][i] << ' ' << hs[1][i] << ' ' << xs[2][i] << ' ' << hs[2][i] << '\n';
    f.script << R"gp(set terminal pngcairo size 900,760 font "DejaVu Sans,12" linewidth 1.5
set output 'wave_profiles.png'
set key top center horizontal
set yrange [-1.2:1.9]
set multiplot layout 2,1 title "Wave profiles: what each chapter adds to the crest"
set title "step04's two shapes, of equal crest-to-trough height 1 − e⁻² = 0.86; the sine of steps 01-03 for scale"
set xlabel "angle θ / π (the whole angle: step03 calls it angle_i)"
set ylabel "height / amplitude"
set key at graph 0.99, graph 0.99 right top vertical font ",10"
plot 'wave_profiles.dat' index 0 using 1:2 with lines ls 5 title "sin θ (steps 01-03)", \
     '' index 0 using 1:3 with lines ls 1 title "0.43 sin θ (step04, shape=sine)", \
     '' index 0 using 1:4 with lines ls 2 title "exp(sin θ − 1) − 0.466 (step04)"
set key default
set key top center horizontal box
set title "step05: one FFT mode moved sideways by λD (Gerstner's trochoid), steepness λkA"
set xlabel "x (metres, wavelength 16 m)"
set xrange [-16:16]
set ylabel "height (m)"
plot 'wave_profiles.dat' index 1 using 1:2 with lines ls 1 title "λkA = 0.5", \
     '' index 1 using 3:4 with lines ls 2 title "λkA = 0.9 (nearly a cusp)", \
     '' index 1 using 5:6 with lines ls 4 title "λkA = 1.3 (folds: J < 0)"
unset multiplot
)gp";
    return f;
}

// step04's domain warp, along one line of its default sea (two cascades of 20 exp-sine waves,
// a0 = 1.2 m, at t = 3 s): the height at warp 0, 4 (the default) and 8, from fbm.hpp. Each wave is
// read at a point the waves before it pushed downhill, so the crests move and lean; the sum of
// independent sines becomes a pattern whose waves interact.
Figure domain_warp() {
    Figure f("domain_warp");
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

// One travelling mode of wavelength 16 m on a 64 m tile, amplitude 1 m, through step05's CPU
// reference (spectrum slot, time evolution, inverse FFT): the rendered x = x0 + lambda Dx, the
// height, and J = 1 + lambda dDx/dx along the row z = 0.
std::vector<double> one_mode_profile(double steepness, std::vector<double>* x_out, std::vector<double>* jacobian,
                                     std::vector<double>* rest_x) {
    const int i = 4;  // k = 2 pi 4 / 64 m: a 16 m wave along +x, a vertex every 25 cm
    const double amplitude = 1.0;
    const step05::InitialSpectrum s = single_mode(256, i, 0, amplitude);
    const double k = step05::wavenumber(i, s.n, s.patch_size);
    const step05::OceanMaps maps = step05::simulate_cpu(s, 0.0);
    const double lambda = steepness / (k * amplitude);
    std::vector<double> heights;
    for (int x = 0; x <= s.n; ++x) {
        const std::size_t at = std::size_t(x % s.n);
        const double rest = x * s.patch_size / s.n - 32;
        x_out->push_back(rest + lambda * maps[step05::DisplacementX][at]);
        if (rest_x != nullptr) rest_x->push_back(rest);
        heights.push_back(maps[step05::Height][at]);
        if (jacobian != nullptr) jacobian->push_back(1 + lambda * maps[step05::DDxDx][at]);
    }
    return heights;
}

// The bridge from step04 (step05's README): one wave is one pair of lattice points, k and -k,
// holding conjugate numbers; the lattice 2 pi n / L makes every wave fit the tile a whole number
// of times. The height is step05's simulate_cpu of that single pair on a 64 m tile.
Figure spectrum_lattice() {
    Figure f("spectrum_lattice");
    const int i = 2, j = 1;  // k = (2 pi 2 / 64, 2 pi 1 / 64): two crests across x, one across z
    const step05::InitialSpectrum s = single_mode(16, i, j, 1.0);
    const step05::OceanMaps maps = step05::simulate_cpu(s, 0.0);
    f.data << "# kx kz: the lattice (N = 16, L = 64 m)\n";
    for (int b = 0; b < s.n; ++b)
        for (int a = 0; a < s.n; ++a)
            f.data << step05::wavenumber(a, s.n, s.patch_size) << ' ' << step05::wavenumber(b, s.n, s.patch_size) << '\n';
    const double kx = step05::wavenumber(i, s.n, s.patch_size), kz = step05::wavenumber(j, s.n, s.patch_size);
    f.data << "\n\n# the wave's two points: k, holding A/2, and -k, holding its conjugate\n"
           << kx << ' ' << kz << "\n" << -kx << ' ' << -kz << "\n";
    f.data << "\n\n# x z height: the real wave those two points make, on the tile\n";
    for (int b = 0; b < s.n; ++b) {
        for (int a = 0; a < s.n; ++a)
            f.data << a * s.patch_size / s.n << ' ' << b * s.patch_size / s.n << ' '
                   << maps[step05::Height][std::size_t(b) * s.n + std::size_t(a)] << '\n';
        f.data << '\n';
    }
    f.script << R"gp(set terminal pngcairo size 1000,460 font "DejaVu Sans,12" linewidth 1.5
set output 'spectrum_lattice.png'
set multiplot layout 1,2 title "One wave = one pair of points of the spectrum (step05's simulate\\_cpu, N = 16, L = 64 m)"
set title "the lattice k = 2π(n, m)/L: h̃ is zero except at k and −k"
set xlabel "k_x (rad/m)"
set ylabel "k_z (rad/m)"
set size ratio -1
set key below
plot 'spectrum_lattice.dat' index 0 using 1:2 with points pt 7 ps 0.5 lc rgb '#bbbbbb' title "the grid's wavevectors",      '' index 1 every ::0::0 using 1:2 with points pt 7 ps 2 lc rgb '#1f5fa8' title "k: A/2 e^{iφ}",      '' index 1 every ::1::1 using 1:2 with points pt 7 ps 2 lc rgb '#d9822b' title "−k: its conjugate"
set title "their sum: a real wave fitting the tile 2 × 1 times"
set xlabel "x (m)"
set ylabel "z (m)"
set xrange [0:60]
set yrange [0:60]
set palette defined (-1 '#0b2e59', 0 '#6fa8dc', 1 '#ffffff')
set cblabel "height (m)"
unset key
set view map
set pm3d map interpolate 4,4
splot 'spectrum_lattice.dat' index 2 using 1:2:3 with pm3d
unset multiplot
)gp";
    return f;
}

// The fold itself: where lambda k A > 1 the surface crosses over itself, and J < 0 marks it.
Figure jacobian_fold() {
    Figure f("jacobian_fold");
    std::vector<double> x, j, rest;
    const std::vector<double> h = one_mode_profile(1.3, &x, &j, &rest);
    f.data << "# rest x  rendered x  height  J (lambda k A = 1.3)\n";
    for (std::size_t i = 0; i < h.size(); ++i) f.data << rest[i] << ' ' << x[i] << ' ' << h[i] << ' ' << j[i] << '\n';
    f.script << R"gp(set terminal pngcairo size 900,760 font "DejaVu Sans,12" linewidth 1.5
set output 'jacobian_fold.png'
set key top center horizontal
set multiplot layout 2,1 title "A fold, and the Jacobian that finds it (one mode, λkA = 1.3)"
set title "the rendered surface (x0 + λDx, h): the crest has crossed over itself"
set xlabel "rendered x (m)"
set ylabel "height (m)"
set xrange [-20:20]
set yrange [-1.2:1.9]
plot 'jacobian_fold.dat' using 2:3 with linespoints ls 4 pt 7 ps 0.4 title "surface (points: grid vertices, 25 cm apart at rest)"
set title "J = 1 + λ dDx/dx at each vertex: below 0 where the vertices' order reverses (step06 puts foam there)"
set xlabel "rest x (m)"
set ylabel "J"
set yrange [-0.5:3.2]
plot 'jacobian_fold.dat' using 1:4 with lines ls 1 title "J", 0 with lines ls 5 title "J = 0"
unset multiplot
)gp";
    return f;
}

// S(omega) for a 14 m/s wind: JONSWAP over 100 km, the same with gamma = 1 (its shape without the
// peak enhancement), Pierson-Moskowitz's fully developed sea (unlimited fetch), and Phillips turned
// into S(omega) by dk/domega; the peaks and step05's grid cut-offs.
// The sea the spectrum figures show: step06's default wind (14 m/s over 100 km), 256 modes on a
// 500 m tile.
step05::SpectrumParams figure_sea() {
    step05::SpectrumParams p;
    p.wind_speed = 14;
    p.fetch = 100000;
    p.resolution = 256;
    p.patch_size = 500;
    return p;
}

Figure spectra() {
    Figure f("spectra");
    const step05::SpectrumParams p = figure_sea();
    const double peak = step05::jonswap_peak_omega(p.wind_speed, p.fetch);
    f.data << "# omega  JONSWAP  JONSWAP(gamma=1)  Phillips  Pierson-Moskowitz\n";
    for (int i = 1; i <= 600; ++i) {
        const double omega = 3.0 * i / 600.0;
        const double k = omega * omega / step05::kGravity, dk_domega = 2 * omega / step05::kGravity;
        f.data << omega << ' ' << step05::jonswap(omega, p.wind_speed, p.fetch, 3.3) << ' '
               << step05::jonswap(omega, p.wind_speed, p.fetch, 1.0) << ' '
               << step05::phillips_k(k, p.wind_speed) * dk_domega << ' ' << step05::pierson_moskowitz(omega, p.wind_speed)
               << '\n';
    }
    const double pm_peak = step05::pierson_moskowitz_peak_omega(p.wind_speed);
    // The shortest wave the tile holds is at its corner, (N/2 - 1, N/2 - 1): the Nyquist row, n = N/2, is held at zero.
    const double k_min = 2 * kPi / p.patch_size, k_max = std::sqrt(2.0) * 2 * kPi * (p.resolution / 2 - 1) / p.patch_size;
    const double omega_min = step05::dispersion(k_min, p.depth), omega_max = step05::dispersion(k_max, p.depth);
    f.script << "set title \"Wave spectra S(ω), wind 14 m/s (step05's spectrum.cpp)\"\n"
             << "set xlabel \"ω (rad/s)\"\nset ylabel \"S(ω) (m² s / rad)\"\nset xrange [0:3]\n"
             << "set arrow from " << peak << ", graph 0 to " << peak << ", graph 1 nohead ls 5\n"
             << "set label \"ω_p = " << std::round(peak * 1000) / 1000 << "\" at " << peak + 0.03 << ", graph 0.95 left\n"
             << "set arrow from " << pm_peak << ", graph 0 to " << pm_peak << ", graph 1 nohead ls 5 lc rgb '#a33b8f'\n"
             << "set label \"0.855 g/U = " << std::round(pm_peak * 1000) / 1000 << "\" at " << pm_peak - 0.03
             << ", graph 0.95 right tc rgb '#a33b8f'\n"
             << "set key at graph 0.98, graph 0.55\n"
             << "set arrow from " << omega_min << ", graph 0 to " << omega_min << ", graph 1 nohead ls 5 lc rgb '#aa3333'\n"
             << "set label \"one 500 m tile's longest wave\" at " << omega_min - 0.03 << ", graph 0.5 center rotate by 90 tc rgb '#aa3333'\n"
             << "set label \"its shortest (N = 256, at the\\ngrid's corner): ω = " << std::round(omega_max * 100) / 100 << ", off the plot\" at 1.45, graph 0.22 tc rgb '#aa3333'\n"
             << R"gp(plot 'spectra.dat' using 1:2 with lines ls 1 title "JONSWAP, 100 km fetch (γ = 3.3)", \
     '' using 1:3 with lines ls 2 title "JONSWAP, 100 km, γ = 1: no peak enhancement", \
     '' using 1:5 with lines ls 4 title "Pierson–Moskowitz: fully developed", \
     '' using 1:4 with lines ls 3 title "Phillips (Tessendorf)"
)gp";
    return f;
}

// step06's four cascades over the spectrum they share: each tile carries one band of wavenumbers.
Figure cascade_bands() {
    Figure f("cascade_bands");
    const step05::SpectrumParams p = figure_sea();
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
    Figure f("glitter_slopes");
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
    Figure f("fresnel");
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

// The data flow of a 16-point inverse FFT as fft.comp runs it: two radix-4 Stockham stages. At the
// stage of stride p (1, then 4), thread t < N/4 with k = t mod p reads x[t + j N/4], j = 0..3,
// twiddles them by w^(j k), w = e^{+2 pi i / (4 p)}, and writes the 4-point DFT of the four to
// y[(t - k) 4 + k + q p], q = 0..3 (radix4_stage). The indices are the shader's own formulas.
Figure butterfly() {
    Figure f("butterfly");
    const int n = 16, quarter = n / 4;
    f.data << "# x0 y0 x1 y1 (one line segment a row)\n";
    int stage = 0;
    std::string highlighted;  // one radix-4 butterfly, its sixteen lines (stage p = 4, thread t = 1)
    for (int p = 1; p < n; p *= 4, ++stage)
        for (int t = 0; t < quarter; ++t) {
            const int r = t & (p - 1), out = (t - r) * 4 + r;
            for (int j = 0; j < 4; ++j)
                for (int q = 0; q < 4; ++q) {
                    const std::string line = std::to_string(stage) + ' ' + std::to_string(t + j * quarter) + ' ' +
                                             std::to_string(stage + 1) + ' ' + std::to_string(out + q * p) + '\n';
                    f.data << line;
                    if (p == 4 && t == 1) highlighted += line;
                }
        }
    f.data << "\n\n# the butterfly of thread t = 1 at p = 4: r = 1, inputs 1, 5, 9, 13, outputs 1, 5, 9, 13\n"
           << highlighted;
    f.script << "set terminal pngcairo size 900,640 font \"DejaVu Sans,12\"\nset output 'butterfly.png'\n"
             << "set title \"A 16-point inverse FFT as fft.comp runs it: two radix-4 Stockham stages\"\n"
             << "set xlabel \"stage\"\nset ylabel \"index in the line\"\nset xrange [-0.3:3.6]\nset yrange [-0.5:15.5]\n"
             << "set xtics (\"input x\" 0, \"after stage 0\\n(stride p = 1)\" 1, \"after stage 1\\n(p = 4): output\" 2)\n"
             << "set ytics 1\nunset key\nset style textbox opaque noborder\n"
             << "set label \"thread t, r = t mod p:\\n  a_j = x[t + 4j] ζ_{4p}^{jr},  ζ_{4p} = e^{2πi/4p}\\n"
                "  y[4(t − r) + r + qp] = Σ_j a_j i^{jq}\\n\\none butterfly (stage 1, t = 1):\\n"
                "  four inputs 1, 5, 9, 13\\n  four outputs 1, 5, 9, 13\\n  twiddles e^{2πij/16}\" at 2.15, 12.5 front boxed tc rgb '#d9822b'\n"
             << "plot 'butterfly.dat' index 0 using 1:2:($3-$1):($4-$2) with vectors nohead lc rgb '#9db8d9' lw 1.2, \\\n"
             << "     '' index 1 using 1:2:($3-$1):($4-$2) with vectors nohead lc rgb '#d9822b' lw 3, \\\n"
             << "     '' index 0 using 1:2 with points pt 7 ps 1.2 lc rgb '#222222', '' index 0 using 3:4 with points pt 7 ps 1.2 lc rgb '#222222'\n";
    return f;
}

// The plain radix-2 FFT worked by hand (step05's fft.md): an 8-point inverse transform of a step,
// x = (1, 1, 1, 1, 0, 0, 0, 0), by fft_radix2.comp's rule (bit-reversed read, then stage s joins
// blocks of M = 2^s: X[r] = E[r] + zeta^r O[r], X[r + M] = E[r] - zeta^r O[r], zeta = e^{2 pi i/(2M)}),
// every value on its node; the result checked here against the sum X[n] = sum_m x[m] e^{2 pi i m n / 8}.
std::string complex_label(std::complex<double> z) {
    const auto clean = [](double v) { return std::abs(v) < 5e-13 ? 0.0 : v; };
    const double re = clean(z.real()), im = clean(z.imag());
    char text[64];
    if (im == 0) std::snprintf(text, sizeof text, "%.3g", re);
    else if (re == 0) std::snprintf(text, sizeof text, "%.3gi", im);
    else if (std::abs(std::abs(im) - 1) < 5e-13) std::snprintf(text, sizeof text, "%.3g %s i", re, im < 0 ? "−" : "+");
    else std::snprintf(text, sizeof text, "%.3g %s %.3gi", re, im < 0 ? "−" : "+", std::abs(im));
    return text;
}

Figure radix2_by_hand() {
    Figure f("radix2_by_hand");
    const int n = 8, bits = 3;
    const std::vector<std::complex<double>> x = {1, 1, 1, 1, 0, 0, 0, 0};
    std::vector<std::vector<std::complex<double>>> columns(1, std::vector<std::complex<double>>(n));
    for (int e = 0; e < n; ++e) {
        int reversed = 0;
        for (int b = 0; b < bits; ++b) reversed |= ((e >> b) & 1) << (bits - 1 - b);
        columns[0][std::size_t(e)] = x[std::size_t(reversed)];
    }
    f.data << "# segments: x0 y0 x1 y1 (index 0), twiddles: x y label (index 1), values: x y label (index 2)\n";
    std::ostringstream twiddles;
    for (int s = 0; s < bits; ++s) {
        const int h = 1 << s;
        std::vector<std::complex<double>> next(n);
        for (int b = 0; b < n / 2; ++b) {
            const int k = b & (h - 1), even = 2 * (b - k) + k, odd = even + h;
            const std::complex<double> zeta_k = std::polar(1.0, 2 * kPi * k / (2 * h));
            const auto& in = columns.back();
            next[std::size_t(even)] = in[std::size_t(even)] + zeta_k * in[std::size_t(odd)];
            next[std::size_t(odd)] = in[std::size_t(even)] - zeta_k * in[std::size_t(odd)];
            for (int from : {even, odd})
                for (int to : {even, odd}) f.data << s << ' ' << -from << ' ' << s + 1 << ' ' << -to << '\n';
            if (k > 0) twiddles << s + 0.22 << ' ' << -odd + 0.28 << " \"×ζ_{" << 2 * h << "}^{" << k << "}\"\n";
        }
        columns.push_back(next);
    }
    for (int m = 0; m < n; ++m) {  // the direct sum, in double: the butterflies must give it
        std::complex<double> direct = 0;
        for (int j = 0; j < n; ++j) direct += x[std::size_t(j)] * std::polar(1.0, 2 * kPi * j * m / n);
        if (std::abs(direct - columns.back()[std::size_t(m)]) > 1e-12) throw std::runtime_error("radix2_by_hand: wrong");
    }
    f.data << "\n\n" << twiddles.str() << "\n\n";
    for (std::size_t c = 0; c < columns.size(); ++c)
        for (int e = 0; e < n; ++e)
            f.data << c << ' ' << -e << " \"" << complex_label(columns[c][std::size_t(e)]) << "\"\n";
    f.script << "set terminal pngcairo size 960,560 font \"DejaVu Sans,12\"\nset output 'radix2_by_hand.png'\n"
             << "set title \"An 8-point inverse FFT by hand: x = (1, 1, 1, 1, 0, 0, 0, 0), three radix-2 stages\"\n"
             << "set xrange [-0.45:3.45]\nset yrange [-7.6:0.6]\nset bmargin 5\nunset key\nunset grid\nunset border\n"
             << "set ytics (\"0\" 0, \"1\" -1, \"2\" -2, \"3\" -3, \"4\" -4, \"5\" -5, \"6\" -6, \"7\" -7) nomirror\n"
             << "set ylabel \"index in the line\"\n"
             << "set xtics (\"read bit-reversed:\\nx_0 x_4 x_2 x_6 x_1 x_5 x_3 x_7\" 0, \"stage 0 (M = 1):\\n4 transforms of 2\" 1, "
                "\"stage 1 (M = 2):\\n2 transforms of 4\" 2, \"stage 2 (M = 4):\\nX, the transform of 8\" 3) nomirror\n"
             << "set style textbox opaque noborder\n"
             << "plot 'radix2_by_hand.dat' index 0 using 1:2:($3-$1):($4-$2) with vectors nohead lc rgb '#9db8d9' lw 1.5, \\\n"
             << "     '' index 1 using 1:2:3 with labels font \",10\" tc rgb '#d9822b', \\\n"
             << "     '' index 2 using 1:2:3 with labels boxed font \",11\" tc rgb '#1f3f68'\n";
    return f;
}

// One frame's data path, from a step's own pass table (frame_passes.hpp): the passes down the
// page in the order they run, every buffer and texture across it, and in each cell whether the
// pass reads it (blue), writes it (orange) or both.
std::vector<std::string> split_resources(std::string_view list) {
    std::vector<std::string> names;
    std::istringstream in{std::string(list)};
    for (std::string name; std::getline(in, name, ';');)
        if (!name.empty()) names.push_back(name);
    return names;
}

template <class Passes>
Figure frame_path(const std::string& name, const std::string& title, const Passes& passes) {
    Figure f(name);
    std::vector<std::string> resources;
    auto column = [&](const std::string& r) {
        for (std::size_t i = 0; i < resources.size(); ++i)
            if (resources[i] == r) return int(i);
        resources.push_back(r);
        return int(resources.size()) - 1;
    };
    for (const auto& pass : passes) {
        for (const auto& r : split_resources(pass.reads)) column(r);
        for (const auto& r : split_resources(pass.writes)) column(r);
    }
    const int rows = int(passes.size()), columns = int(resources.size());
    const int width = 780 + 66 * columns, height = 260 + 48 * rows;
    f.script << "set terminal pngcairo noenhanced size " << width << "," << height << " font \"DejaVu Sans,11\"\n"
             << "set output '" << name << ".png'\nunset key\nunset border\nunset tics\nunset grid\n"
             << "set label \"" << title << "\" at screen 0.5, screen " << 1.0 - 18.0 / height << " center font \",13\"\n"
             << "set lmargin at screen " << 620.0 / width << "\nset rmargin at screen " << 1.0 - 160.0 / width << "\n"
             << "set tmargin at screen " << 1.0 - 200.0 / height << "\nset bmargin at screen " << 40.0 / height << "\n"
             << "set xrange [-0.5:" << columns - 0.5 << "]\nset yrange [" << rows - 0.5 << ":-0.5]\n";
    int object = 1;
    for (int c = 0; c < columns; ++c)
        f.script << "set label \"" << resources[std::size_t(c)] << "\" at " << c << ", -0.75 rotate by 40 left font \",10\"\n";
    for (int r = 0; r < rows; ++r) {
        const auto& pass = passes[std::size_t(r)];
        f.script << "set label \"" << r + 1 << ". " << pass.timer << ": " << pass.program << "\" at screen "
                 << 10.0 / width << ", first " << r << " left font \",10\"\n";
        const auto reads = split_resources(pass.reads), writes = split_resources(pass.writes);
        for (int c = 0; c < columns; ++c) {
            const bool read = std::find(reads.begin(), reads.end(), resources[std::size_t(c)]) != reads.end();
            const bool written = std::find(writes.begin(), writes.end(), resources[std::size_t(c)]) != writes.end();
            const char* colour = read && written ? "#a33b8f" : written ? "#d9822b" : read ? "#1f5fa8" : "#f1f1f1";
            const char* mark = read && written ? "RW" : written ? "W" : read ? "R" : "";
            f.script << "set object " << object++ << " rect from " << c - 0.45 << ", " << r - 0.4 << " to " << c + 0.45
                     << ", " << r + 0.4 << " fc rgb '" << colour << "' fs solid noborder behind\n";
            if (*mark) f.script << "set label \"" << mark << "\" at " << c << ", " << r << " center tc rgb 'white' front\n";
        }
    }
    f.script << "set label \"R: the pass reads it   W: writes it   RW: both\" at screen " << 10.0 / width
             << ", screen " << 15.0 / height << " left\n"
             << "plot NaN\n";
    f.data << "# drawn from the pass table; no data\n";
    return f;
}

Figure step05_frame() {
    return frame_path("step05_frame", "step05: one frame's passes and what each reads and writes (frame_passes.hpp)",
               step05::kFramePasses);
}

Figure step06_frame() {
    return frame_path("step06_frame", "step06: one frame's passes and what each reads and writes (frame_passes.hpp)",
               step06::kFramePasses);
}

// The vectors of the lighting model at a point of a wave (a cut through x, y): T, N from step03's
// normals.hpp, V to the eye, L to the sun, H halfway, R the reflection of V.
Figure lighting_vectors() {
    Figure f("lighting_vectors");
    const std::vector<step02::DirectionalWave> waves{{0.0, 12.0, 1.0, 0.0}};  // along +x, 12 m, 1 m high
    f.data << "# x  height\n";
    for (int i = 0; i <= 300; ++i) {
        const double x = -10 + 20.0 * i / 300;
        f.data << x << ' ' << step03::height_and_gradient(waves, x, 0, 0).height << '\n';
    }
    const double x0 = 1.5;
    const step03::HeightGradient g = step03::height_and_gradient(waves, x0, 0, 0);
    const Vec3 t = step03::normalize(step03::tangent(g)), n = step03::normal(g);
    const Vec3 v = step03::normalize({-0.82, 0.57, 0}), l = step03::normalize({0.77, 0.64, 0});
    const Vec3 h = step03::normalize({v.x + l.x, v.y + l.y, v.z + l.z});
    // M, the sun mirrored about N: where a flat mirror along the surface sends the sunlight (Phong's R).
    const double ln = step03::dot(l, n);
    const Vec3 m{2 * ln * n.x - l.x, 2 * ln * n.y - l.y, 0};
    f.data << "\n\n# x y dx dy label\n";
    const double length = 3.0;
    const struct {
        const char* label;
        Vec3 d;
    } arrows[] = {{"T", t}, {"N", n}, {"V (to the eye)", v}, {"L (to the sun)", l}, {"H", h}, {"M", m}};
    for (const auto& a : arrows)
        f.data << x0 << ' ' << g.height << ' ' << length * a.d.x << ' ' << length * a.d.y << " \"" << a.label << "\"\n";
    f.script << R"gp(set title "The vectors of the lighting model at one point (step03's normals.hpp)"
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1
set xrange [-6:8]
set yrange [-2:5]
unset key
plot 'lighting_vectors.dat' index 0 using 1:2 with lines ls 1, \
     '' index 1 using 1:2:3:4 with vectors head filled lw 2 lc rgb '#a33b8f', \
     '' index 1 using ($1+$3*1.12):($2+$4*1.12):5 with labels tc rgb '#222222'
)gp";
    return f;
}

// step02: one directional wave seen from above (x to the right, z down the page, as the "top"
// camera shows it), its height from waves.hpp, its crest lines d.p = lambda (n + 1/4), which are
// perpendicular to d and lambda = 2 pi / w apart, and its direction d.
Figure directional_wave() {
    Figure f("directional_wave");
    const step02::DirectionalWave wave{30.0, 12.0, 1.0, 0.0};  // d at 30 degrees, 12 m, 1 m high
    const step02::Direction d = step02::direction(wave);
    const double lambda = 2 * kPi / step02::angular_wavenumber(wave);
    f.data << "# x z height (t = 0)\n";
    for (int b = 0; b <= 400; ++b)
        for (int a = 0; a <= 400; ++a) {
            const double x = -20 + 0.1 * a, z = -20 + 0.1 * b;
            f.data << x << ' ' << z << ' ' << step02::height({wave}, x, z, 0.0) << '\n';
        }
    f.data << "\n\n# crest lines: d.p = lambda (n + 1/4), where the height is the amplitude\n";
    for (int n = -4; n <= 3; ++n) {
        const double s = lambda * (n + 0.25);
        for (double u : {-40.0, 40.0}) f.data << s * d.x - u * d.z << ' ' << s * d.z + u * d.x << '\n';
        f.data << "\n";
        if (std::abs(step02::height({wave}, s * d.x, s * d.z, 0.0) - wave.amplitude) > 1e-9)
            std::fprintf(stderr, "figure_data: directional_wave: a crest line misses the crest\n");
    }
    const double s0 = lambda * 0.25, side = -9.0;  // the wavelength's arrow, beside the origin
    f.data << "\n# x z dx dz: d (8 m long), then lambda between two crests\n"
           << "0 0 " << 8 * d.x << ' ' << 8 * d.z << '\n'
           << s0 * d.x + side * -d.z << ' ' << s0 * d.z + side * d.x << ' ' << lambda * d.x << ' ' << lambda * d.z << '\n';
    f.script << "set terminal pngcairo size 760,700 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'directional_wave.png'\n"
             << "set title \"step02: one wave a sin(w d·(x, z) − tφ) seen from above (waves.hpp)\"\n"
             << "set xlabel \"x (m)\"\nset ylabel \"z (m), down the page: the view from above\"\n"
             << "set size ratio -1\nset xrange [-20:20]\nset yrange [20:-20]\nunset key\nunset grid\nset clip two\n"
             << "set palette defined (-1 '#0b2e59', 0 '#6fa8dc', 1 '#ffffff')\nset cblabel \"height (m)\"\nset cbrange [-1:1]\n"
             << "set style textbox opaque noborder\n"
             << "set label 1 \"d = (cos α, sin α), α = 30°\\ncrests travel along +d\" at " << 8.6 * d.x + 0.6 << ", "
             << 8.6 * d.z + 0.4 << " left front boxed tc rgb '#a33b8f'\n"
             << "set label 2 \"λ = 2π/w = " << std::lround(lambda) << " m\" at "
             << (s0 + 0.5 * lambda) * d.x + (side - 1.2) * -d.z << ", " << (s0 + 0.5 * lambda) * d.z + (side - 1.2) * d.x
             << " center front boxed tc rgb '#222222'\n"
             << "set label 3 \"crest lines: d·(x, z) = const,\\nperpendicular to d\" at -19, 18 left front boxed tc rgb '#d9822b'\n"
             << R"gp(plot 'directional_wave.dat' index 0 using 1:2:3 with image, \
     '' index 1 using 1:2 with lines lc rgb '#d9822b' lw 2.5, \
     '' index 2 every ::0::0 using 1:2:3:4 with vectors head filled size 1.2,20 lw 3 lc rgb '#a33b8f', \
     '' index 2 every ::1::1 using 1:2:3:4 with vectors heads filled size 0.8,20 lw 2 lc rgb '#222222'
)gp";
    return f;
}

// step02's camera from the side: the vertical plane through the eye and the target of the
// "overview" view (common/camera.cpp), the frustum's top and bottom edges from the inverse of
// projection * view, the eye's forward f and up u, and the sea of step02's default waves along the
// plane. Below: the depth the projection stores against the distance in front of the eye.
Figure camera_frustum() {
    Figure f("camera_frustum");
    ocean::ParamRegistry registry;
    ocean::Camera camera;
    camera.declare_params(registry, ocean::camera_view("overview"));
    step02::WaveParams sea;
    sea.declare(registry);
    const float aspect = 16.0f / 9.0f;
    const glm::mat4 view = camera.view(), projection = camera.projection(aspect);
    const glm::mat4 to_world = glm::inverse(projection * view);
    const glm::vec3 eye = camera.eye(), forward = camera.forward();
    const glm::vec3 heading = glm::normalize(glm::vec3(forward.x, 0, forward.z));
    const glm::vec3 up = glm::cross(glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0))), forward);
    // A point's coordinates in the figure: s along the heading from below the eye, and y.
    auto side = [&](glm::vec3 p) { return glm::vec2(glm::dot(p - eye, heading), p.y); };
    f.data << "# s  height of step02's default sea along the plane (t = 0)\n";
    for (int i = 0; i <= 830; ++i) {
        const double s = -36 + 0.2 * i;
        const glm::vec3 p = eye + heading * float(s);
        f.data << s << ' ' << step02::height(sea.waves(), p.x, p.z, 0.0) << '\n';
    }
    // The frustum's top and bottom edges in this plane, from the eye through the far plane's points
    // (x_ndc = 0, y_ndc = -1 and 1, z_ndc = 1), cut where they leave the figure (s = 130, y = -6).
    const double s_max = 130, y_min = -6;
    const glm::vec2 eye_2d = side(eye), target_2d = side(glm::vec3(camera.target));
    glm::vec2 edge_end[2];
    double edge_angle[2];
    f.data << "\n\n# the frustum's edges in this plane: from the eye to where they leave the figure\n";
    for (int e = 0; e < 2; ++e) {
        const glm::vec4 p = to_world * glm::vec4(0.0f, e == 0 ? -1.0f : 1.0f, 1.0f, 1.0f);
        const glm::vec2 far_point = side(glm::vec3(p) / p.w), along = glm::normalize(far_point - eye_2d);
        const double reach = std::min(along.x > 0 ? (s_max - eye_2d.x) / along.x : 1e9,
                                      along.y < 0 ? (y_min - eye_2d.y) / along.y : 1e9);
        edge_end[e] = eye_2d + along * float(reach);
        edge_angle[e] = std::atan2(double(along.y), double(along.x)) * 180 / kPi;
        f.data << eye_2d.x << ' ' << eye_2d.y << '\n' << edge_end[e].x << ' ' << edge_end[e].y << "\n\n";
    }
    f.data << "\n# x y dx dy: f, u and the world's up (14 m long)\n"
           << eye_2d.x << ' ' << eye_2d.y << ' ' << 14 * glm::dot(forward, heading) << ' ' << 14 * forward.y << '\n'
           << eye_2d.x << ' ' << eye_2d.y << ' ' << 14 * glm::dot(up, heading) << ' ' << 14 * up.y << '\n'
           << eye_2d.x << ' ' << eye_2d.y << " 0 14\n";
    f.data << "\n\n# eye, target\n" << eye_2d.x << ' ' << eye_2d.y << '\n' << target_2d.x << ' ' << target_2d.y << '\n';
    f.data << "\n\n# distance in front of the eye (m)  depth stored, in [0, 1]\n";
    for (int i = 0; i <= 400; ++i) {
        const double distance = camera.near_plane * std::pow(double(camera.far_plane / camera.near_plane), i / 400.0);
        const glm::vec4 clip = projection * view * glm::vec4(eye + forward * float(distance), 1.0f);
        f.data << distance << ' ' << 0.5 * clip.z / clip.w + 0.5 << '\n';
    }
    const double n = camera.near_plane, far = camera.far_plane, half = 2 * far * n / (far + n);
    const glm::vec4 target_clip = projection * view * glm::vec4(glm::vec3(camera.target), 1.0f);
    const double target_depth = 0.5 * target_clip.z / target_clip.w + 0.5;
    const double distance = camera.distance, pitch = camera.pitch_deg, fov = camera.fov_deg;
    f.script << "set terminal pngcairo size 900,880 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'camera_frustum.png'\n"
             << "set multiplot layout 2,1 title \"step02's camera (common/camera.cpp, the overview view): what the view and projection matrices do\"\n"
             << "set size ratio -1\nset xrange [-36:" << s_max << "]\nset yrange [" << y_min << ":50]\nunset key\nset clip two\n"
             << "set title \"from the side: the vertical plane through the eye and the target (fov " << fov << "°, pitch "
             << pitch << "°, distance " << distance << " m)\"\n"
             << "set xlabel \"metres along the view's heading\"\nset ylabel \"y (m)\"\n"
             << "set style textbox opaque noborder\n"
             << "set object 1 polygon from " << eye_2d.x << ',' << eye_2d.y << " to " << edge_end[0].x << ',' << edge_end[0].y
             << " to " << s_max << ',' << y_min << " to " << edge_end[1].x << ',' << edge_end[1].y << " to " << eye_2d.x << ','
             << eye_2d.y << " fc rgb '#d9822b' fs transparent solid 0.12 noborder\n"
             << "set object 2 circle at " << eye_2d.x << ',' << eye_2d.y << " size 28 arc [" << edge_angle[0] << ':'
             << edge_angle[1] << "] fs empty border lc rgb '#d9822b' lw 1.5 front\n"
             << "set label 1 \"eye\" at " << eye_2d.x - 2 << ", " << eye_2d.y - 2 << " right front boxed\n"
             << "set label 9 \"eye = target − distance · f\" at -34, 8 left front boxed\n"
             << "set label 2 \"target\" at " << target_2d.x << ", " << target_2d.y + 4.5 << " center front boxed\n"
             << "set label 3 \"f\" at " << eye_2d.x + 14 * glm::dot(forward, heading) + 1.5 << ", "
             << eye_2d.y + 14 * forward.y - 1.5 << " left front tc rgb '#a33b8f'\n"
             << "set label 4 \"u (the camera's up)\" at " << eye_2d.x + 14.5 * glm::dot(up, heading) + 1 << ", "
             << eye_2d.y + 14.5 * up.y << " left front boxed tc rgb '#1f5fa8'\n"
             << "set label 5 \"world up (0, 1, 0)\" at " << eye_2d.x - 1.5 << ", " << eye_2d.y + 13 << " right front boxed tc rgb '#777777'\n"
             << "set label 6 \"field of view " << fov << "° (vertical)\" at " << eye_2d.x + 30 << ", " << eye_2d.y - 14
             << " left front boxed tc rgb '#d9822b'\n"
             << "set label 7 \"near plane: " << n << " m from the eye\\nfar plane: " << far
             << " m along f, beyond the figure\" at " << s_max - 3 << ", 45 right front boxed font \",10\"\n"
             << "set label 8 \"the sea: step02's default waves\" at 100, -3.8 center front tc rgb '#0b2e59' font \",10\"\n"
             << R"gp(plot 'camera_frustum.dat' index 1 using 1:2 with lines lc rgb '#d9822b' lw 2, \
     '' index 0 using 1:2 with filledcurves y=-6 fc rgb '#6fa8dc' fs solid 0.5 noborder, \
     '' index 0 using 1:2 with lines ls 1, \
     '' index 2 every ::0::0 using 1:2:3:4 with vectors head filled lw 2.5 lc rgb '#a33b8f', \
     '' index 2 every ::1::1 using 1:2:3:4 with vectors head filled lw 2.5 lc rgb '#1f5fa8', \
     '' index 2 every ::2::2 using 1:2:3:4 with vectors head filled lw 1.5 dt 2 lc rgb '#777777', \
     '' index 3 using 1:2 with points pt 7 ps 1.4 lc rgb '#222222'
)gp"
             << "unset object 1\nunset object 2\nunset label\nset size noratio\nset autoscale\nset logscale x\nset format x \"10^{%L}\"\n"
             << "set xrange [" << n << ":" << far << "]\nset yrange [0:1.05]\n"
             << "set title \"the depth the projection stores, (z/w + 1)/2, against the distance in front of the eye\"\n"
             << "set xlabel \"distance along f (m), near plane to far plane\"\nset ylabel \"depth\"\n"
             << "set arrow 1 from " << half << ", graph 0 to " << half << ", graph 1 nohead ls 5\n"
             << "set label 1 \"half the depth values lie within " << std::round(half * 100) / 100
             << " m of the eye: 2 near far / (near + far)\" at " << half * 1.3 << ", 0.35 left boxed\n"
             << "set arrow 2 from " << distance << ", graph 0 to " << distance << ", graph 1 nohead ls 5 lc rgb '#a33b8f'\n"
             << "set label 2 \"the target, " << distance << " m: depth " << std::round(target_depth * 1e4) / 1e4
             << "\" at " << distance / 1.3 << ", 0.6 right boxed tc rgb '#a33b8f'\n"
             << "plot 'camera_frustum.dat' index 4 using 1:2 with lines ls 1\n"
             << "unset multiplot\n";
    return f;
}

// step04's fBm as a spectrum: the amplitude of each wave of its default cascades against its
// wavenumber, on log-log axes, where a_i = a_0 gain^i and w_i = w_0 lacunarity^i lie on a line of
// slope log(gain) / log(lacunarity). Beside them, step05's JONSWAP sea of the spectra figure
// (14 m/s over 100 km) as the amplitudes of waves spaced like the fBm's: a = sqrt(2 F(k) k ln 1.18),
// whose tail falls as k^-1 (F ~ k^-3).
Figure fbm_spectrum() {
    Figure f("fbm_spectrum");
    step04::CascadeSettings first;
    first.wave_count = 20;  // step04's defaults (fbm_params.hpp): 20 waves of 40 m, a0 = 1.2 m, two cascades at 0.37
    first.base_amplitude = 1.2;
    const auto cascades = step04::make_cascades(first, 2, 0.37);
    for (std::size_t c = 0; c < cascades.size(); ++c) {
        f.data << "# cascade " << c << ": w (rad/m)  a (m)\n";
        for (const auto& wave : cascades[c].waves) f.data << wave.wavenumber << ' ' << wave.amplitude << '\n';
        f.data << "\n\n";
    }
    const step05::SpectrumParams p = figure_sea();
    f.data << "# k (rad/m)  the amplitude of one wave per band of ratio 1.18: sqrt(2 F(k) k ln 1.18)\n";
    for (int i = 0; i <= 400; ++i) {
        const double k = std::pow(10.0, -2 + 3.5 * i / 400.0);
        f.data << k << ' ' << std::sqrt(2 * step05::omnidirectional_k(p, k) * k * std::log(first.lacunarity)) << '\n';
    }
    const double slope = std::log(first.gain) / std::log(first.lacunarity);
    const double w0 = cascades[0].waves[0].wavenumber, a0 = cascades[0].waves[0].amplitude;
    // JONSWAP's a k where its tail is a straight line (k = 3 rad/m), for the slope -1 guide.
    const double tail = 3 * std::sqrt(2 * step05::omnidirectional_k(p, 3) * 3 * std::log(first.lacunarity));
    f.script << "set terminal pngcairo size 900,600 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'fbm_spectrum.png'\n"
             << "set title \"step04's fBm as a spectrum: each wave's amplitude against its wavenumber (fbm.hpp)\"\n"
             << "set xlabel \"wavenumber w = 2π/λ (rad/m; step05 calls it k)\"\nset ylabel \"amplitude (m)\"\n"
             << "set logscale xy\nset xrange [0.01:30]\nset yrange [0.003:10]\nset format x \"10^{%L}\"\nset format y \"10^{%L}\"\n"
             << "set key top right font \",10\" spacing 1.2\n"
             << "plot 'fbm_spectrum.dat' index 0 using 1:2 with points pt 7 ps 1.3 lc rgb '#1f5fa8' title \"cascade 0: 20 waves from 40 m, a_0 = 1.2 m\", \\\n"
             << "     '' index 1 using 1:2 with points pt 5 ps 1.1 lc rgb '#d9822b' title \"cascade 1: × 0.37 in wavelength and amplitude\", \\\n"
             << "     " << a0 << " * (x / " << w0 << ")**(" << slope
             << ") with lines ls 5 title \"a_0 (w / w_0)^σ, σ = log 0.82 / log 1.18 = −" << std::round(-slope * 100) / 100 << "\", \\\n"
             << "     '' index 2 using 1:2 with lines ls 3 title \"step05: JONSWAP, 14 m/s over 100 km, as waves 1.18 apart\", \\\n"
             << "     " << tail << " / x with lines ls 5 lc rgb '#3a9a5b' title \"slope −1: its tail, F(k) ∝ k^{−3}\"\n";
    return f;
}

// step07's controls on a flat sea at the defaults (bodies.hpp, the code the window runs): how far
// a right click carries each body (against d(t) = v (1 - e^-ct) / c, the linear drag's closed
// form), and the boat's track from above under the arrows.
Figure push_and_steer() {
    Figure f("push_and_steer");
    const step07::FlatSea calm;
    constexpr double dt = 1.0 / 60;
    std::vector<step07::FloatingBody> bodies = step07::drop_bodies(step07::BodyParams{}, {0, 3, 0}, {1, 0});
    for (int i = 0; i < 15 * 60; ++i)  // settled first: 15 s is plenty on still water
        for (auto& body : bodies) body.step(calm, calm, dt);
    double speeds[3] = {};
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        step07::FloatingBody body = bodies[b];
        speeds[b] = step07::push_speed(body);
        const glm::dvec3 start = body.position();
        f.data << "# " << step07::kBodyNames[b] << ": t (s), distance (m) after a push at " << speeds[b] << " m/s\n";
        body.push(speeds[b] * body.mass() * glm::dvec3(0, 0, 1), body.position());
        for (int i = 0; i <= 3 * 60; ++i) {
            if (i % 3 == 0) f.data << i * dt << ' ' << body.position().z - start.z << '\n';
            body.step(calm, calm, dt);
        }
        f.data << "\n\n";
    }
    // The boat for 5 s: the up arrow alone, then the up and right arrows held together; in its own
    // frame at the start (ahead, and to its right: starboard).
    for (const double rudder : {0.0, 1.0}) {
        step07::FloatingBody boat = bodies[step07::kBoat];
        const glm::dvec3 start = boat.position();
        const glm::dvec3 ahead = boat.orientation() * glm::dvec3(1, 0, 0), right = boat.orientation() * glm::dvec3(0, 0, 1);
        f.data << "# the boat, up arrow" << (rudder > 0 ? " and right arrow" : "") << ": ahead, right (m) every 0.5 s\n";
        for (int i = 0; i <= 5 * 60; ++i) {
            const glm::dvec3 moved = boat.position() - start;
            if (i % 30 == 0) f.data << glm::dot(moved, ahead) << ' ' << glm::dot(moved, right) << '\n';
            step07::steer(boat, 1, rudder);
            boat.step(calm, calm, dt);
        }
        f.data << "\n\n";
    }
    const double c = step07::BodyParams{}.drag;
    const auto closed_form = [&](int b) {
        std::ostringstream e;
        e << speeds[b] << " * (1 - exp(-" << c << " * x)) / " << c;
        return e.str();
    };
    f.script << "set terminal pngcairo size 1000,440 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'push_and_steer.png'\n"
             << "set multiplot layout 1,2 title \"step07's controls on a flat sea, at the defaults (bodies.hpp)\"\n"
             << "set title \"a right click: each body pushed its size (3 to 6 m) in 1 s\"\n"
             << "set xlabel \"time after the push (s)\"\nset ylabel \"distance (m)\"\nset xrange [0:3]\nset key bottom right\n"
             << "plot 'push_and_steer.dat' index 0 with lines ls 1 title \"buoy (1.2 m)\", \\\n"
             << "     '' index 1 with lines ls 2 title \"raft (5 m)\", \\\n"
             << "     '' index 2 with lines ls 3 title \"boat (9 m)\", \\\n"
             << "     " << closed_form(0) << " with lines ls 5 notitle, " << closed_form(1) << " with lines ls 5 notitle, \\\n"
             << "     " << closed_form(2) << " with lines ls 5 title \"v (1 − e^{−ct}) / c\"\n"
             << "set title \"the arrows held 5 s, seen from above (dots 0.5 s apart)\"\n"
             << "set xlabel \"ahead of the boat (m)\"\nset ylabel \"to its right (m)\"\nset autoscale\nset yrange [*:*] reverse\n"
             << "set size ratio -1\nset key bottom right\n"
             << "plot '' index 3 with linespoints ls 1 pt 7 ps 0.6 title \"↑\", \\\n"
             << "     '' index 4 with linespoints ls 2 pt 7 ps 0.6 title \"↑ and →\"\n"
             << "unset multiplot\n";
    return f;
}

// step08's Kelvin angle by the group velocity (README section 5): a boat at the origin sailing
// towards +x at U was at P = (-U t, 0) t seconds ago. The waves it made there that keep pace with
// it (phase speed c = U cos theta, theta from the track) carry their energy at the group
// velocity c / 2 along theta: after t it lies at P + (U t / 2) cos theta (cos theta, sin theta), on
// a circle of radius U t / 4 centred at (-3 U t / 4, 0). Every such circle is seen from the boat
// within arcsin((U t / 4) / (3 U t / 4)) = arcsin(1/3) of the track.
Figure kelvin_construction() {
    Figure f("kelvin_construction");
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

// The timed passes of a step's table, in order, each once: what --bench must list (frame_passes.sh).
template <class Passes>
int print_timers(const Passes& passes) {
    std::vector<std::string> printed;
    for (const auto& pass : passes)
        if (std::find(printed.begin(), printed.end(), std::string(pass.timer)) == printed.end()) {
            printed.emplace_back(pass.timer);
            std::printf("%s\n", printed.back().c_str());
        }
    return 0;
}

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--timers") {
        if (std::string(argv[2]) == "step05_fft") return print_timers(step05::kFramePasses);
        if (std::string(argv[2]) == "step06_foam_sky") return print_timers(step06::kFramePasses);
        return std::fprintf(stderr, "figure_data: no pass table for %s\n", argv[2]), 2;
    }
    if (argc != 2) return std::fprintf(stderr, "usage: figure_data OUT_DIR | figure_data --timers STEP\n"), 2;
    const fs::path dir = argv[1];
    std::error_code error;
    fs::create_directories(dir, error);
    if (error) return std::fprintf(stderr, "figure_data: cannot make %s: %s\n", argv[1], error.message().c_str()), 1;
    const std::vector<std::function<Figure()>> figures{
        wave_profiles, domain_warp, spectrum_lattice, jacobian_fold, spectra, cascade_bands, glitter_slopes, fresnel, butterfly, radix2_by_hand, lighting_vectors, step05_frame, step06_frame,
        directional_wave, camera_frustum, fbm_spectrum, push_and_steer, kelvin_construction};
    for (const auto& make : figures)
        if (auto failure = make().write(dir)) return std::fprintf(stderr, "figure_data: %s\n", failure->c_str()), 1;
    std::printf("figure_data: %zu figures' data and scripts in %s\n", figures.size(), argv[1]);
    return 0;
}
