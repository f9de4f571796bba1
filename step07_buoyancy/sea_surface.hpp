// Chapter 7.1: the sea as something to ask questions of. The renderer never needs "how high is the
// water at this world point?": it draws each rest position x where the maps send it, at
// x + (l Dx, h, l Dz). A boat needs exactly that question, and the maps do not answer it directly:
// the height stored at x belongs to the point drawn at x + l D(x), up to a metre or more away.
//
// A Surface gives the displacement of the point resting at x and its derivatives (what step05's
// two maps hold); sea_query.hpp inverts it. Two surfaces here: a sum of Gerstner waves (closed
// form, for the tests) and the cascade maps the renderer draws (bilinear, periodic, summed).
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace step07 {

// At rest position x = (x, z): the displacement (l Dx, h, l Dz) and its derivatives along x and z.
struct SurfaceAt {
    glm::dvec3 displacement{0.0};
    glm::dvec3 d_dx{0.0}, d_dz{0.0};
};

class Surface {
public:
    virtual ~Surface() = default;
    virtual SurfaceAt at(glm::dvec2 rest) const = 0;
    // The displacement of the water resting `depth` metres (>= 0) under the surface point that
    // rests at `rest`. A linear wave of wavenumber k moves the water below it on orbits that
    // shrink as e^(-k depth) (Airy; exactly so for a Gerstner wave's particles), so each wave's
    // share of at(rest).displacement is scaled by e^(-k depth) for its own k. Depth 0: the surface's.
    virtual glm::dvec3 displacement_below(glm::dvec2 rest, double depth) const = 0;
};

// Still water: nothing moves (the Archimedes and heave tests).
class FlatSea : public Surface {
public:
    SurfaceAt at(glm::dvec2) const override { return {}; }
    glm::dvec3 displacement_below(glm::dvec2, double) const override { return glm::dvec3(0.0); }
};

// One Gerstner wave (step05's sign: crests travel along `direction`): theta = k.x - omega t + phase,
// h = A cos(theta), D = -k^ A sin(theta); with steepness kA < 1 a trochoid that does not fold.
struct GerstnerWave {
    double amplitude = 1;    // metres
    double wavelength = 20;  // metres
    glm::dvec2 direction{1.0, 0.0};  // unit
    double phase = 0;
    double wavenumber() const;
    double omega() const;  // deep water: sqrt(g k)
};

// A sum of Gerstner waves at one time.
class GerstnerSea : public Surface {
public:
    GerstnerSea(std::vector<GerstnerWave> waves, double time) : waves_(std::move(waves)), time_(time) {}
    SurfaceAt at(glm::dvec2 rest) const override;
    glm::dvec3 displacement_below(glm::dvec2 rest,
                                  double depth) const override;  // each wave by its own k: exact

private:
    std::vector<GerstnerWave> waves_;
    double time_;
};

// One cascade's maps as step05 lays them out: n x n texels over a tile of `tile` metres, texel
// (i, j) at rest position (i, j) tile / n; per texel (l Dx, h, l Dz, l dDx/dz) and (dh/dx, dh/dz,
// l dDx/dx, l dDz/dz), choppiness l included.
struct CascadeMaps {
    int n = 0;
    double tile = 0;
    std::vector<float> displacement, slopes;  // n * n * 4 each, row (z) major
    // rad/m: the one wavenumber by which this cascade's orbits shrink with depth, e^(-k depth)
    // (sea_maps.hpp's band_wavenumbers); 0: they do not shrink (the surface's motion at every depth).
    double wavenumber = 0;
};

// The sum of the cascades, each read bilinearly and periodically: what the renderer's vertices
// sample at mip level 0.
class MapSea : public Surface {
public:
    explicit MapSea(std::vector<CascadeMaps> cascades) : cascades_(std::move(cascades)) {}
    SurfaceAt at(glm::dvec2 rest) const override;
    // The maps hold the sum of a band's waves, not each wave: a cascade's displacement is scaled
    // as a whole, by e^(-wavenumber depth) with its band's representative wavenumber.
    glm::dvec3 displacement_below(glm::dvec2 rest, double depth) const override;
    const std::vector<CascadeMaps>& cascades() const { return cascades_; }

private:
    std::vector<CascadeMaps> cascades_;
};

}  // namespace step07
