#include "step08_wakes/wake_maps.hpp"

#include <cmath>

namespace step08 {

step06::LocalWaveMaps wake_maps(const WaveField& field, double choppiness) {
    const int n = field.n();
    const std::size_t cells = std::size_t(n) * std::size_t(n);
    const Fft2d fft(n);
    std::vector<Complex> heights(cells);
    for (std::size_t c = 0; c < cells; ++c) heights[c] = field.heights()[c];
    fft.forward(heights);

    // Four complex maps, each carrying two real ones (first + i second): the transform of a real
    // map is Hermitian, so the inverse transform of A + i B is a + i b.
    const Complex i1(0, 1);
    std::vector<Complex> height_dx(cells), dz_cross(cells), slopes(cells), stretch(cells);
    const double l = choppiness;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t c = std::size_t(j) * std::size_t(n) + std::size_t(i);
            const glm::dvec2 k = field.wavenumber(i, j);
            const double length = std::hypot(k.x, k.y);
            if (i == n / 2 || j == n / 2) continue;  // Nyquist: left out (the header says why)
            const Complex eta = heights[c];
            const glm::dvec2 unit = length > 0 ? k / length : glm::dvec2(0.0);
            const Complex dx = i1 * unit.x * eta, dz = i1 * unit.y * eta;  // D^ = i k^ eta^
            height_dx[c] = eta + i1 * (l * dx);                           // h, l Dx
            dz_cross[c] = l * dz + i1 * (l * i1 * k.y * dx);              // l Dz, l dDx/dz
            slopes[c] = i1 * k.x * eta + i1 * (i1 * k.y * eta);           // dh/dx, dh/dz
            stretch[c] = l * i1 * k.x * dx + i1 * (l * i1 * k.y * dz);    // l dDx/dx, l dDz/dz
        }
    for (auto* map : {&height_dx, &dz_cross, &slopes, &stretch}) fft.inverse(*map);

    step06::LocalWaveMaps maps;
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
