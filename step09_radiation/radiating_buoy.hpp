// Chapter 9, the radiating buoy in the program: step07's buoy, a sphere, as sources on its wetted surface
// (source_hull.hpp) while it floats within the field. Each step it reads the field where it is,
// moves (step07's Archimedes on the sea without the wake, the wake's force from the reading, and the
// sources' added mass on its heave), and puts the sources that give the water its heave through
// the surface: the waves it makes carry its energy away, and it stops ringing.
//
// Linear theory about the buoy floating still: the panels stay on the cap it wets at rest, wherever
// the sea's waves carry it. The body condition holds its motion relative to the sea's (the water
// round a small body moves with the long waves it rides; what the buoy does beyond that makes
// waves), and the added mass takes the relative acceleration.
#pragma once

#include "step07_buoyancy/floating_body.hpp"
#include "step07_buoyancy/sea_surface.hpp"
#include "step09_radiation/source_hull.hpp"

namespace step09 {

// The source hull of one of step07's spheres floating still: its centre as far above the water as
// its density puts it (the cap under the water weighs what the sphere does); 8 bands of 24 panels,
// whose figures are within 2 % of the tests' 12 of 36 (how_we_know.md) in a third of the time.
SourceHullSettings floating_sphere(const step07::BodySettings& sphere);

class RadiatingBuoy {
public:
    // The sources of `buoy` (a sphere; ocean::Error for any other shape) for `field`'s grid.
    RadiatingBuoy(const WaveField& field, const step07::FloatingBody& buoy);

    // Whether the sources hold for the buoy now: it lies within the field's inner part (its waves
    // are the field's to carry) and is afloat on `sea`, its centre within a radius of the surface
    // (a buoy thrown clear of the water, or pushed under, is not a floating cap).
    bool holds(const WaveField& field, const step07::FloatingBody& buoy, const step07::Surface& sea) const;
    // One step of h seconds while they hold, the sea going from `from` to `to` (`sea_interval`
    // seconds apart): reads the field, moves the buoy, and adds its sources to `forcing.source`
    // for the field's step that follows.
    void step(const WaveField& field, step07::FloatingBody& buoy, const step07::Surface& from, const step07::Surface& to,
              double h, double sea_interval, Forcing& forcing);
    // The buoy let go (it left the field or the water): its added mass back to none, and the sea's
    // speed forgotten.
    void let_go(step07::FloatingBody& buoy);

    const SourceHull& hull() const { return hull_; }

private:
    SourceHull hull_;
    double sea_speed_ = 0;  // the sea's vertical speed under the buoy last step, for its acceleration
    bool stepped_ = false;
};

}  // namespace step09
