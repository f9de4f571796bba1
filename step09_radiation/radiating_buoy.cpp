#include "step09_radiation/radiating_buoy.hpp"

#include "step07_buoyancy/sea_query.hpp"
#include "step09_radiation/hull_contact.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <cmath>

namespace step09 {

SourceHullSettings floating_sphere(const step07::BodySettings& sphere) {
    if (sphere.shape.kind != step07::ShapeKind::Sphere) throw ocean::Error("radiating buoy: only a sphere has a source hull");
    if (!(sphere.density > 0 && sphere.density < step07::kWaterDensity))
        throw ocean::Error("radiating buoy: a sphere floats only if it is lighter than the water");
    SourceHullSettings s;
    s.radius = 0.5 * sphere.shape.size.x;
    s.bands = 8;
    s.around = 24;
    // The draft d whose cap, pi d^2 (3R - d) / 3, holds the sphere's weight: the cap grows with d,
    // so halving the interval finds it.
    const double R = s.radius, afloat = sphere.density / step07::kWaterDensity * 4.0 / 3.0 * ocean::kPi * R * R * R;
    double low = 0, high = 2 * R;
    for (int i = 0; i < 60; ++i) {
        const double d = 0.5 * (low + high);
        (ocean::kPi * d * d * (3 * R - d) / 3 < afloat ? low : high) = d;
    }
    s.centre_height = R - 0.5 * (low + high);
    return s;
}

RadiatingBuoy::RadiatingBuoy(const WaveField& field, const step07::FloatingBody& buoy)
    : hull_(field, floating_sphere(buoy.settings())) {}

bool RadiatingBuoy::holds(const WaveField& field, const step07::FloatingBody& buoy, const step07::Surface& sea) const {
    if (!within_field(field, buoy)) return false;
    const glm::dvec3 centre = buoy.position();
    const double above = centre.y - step07::query(sea, {centre.x, centre.z}).height;
    return std::abs(above) < 0.5 * buoy.settings().shape.size.x;
}

void RadiatingBuoy::step(const WaveField& field, step07::FloatingBody& buoy, const step07::Surface& from,
                         const step07::Surface& to, double h, double sea_interval, Forcing& forcing) {
    const glm::dvec2 at(buoy.position().x, buoy.position().z);
    const SourceHull::Reading reading = hull_.read(field, at);
    // The sea's heave under the buoy over this step, and how it changed since the last.
    const double sea_speed =
        sea_interval > 0 ? (step07::query(to, at).height - step07::query(from, at).height) / sea_interval : 0.0;
    const double sea_acceleration = stepped_ ? (sea_speed - sea_speed_) / h : 0.0;
    sea_speed_ = sea_speed;
    stepped_ = true;
    // The water's pressure beyond the sea's Archimedes: the wake's waves on the hull, and the added
    // mass's -A (a - a_sea), whose -A a moves to the body's side as inertia.
    const double added = step07::kWaterDensity * hull_.added_mass();
    buoy.set_heave_added_mass(added);
    buoy.add_force({0, step07::kWaterDensity * reading.wave_force + added * sea_acceleration, 0}, glm::dvec3(0.0));
    buoy.step(from, to, h, sea_interval);
    // The sources that give the water the buoy's heave relative to the sea's, over the step.
    const std::vector<double> put = hull_.surface_source(reading, buoy.velocity().y - sea_speed, 0.5 * h, field, at);
    if (forcing.source.size() != put.size()) forcing.source.assign(put.size(), 0.0);
    for (std::size_t c = 0; c < put.size(); ++c) forcing.source[c] += put[c];
}

void RadiatingBuoy::let_go(step07::FloatingBody& buoy) {
    buoy.set_heave_added_mass(0);
    stepped_ = false;
}

}  // namespace step09
