// Chapter 8.4, a hull under the surface: a floating hemisphere in heave, as sources spread on its
// wetted surface (a panel method), coupled to the wave field.
//
// The contact (wave_field.hpp) holds the surface under a hull where the hull is: a body with no
// draft, a disk on the water. A hemisphere's bottom is a radius deep, where its waves are weaker by
// e^(-k d), and the water flows round it, not only up and down. Linear theory splits the flow it
// makes in two (the same split as the transient Green function's, Cummins 1962):
//   - an instantaneous part: sources of strength sigma (m/s, volume per area and second) on the
//     hull, each with an image sink mirrored above the surface, so that phi = 0 there (the
//     surface's condition at the instant of a sudden motion): 1/(4 pi) (-1/r + 1/r'). Their
//     strengths make the water's speed along the hull's normal the hull's own, each step;
//   - a memory: the waves, which the wave field carries. The sources and their images put water
//     through the surface, sigma e^(-k d) per mode for a source d deep: the field's volume source
//     (Forcing::source). The field's potential reaches down as e^(k y).
// The hull feels the pressure -rho dphi/dt of both on its surface: the first as an added mass that
// moves with it (half the displaced water's, that of a sphere in open water), the second as the
// waves' force, read from the field each step.
//
// The hemisphere heaves about a fixed place of a field that does not follow (the hull's readings are
// made for the grid's cells as they are when it is built). Bands of panels from its bottom to its
// waterline share one source strength: heave is the same all round.
#pragma once

#include "step08_wakes/wave_field.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace step08 {

struct SourceHullSettings {
    double radius = 1;  // m
    int bands = 12;     // rings of panels from the bottom to the waterline, one source strength each
    int around = 36;    // panels round each ring
    int split = 2;      // each panel's integrals taken over split x split parts: an even number, so
                        // that a band's point (its first panel's middle) is never a part's middle
};

class SourceHull {
public:
    // A hemisphere floating at `centre` (x, z) of `field`'s grid, its flat face at the still
    // water's level. Throws ocean::Error on settings it cannot use (a radius not positive, or
    // larger than a quarter of the grid; fewer than one band or three panels round; an odd split).
    SourceHull(const WaveField& field, glm::dvec2 centre, const SourceHullSettings& settings);

    double volume() const;     // m^3, under the water at rest
    double waterplane() const; // m^2, pi R^2
    // The instantaneous part's added mass over the water's density (m^3): rho times it moves with
    // the hull as if it were part of it. Half the volume for a hemisphere (within the panels' error).
    double added_mass() const { return added_mass_; }

    // What the hull reads from the field at one instant: per band, the field's own flow along the
    // hull's normal (m/s), and its rate of change (m/s^2); and the waves' force on the hull over
    // the water's density (m^4/s^2, upwards), their sources' answer to the change included.
    struct Reading {
        std::vector<double> normal_speed, normal_rate;
        double wave_force = 0;
    };
    Reading read(const WaveField& field) const;
    // The sources' strengths (m/s, per band) that give the hull heaving upwards at `heave_speed`
    // (m/s) its own speed along its normal, the field's flow added as `reading` has it `ahead`
    // seconds on (its rate times `ahead`: half a step, to hold the step's middle over the step);
    // and what they put through the surface, a value a cell (m/s), for Forcing::source.
    std::vector<double> strengths(const Reading& reading, double heave_speed, double ahead) const;
    std::vector<double> surface_source(const std::vector<double>& strengths) const;

private:
    // The strengths x with influence x = rhs: influence[i][j] the speed along the normal at band
    // i's point per unit strength on band j, images included; its inverse is made once.
    std::vector<double> solve(const std::vector<double>& rhs) const;

    SourceHullSettings settings_;
    int bands_;
    std::vector<double> band_area_, band_normal_y_;  // m^2; the normals' mean vertical part
    std::vector<double> inverse_influence_;          // bands x bands, row major
    std::vector<double> potential_;  // [i][j]: the potential at band i's point per unit strength on band j
    double added_mass_ = 0;
    // Per band and mode: the band's mean of the field's flow along the normal per unit of the
    // potential's transform (and of its pressure's, per unit of -g eta^); and what a unit strength
    // on the band puts through each cell.
    std::vector<std::vector<Complex>> normal_read_, potential_read_;
    std::vector<std::vector<double>> source_pattern_;
};

}  // namespace step08
