// Chapter 9, the panel method: a hull under the surface, a floating hemisphere in heave, as sources spread on its
// wetted surface (a panel method), coupled to the wave field.
//
// The contact (contact_step.hpp) holds the surface under a hull where the hull is: a body with no
// draft, a disk on the water. A hemisphere's bottom is a radius deep, where its waves are weaker by
// e^(-k d), and the water flows round it, not only up and down. Linear theory splits the flow it
// makes in two (the same split as the transient Green function's, Cummins 1962):
//   - an instantaneous part: sources of strength sigma (m/s, volume per area and second) on the
//     hull, each with an image sink mirrored above the surface, so that phi = 0 there (the
//     surface's condition at the instant of a sudden motion): 1/(4 pi) (-1/r + 1/r'). Their
//     strengths make the water's speed along the hull's normal the hull's own, each step;
//   - a memory: the waves, which the wave field carries. The sources and their images put water
//     through the free surface round the hull: the field's volume source (Forcing::source). How
//     much, mode by mode, Green's second identity over the water gives from the sources' flow and
//     potential on the hull, so none goes through the water plane inside the hull (where the field
//     has a surface the sea has not: fed there, it sloshed and grew; how_we_know.md). The field's
//     potential reaches down as e^(k y).
// The hull feels the pressure -rho dphi/dt of both on its surface: the first as an added mass that
// moves with it (half the displaced water's, that of a sphere in open water), the second as the
// waves' force, read from the field each step through the same table that writes the water the
// hull's heave puts through the surface: what the waves take from the hull, the hull gives them.
//
// The hull is a sphere cut by the still water: a hemisphere when its centre is at the surface,
// step07's buoy (lighter than half its sphere's water) when its centre is above it. Bands of panels
// from its bottom to its waterline share one source strength: heave is the same all round. Its
// readings are made once, relative to its centre, for any place on the grid: the hull may drift
// and the grid follow a boat (a mode's phase at the centre is applied each step).
#pragma once

#include "step09_radiation/contact_step.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace step09 {

struct SourceHullSettings {
    double radius = 1;         // m
    double centre_height = 0;  // m: the sphere's centre above the still water, between -R and R
    int bands = 12;     // rings of panels from the bottom to the waterline, one source strength each
    int around = 36;    // panels round each ring
    int split = 2;      // each panel's integrals taken over split x split parts: an even number, so
                        // that a band's point (its first panel's middle) is never a part's middle
};

class SourceHull {
public:
    // The hull cut by the still water at `settings.centre_height`, for `field`'s grid (its cells
    // and side; the grid may move). Throws ocean::Error on settings it cannot use (a radius not
    // positive, or larger than a quarter of the grid; a centre not within a radius of the surface;
    // fewer than one band or three panels round; an odd split).
    SourceHull(const WaveField& field, const SourceHullSettings& settings);

    double volume() const;      // m^3, under the water at rest: the cap pi d^2 (3R - d) / 3, d = R - c
    double waterplane() const;  // m^2, pi (R^2 - c^2)
    double wetted_area() const; // m^2, the panels' sum: the cap's 2 pi R d
    // The instantaneous part's added mass over the water's density (m^3): rho times it moves with
    // the hull as if it were part of it. Half the volume for a hemisphere (within the panels' error).
    double added_mass() const { return added_mass_; }

    // What the hull centred at `centre` (x, z) reads from the field at one instant: per band, the
    // field's own flow along the hull's normal (m/s), and its rate of change (m/s^2); and the waves'
    // force on the hull over the water's density (m^4/s^2, upwards), their sources' answer to the
    // change included.
    struct Reading {
        std::vector<double> normal_speed, normal_rate;
        double wave_force = 0;
    };
    Reading read(const WaveField& field, glm::dvec2 centre) const;
    // What the sources that give the hull heaving upwards at `heave_speed` (m/s) its own speed
    // along its normal, the field's flow there cancelled as `reading` has it `ahead` seconds on
    // (its rate times `ahead`: half a step, to hold the step's middle over the step), put through
    // the free surface round the hull centred at `centre` (x, z): a value a cell (m/s), for
    // Forcing::source. Found by Green's identity from the sources' flow and potential on the hull,
    // with the table the force is read with, so that the water and the hull trade energy alike.
    std::vector<double> surface_source(const Reading& reading, double heave_speed, double ahead, const WaveField& field,
                                       glm::dvec2 centre) const;

private:
    // The strengths x with influence x = rhs: influence[i][j] the speed along the normal at band
    // i's point per unit strength on band j, images included; its inverse (S) is made once.
    std::vector<double> solve(const std::vector<double>& rhs) const;

    SourceHullSettings settings_;
    int bands_;
    std::vector<double> band_area_;                  // m^2
    std::vector<double> inverse_influence_;          // bands x bands, row major
    double added_mass_ = 0;
    std::vector<double> area_potential_;             // bands x bands: dS_i (potential S)_ij, dS_i band i's area, potential[i][j] at band i's point per unit strength on band j
    // Per band and mode, for the hull centred at the grid's origin: the band's mean of a mode's
    // flow along the normal per unit of the potential's transform, and of its potential. Per mode:
    // the heave's table, the force on the hull per unit of a mode's dphi^/dt, which also writes the
    // water its heave puts through the surface. The panels are mirror-symmetric across x and z, so
    // these are real and the same for (+-kx, +-kz): kept for a quarter of the modes, (|i|, |j|) up
    // to n/2 (quarter()).
    std::size_t quarter(int i, int j) const;
    int cells_ = 0;
    double cell_area_ = 0;
    std::vector<std::vector<double>> normal_read_, potential_read_;
    std::vector<double> heave_;
    // Each mode's phase at `centre`, e^(i k.(centre - x0)), as its x and z factors.
    void phases(const WaveField& field, glm::dvec2 centre, std::vector<Complex>& along_x, std::vector<Complex>& along_z) const;
};

}  // namespace step09
