// Chapter 8, the field: the waves the boat and the stones make, on a square grid that follows the boat.
//
// Linear water waves (the same theory as step05's spectrum) in two fields at the surface: the height
// eta(x, z) and the velocity potential phi(x, z) of the water's flow (its velocity is grad phi).
// For one Fourier mode of wavenumber k, over water of depth h,
//     d eta^ / dt = K phi^ + s^               K = |k| tanh(|k| h)  (|k| in deep water)
//     d phi^ / dt = -g eta^ - P^              P = p / rho, the pressure pushed on the surface
// s a volume source (metres per second: the water a moving hull pushes out of its way). Without
// sources, a mode turns in the (eta^, phi^) plane at omega = sqrt(g K): the dispersion relation
// omega^2 = g k tanh(k h). step() turns every mode by its own omega dt, exactly (the README's "exact step"):
// waves of every length travel at their own speed, whatever dt, and the energy
//     E = rho / 2 * integral of (g eta^2 + phi K phi)    (potential + kinetic)
// is kept to rounding. A pressure held constant over a step is integrated exactly too: the
// constant solution (eta = -P / g) is taken away, the rest turned, and added back (turn_mode,
// which also takes a source s: the boat and the stones push with pressure, a source puts water in).
//
// The grid is periodic (the FFT's), so a wave leaving at one edge would come back at the other:
// an absorbing layer damps eta and phi near the edges (the README's "absorbing layer"). The grid follows the boat by
// whole cells (follow()): the samples move with the grid unchanged, so nothing is smeared.
#pragma once

#include "step08_wakes/fft.hpp"

#include <glm/vec2.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace step08 {

struct WaveFieldSettings {
    int n = 128;                                               // cells a side, a power of two
    double cell = 0.5;                                         // metres
    double depth = std::numeric_limits<double>::infinity();  // metres
    double absorbing_width = 8;                                // metres, at each edge (0: none)
    double absorbing_rate = 3;                                 // 1/s at the very edge, falling as the square to 0 inside
};

// Whether two settings make the same grid (cells, cell size, depth): a field made for one can go
// on under the other (the absorbing layer aside, which the programs derive from these).
bool same_grid(const WaveFieldSettings& a, const WaveFieldSettings& b);

// K = k tanh(k h): what turns a potential into a surface's vertical speed (k in deep water).
double vertical_speed_factor(double wavenumber, double depth);

// What pushes the water during one step, one value a cell (row (z) major), held constant over it;
// an empty vector is none. The boat and the stones push with pressure; a source puts water in at
// the surface (the second forcing linear theory allows: a body that moves water under it).
struct Forcing {
    std::vector<double> pressure;  // p / rho, m^2/s^2: a pressure on the surface
    std::vector<double> source;    // m/s: water put in at the surface, a volume per area and second
};

class WaveField {
public:
    // Throws ocean::Error on settings it cannot run (n not a power of two, a cell or depth not
    // positive, a layer wider than half the grid).
    explicit WaveField(const WaveFieldSettings& settings);
    const WaveFieldSettings& settings() const { return settings_; }
    int n() const { return settings_.n; }
    double side() const { return settings_.n * settings_.cell; }  // metres

    // Advances `dt` seconds (> 0): every mode turned exactly, the forcing held constant, then the
    // absorbing layer applied.
    void step(double dt, const Forcing& forcing = {});

    // Moves the grid by whole cells so that its centre is the cell nearest `centre` (x, z): the
    // samples keep their world positions; those that leave are dropped, the new ones are calm.
    void follow(glm::dvec2 centre);
    // An impulse on the surface (a stone's splash): integral of p / rho over its time and area
    // (m^4/s), spread as a Gaussian of standard deviation `radius` metres around `at`.
    void add_impulse(glm::dvec2 at, double impulse, double radius);

    // Cell (i, j)'s centre in the world (x, z); i along x, j along z.
    glm::dvec2 cell_centre(int i, int j) const;
    // Whether a world point (x, z) lies within the grid (between its outermost cell centres).
    bool covers(glm::dvec2 at) const;
    // The height at a world point, bilinear between cell centres; 0 outside the grid.
    double height_at(glm::dvec2 at) const;
    // The four cells around a world point (x, z) and their bilinear weights, as height_at reads
    // them; false outside the grid.
    struct Taps {
        std::size_t cells[4];
        double weights[4];
    };
    bool bilinear_taps(glm::dvec2 at, Taps& taps) const;

    const std::vector<double>& heights() const { return eta_; }     // n * n, metres
    const std::vector<double>& potentials() const { return phi_; }  // n * n, m^2/s
    std::vector<double>& heights() { return eta_; }                 // for tests and initial states
    std::vector<double>& potentials() { return phi_; }
    // E / rho (J per kg/m^3 = m^5/s^2): g/2 integral eta^2 + 1/2 integral phi K phi, summed over
    // the modes (Parseval).
    double energy() const;
    // Each mode's wavenumber (kx, kz), rad/m, for index (i, j) of the transform.
    glm::dvec2 wavenumber(int i, int j) const;
    // The field's transform (n x n), for what is derived from it (wake_maps.hpp).
    const Fft2d& fft() const { return fft_; }

private:
    std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(settings_.n) + std::size_t(i); }
    void turn(double dt, const Forcing& forcing);  // every mode turned, the layer not applied
    void absorb(double dt);

    WaveFieldSettings settings_;
    Fft2d fft_;
    std::vector<double> eta_, phi_;
    std::vector<double> absorbing_rate_;  // 1/s, a cell
    std::vector<double> speed_factor_;    // K = |k| tanh(|k| h) of each mode, by transform index
    std::int64_t origin_i_ = 0, origin_j_ = 0;  // the grid's centre, in whole cells from the world origin
    mutable std::vector<Complex> work_, forcing_work_;
};

}  // namespace step08
