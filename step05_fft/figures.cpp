// step05's teaching figures, computed by the chapter's own code (spectrum.hpp, the CPU reference
// simulate_cpu, the pass table), so that the lessons' pictures show what the step does. Into this
// folder: spectrum_lattice.png, jacobian_fold.png and step05_frame.png (README), spectra.png
// (spectrum.md), radix2_by_hand.png and butterfly.png (fft.md). Two show step04's waves beside this
// chapter's and go where step04 finds them: wave_profiles.png (docs/figures: both READMEs show
// it) and fbm_spectrum.png (step04's folder).
#include "step05_fft/figures.hpp"

#include "common/constants.hpp"
#include "step04_fbm/fbm.hpp"
#include "step05_fft/frame_passes.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "tools/frame_path.hpp"

#include <cmath>
#include <complex>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace step05 {

namespace {

using figures::Figure;
constexpr double kPi = ocean::kPi;
const char* const kFolder = "step05_fft";

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

// One travelling mode of wavelength 16 m on a 64 m tile, amplitude 1 m, through step05's CPU
// reference (spectrum slot, time evolution, inverse FFT): the rendered x = x0 + lambda Dx, the
// height, and J = 1 + lambda dDx/dx along the row z = 0.
std::vector<double> one_mode_profile(double steepness, std::vector<double>* x_out, std::vector<double>* jacobian,
                                     std::vector<double>* rest_x = nullptr) {
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

// step04's two wave shapes over two periods, and step05's choppy displacement of one mode at three
// steepnesses (lambda k A = 0.5, 0.9 and 1.3: past 1 the crest folds over itself).
Figure wave_profiles() {
    Figure f("wave_profiles", "docs/figures");  // step04's README shows it too
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

// The bridge from step04 (step05's README): one wave is one pair of lattice points, k and -k,
// holding conjugate numbers; the lattice 2 pi n / L makes every wave fit the tile a whole number
// of times. The height is step05's simulate_cpu of that single pair on a 64 m tile.
Figure spectrum_lattice() {
    Figure f("spectrum_lattice", kFolder);
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
    Figure f("jacobian_fold", kFolder);
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
set title "J = 1 + λ dDx/dx at each vertex: below 0 where the vertices' order reverses (where foam gathers)"
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
Figure spectra() {
    Figure f("spectra", kFolder);
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

// The data flow of a 16-point inverse FFT as fft.comp runs it: two radix-4 Stockham stages. At the
// stage of stride p (1, then 4), thread t < N/4 with k = t mod p reads x[t + j N/4], j = 0..3,
// twiddles them by w^(j k), w = e^{+2 pi i / (4 p)}, and writes the 4-point DFT of the four to
// y[(t - k) 4 + k + q p], q = 0..3 (radix4_stage). The indices are the shader's own formulas.
Figure butterfly() {
    Figure f("butterfly", kFolder);
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
    Figure f("radix2_by_hand", kFolder);
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

// One frame's data path, drawn from the chapter's pass table (frame_passes.hpp).
Figure step05_frame() {
    return figures::frame_path("step05_frame", kFolder,
                               "step05: one frame's passes and what each reads and writes (frame_passes.hpp)", kFramePasses);
}

// step04's fBm as a spectrum: the amplitude of each wave of its default cascades against its
// wavenumber, on log-log axes, where a_i = a_0 gain^i and w_i = w_0 lacunarity^i lie on a line of
// slope log(gain) / log(lacunarity). Beside them, step05's JONSWAP sea of the spectra figure
// (14 m/s over 100 km) as the amplitudes of waves spaced like the fBm's: a = sqrt(2 F(k) k ln 1.18),
// whose tail falls as k^-1 (F ~ k^-3).
Figure fbm_spectrum() {
    Figure f("fbm_spectrum", "step04_fbm");  // step04's README shows it
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

}  // namespace

figures::FigureMakers teaching_figures() {
    return {spectrum_lattice, step05_frame, wave_profiles, jacobian_fold, spectra, radix2_by_hand, butterfly, fbm_spectrum};
}

}  // namespace step05

// step05_fft_figures OUT_DIR writes the figures; --timers prints what --bench must time.
int main(int argc, char** argv) {
    return figures::run_main(argc, argv, step05::teaching_figures(), figures::timed_passes(step05::kFramePasses));
}
