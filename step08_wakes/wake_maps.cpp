#include "step08_wakes/wake_maps.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <cmath>

namespace step08 {

step06::ExtraWaveMaps wake_maps(const WaveField& field, double choppiness, const std::vector<double>* heights_drawn) {
    const int n = field.n();
    const std::size_t cells = std::size_t(n) * std::size_t(n);
    const Fft2d& fft = field.fft();
    std::vector<Complex> heights(cells);
    const std::vector<double>& drawn = heights_drawn != nullptr ? *heights_drawn : field.heights();
    if (drawn.size() != cells) throw ocean::Error("wake maps: heights of the wrong size");
    for (std::size_t c = 0; c < cells; ++c) heights[c] = drawn[c];
    fft.forward(heights);

    // Four complex maps, each carrying two real ones (first + i second): the transform of a real
    // map is Hermitian, so the inverse transform of A + i B is a + i b. Every map is eta^ times a
    // factor (real, or i times real), so each complex map is eta^ times one factor A + i B:
    //   h + i l Dx:           1 + i (i l ux)               = 1 - l ux
    //   l Dz + i l dDx/dz:    i l uz + i (-l kz ux)         = i l (uz - kz ux)
    //   dh/dx + i dh/dz:      i kx + i (i kz)               = -kz + i kx
    //   l dDx/dx + i l dDz/dz: -l kx ux + i (-l kz uz)      = -l (kx ux + i kz uz)
    // with u = k / |k| (D^ = i u eta^; a derivative along x is a factor i kx). The real and
    // imaginary parts are different maps: a factor may add a number without units to one in 1/m.
    std::vector<Complex> height_dx(cells), dz_cross(cells), slopes(cells), stretch(cells);
    const double l = choppiness;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (i == n / 2 || j == n / 2) continue;  // Nyquist: left out (the header says why)
            const std::size_t c = std::size_t(j) * std::size_t(n) + std::size_t(i);
            const glm::dvec2 k = field.wavenumber(i, j);
            const double length = std::hypot(k.x, k.y);
            const glm::dvec2 u = length > 0 ? k / length : glm::dvec2(0.0);
            const Complex eta = heights[c];
            height_dx[c] = (1 - l * u.x) * eta;
            dz_cross[c] = l * (u.y - k.y * u.x) * times_i(eta);
            slopes[c] = times(Complex(-k.y, k.x), eta);
            stretch[c] = -l * times(Complex(k.x * u.x, k.y * u.y), eta);
        }
    for (auto* map : {&height_dx, &dz_cross, &slopes, &stretch}) fft.inverse(*map);

    step06::ExtraWaveMaps maps;
    maps.n = n;
    maps.cell = field.settings().cell;
    maps.first_cell = field.cell_centre(0, 0);
    maps.displacement.resize(4 * cells);
    maps.slopes.resize(4 * cells);
    const double scale = 1.0 / double(cells);  // the inverse transform is unnormalised
    for (std::size_t c = 0; c < cells; ++c) {
        const Complex a = height_dx[c] * scale, b = dz_cross[c] * scale, s = slopes[c] * scale, t = stretch[c] * scale;
        const float displacement[4] = {float(a.imag()), float(a.real()), float(b.real()), float(b.imag())};
        const float slope[4] = {float(s.real()), float(s.imag()), float(t.real()), float(t.imag())};
        for (int q = 0; q < 4; ++q) {
            maps.displacement[4 * c + std::size_t(q)] = displacement[q];
            maps.slopes[4 * c + std::size_t(q)] = slope[q];
        }
    }
    return maps;
}

}  // namespace step08
