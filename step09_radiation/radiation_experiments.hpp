// The chapter's experiments, run on the CPU in double precision: what the tests hold to Hulme's
// hemisphere and to the energy, so the numbers how_we_know.md quotes are the code's.
#pragma once

#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/sea_surface.hpp"
#include "step09_radiation/contact_step.hpp"

#include <vector>

namespace step09 {

// A floating hemisphere (a sphere of half the water's density) released `lift` metres above its
// rest on calm water, heaving only. `with_waves`: in contact with the wave field (the README's contact: the
// water under it ends each step where its hull is, and pushes it with that pressure); without, the
// still water's buoyancy alone (the columns of water it displaces, cell by cell).
struct HeaveRelease {
    double radius = 1;  // m
    double lift = 0.05; // m
    double seconds = 10;
    double dt = 1.0 / 60;
    bool with_waves = true;
    int n = 128;
    double cell = 0.25;  // m
};
struct HeaveRecord {
    std::vector<double> time, height;  // the centre's height above its rest, each step
    double rest = 0;                   // where that rest is: the centre's height above the still water
    double waterplane = 0;             // m^2: the cells' area under the sphere at rest
};
HeaveRecord release_hemisphere(const HeaveRelease& release);
// The same release with the hemisphere as sources on its wetted surface (source_hull.hpp, the
// README's panel method): linear theory's hull, heaving about its rest with the still water's spring rho g pi R^2
// and the sources' added mass, pushed by the waves it makes. `with_waves` false: no field, the
// spring and the added mass alone. `rest` is 0 (the flat face at the still water's level) and
// `waterplane` pi R^2.
HeaveRecord release_hemisphere_of_sources(const HeaveRelease& release);

// Hulme's own experiment: the hemisphere of sources made to heave 5 cm as sin(omega t) at
// nu = omega^2 R / g (its amplitude brought up smoothly over two periods), on the field of
// `release` (its radius, grid and dt; lift and with_waves unused). The water's force on it over
// the last four of `periods` periods (six or more, else ocean::Error), split into the part in
// phase with its acceleration (the added mass) and the part in phase with its speed (the
// damping), in Hulme's units: A / (rho V) and B / (rho V omega), V = 2/3 pi R^3.
struct HeaveCoefficients {
    double nu = 0, added_mass = 0, damping = 0;
};
HeaveCoefficients force_hemisphere_of_sources(const HeaveRelease& release, double nu, int periods);

// One of step07's spheres (the program's buoy) afloat in a wave field, radiating through its
// sources as the program runs it (radiating_buoy.hpp): released `lift` metres above its rest on
// calm water, or riding a swell (one Gerstner wave; amplitude 0: calm). `with_waves` false:
// step07's body alone (Archimedes and drag, no added mass, no waves). The record's height is the
// sphere's centre above its rest on the sea under it (rest: its centre's height afloat in still
// water); waterplane, the cap's.
struct BuoyRun {
    step07::BodySettings buoy;     // a sphere
    step07::GerstnerWave swell{0.0};
    double lift = 0.05;            // m
    double seconds = 10;
    double dt = 1.0 / 60;
    bool with_waves = true;
    int n = 128;
    double cell = 0.5;             // m
};
HeaveRecord run_buoy(const BuoyRun& run);

// A decaying oscillation read from its first `crests` crests after the release: the damped
// period, the damping ratio (from the logarithmic decrement delta between successive crests,
// zeta = delta / sqrt(4 pi^2 + delta^2)) and the undamped angular frequency.
struct Decay {
    double period = 0, damping_ratio = 0, natural_frequency = 0;
    int crests = 0;
};
Decay measure_decay(const HeaveRecord& record, int crests);

}  // namespace step09
