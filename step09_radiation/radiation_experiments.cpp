#include "step09_radiation/radiation_experiments.hpp"

#include "step09_radiation/radiating_buoy.hpp"
#include "step09_radiation/source_hull.hpp"

#include "step07_buoyancy/sea_query.hpp"
#include "step08_wakes/wake_experiments.hpp"

#include "common/constants.hpp"
#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace step09 {

using step08::deep_field;

HeaveRecord release_hemisphere(const HeaveRelease& r) {
    WaveField field(deep_field(r.n, r.cell, 0.2, 3));
    ContactStep contact_step;
    // Per unit density: the mass is the hemisphere's volume, and the contact's pushes are forces.
    const double mass = 2.0 / 3.0 * ocean::kPi * std::pow(r.radius, 3), area = r.cell * r.cell, g = ocean::kGravity;
    // The sphere's underside under each cell, below its centre; cells outside it left out.
    std::vector<std::size_t> under;
    std::vector<double> below_centre;
    for (int j = 0; j < r.n; ++j)
        for (int i = 0; i < r.n; ++i) {
            const glm::dvec2 x = field.cell_centre(i, j);
            const double r2 = r.radius * r.radius - (x.x * x.x + x.y * x.y);
            if (r2 > 0) under.push_back(std::size_t(j) * std::size_t(r.n) + std::size_t(i)), below_centre.push_back(std::sqrt(r2));
        }
    // The columns of still water it displaces with its centre at z.
    const auto displaced = [&](double z) {
        double v = 0;
        for (double b : below_centre) v += std::max(0.0, b - z) * area;
        return v;
    };
    HeaveRecord record;
    double low = -r.radius, high = r.radius;  // the rest: the columns' volume is the mass's
    for (int i = 0; i < 60; ++i) (displaced(0.5 * (low + high)) > mass ? low : high) = 0.5 * (low + high);
    record.rest = 0.5 * (low + high);
    for (double b : below_centre) record.waterplane += b > record.rest ? area : 0;
    double z = record.rest + r.lift, v = 0;
    // Held there until the water has settled: the surface under the hull at its underside (the
    // pressure g d holds it there, exactly: -P / g is the steady state), flat elsewhere.
    if (r.with_waves)
        for (std::size_t c = 0; c < under.size(); ++c) field.heights()[under[c]] = std::min(0.0, z - below_centre[c]);
    const int steps = int(std::lround(r.seconds / r.dt));
    for (int s = 0; s <= steps; ++s) {
        record.time.push_back(s * r.dt);
        record.height.push_back(z - record.rest);
        double force = 0;
        if (r.with_waves) {
            // Where the hull would be at the step's end if the water did not push it, and how much a
            // push moves it: every cell's push lifts the whole body alike (heave only).
            const double coasting = z + (v - g * r.dt) * r.dt;
            Contact contact;
            for (std::size_t c = 0; c < under.size(); ++c)
                if (below_centre[c] > coasting) contact.cells.push_back(under[c]), contact.target.push_back(coasting - below_centre[c]);
            contact.compliance.assign(contact.cells.size() * contact.cells.size(), r.dt * r.dt / mass);
            for (double push : contact_step.step(field, r.dt, contact)) force += push;
        } else {
            force = g * displaced(z);
        }
        v += (force / mass - g) * r.dt;  // semi-implicit Euler: the velocity, then the position with it
        z += v * r.dt;
    }
    return record;
}

namespace {

// The hemisphere of sources of `release`'s radius at the middle of `field`.
SourceHull hemisphere_of(const WaveField& field, const HeaveRelease& release) {
    SourceHullSettings settings;
    settings.radius = release.radius;
    return SourceHull(field, settings);
}
glm::dvec2 grid_middle(const WaveField& field) { return field.cell_centre(field.n() / 2, field.n() / 2); }

}  // namespace

HeaveRecord release_hemisphere_of_sources(const HeaveRelease& r) {
    WaveField field(deep_field(r.n, r.cell, 0.2, 3));
    const SourceHull hull = hemisphere_of(field, r);
    const glm::dvec2 middle = grid_middle(field);
    // Per unit density, as the contact: the mass is the volume, forces are over rho.
    const double mass = hull.volume() + hull.added_mass(), spring = ocean::kGravity * hull.waterplane();
    HeaveRecord record;
    record.waterplane = hull.waterplane();
    double z = r.lift, v = 0;
    Forcing forcing;
    const int steps = int(std::lround(r.seconds / r.dt));
    for (int s = 0; s <= steps; ++s) {
        record.time.push_back(s * r.dt);
        record.height.push_back(z);
        const SourceHull::Reading reading = r.with_waves ? hull.read(field, middle) : SourceHull::Reading{};
        v += (reading.wave_force - spring * z) / mass * r.dt;  // semi-implicit Euler, as the contact's
        z += v * r.dt;
        if (!r.with_waves) continue;
        // The sources that give the hull this step's speed, held over the step as the field's source.
        forcing.source = hull.surface_source(reading, v, 0.5 * r.dt, field, middle);
        field.step(r.dt, forcing);
    }
    return record;
}

HeaveCoefficients force_hemisphere_of_sources(const HeaveRelease& r, double nu, int periods) {
    if (periods < 6 || !(nu > 0)) throw ocean::Error("forced heave: it needs a frequency and six periods (two to start, four to measure)");
    WaveField field(deep_field(r.n, r.cell, 0.2, 3));
    const SourceHull hull = hemisphere_of(field, r);
    const glm::dvec2 middle = grid_middle(field);
    const double omega = std::sqrt(nu * ocean::kGravity / r.radius), period = ocean::kTwoPi / omega, amplitude = 0.05;
    // z = amplitude e(t) sin(omega t), e rising as 3x^2 - 2x^3 over two periods (x = t / 2T), then 1.
    const double ramp = 2 * period;
    const auto speed = [&](double t) {
        const double x = std::min(1.0, t / ramp), e = x * x * (3 - 2 * x), de = 6 * x * (1 - x) / ramp;
        return amplitude * (de * std::sin(omega * t) + e * omega * std::cos(omega * t));
    };
    const auto acceleration = [&](double t) {
        const double x = std::min(1.0, t / ramp), e = x * x * (3 - 2 * x);
        const double de = 6 * x * (1 - x) / ramp, dde = x < 1 ? (6 - 12 * x) / (ramp * ramp) : 0.0;
        return amplitude * ((dde - e * omega * omega) * std::sin(omega * t) + 2 * de * omega * std::cos(omega * t));
    };
    // The force's parts in phase with sin and cos, over whole periods at the end.
    double with_sin = 0, with_cos = 0, span = 0;
    const double from = (periods - 4) * period, to = periods * period;
    Forcing forcing;
    for (int s = 0; s * r.dt < to; ++s) {
        const double t = s * r.dt;
        const SourceHull::Reading reading = hull.read(field, middle);
        const double force = reading.wave_force - hull.added_mass() * acceleration(t);  // the water's, over rho
        if (t >= from) {
            with_sin += force * std::sin(omega * t) * r.dt;
            with_cos += force * std::cos(omega * t) * r.dt;
            span += r.dt;
        }
        forcing.source = hull.surface_source(reading, speed(t + 0.5 * r.dt), 0.5 * r.dt, field, middle);
        field.step(r.dt, forcing);
    }
    // force = -A z'' - B z' = A amplitude omega^2 sin - B amplitude omega cos (the ramp over).
    const double in_sin = 2 * with_sin / span, in_cos = 2 * with_cos / span;
    return {nu, in_sin / (amplitude * omega * omega) / hull.volume(), -in_cos / (amplitude * omega) / (hull.volume() * omega)};
}

HeaveRecord run_buoy(const BuoyRun& run) {
    WaveField field(deep_field(run.n, run.cell, 0.125, 3));
    const SourceHullSettings cap = floating_sphere(run.buoy);
    const glm::dvec2 middle = grid_middle(field);
    const double R = cap.radius, c = cap.centre_height;
    step07::FloatingBody buoy(run.buoy, {middle.x, c + run.lift, middle.y});
    RadiatingBuoy sources(field, buoy);
    HeaveRecord record;
    record.rest = c;
    record.waterplane = ocean::kPi * (R * R - c * c);
    Forcing forcing;
    const int steps = int(std::lround(run.seconds / run.dt));
    for (int s = 0; s <= steps; ++s) {
        const step07::GerstnerSea before({run.swell}, s * run.dt), now({run.swell}, (s + 1) * run.dt);
        const glm::dvec3 at = buoy.position();
        record.time.push_back(s * run.dt);
        record.height.push_back(at.y - c - step07::query(before, {at.x, at.z}).height);
        // As the program: the sources while they hold, step07's body on the sea while they do not.
        if (run.with_waves && sources.holds(field, buoy, before)) {
            forcing.source.clear();
            sources.step(field, buoy, before, now, run.dt, run.dt, forcing);
            field.step(run.dt, forcing);
        } else {
            sources.let_go(buoy);
            buoy.step(before, now, run.dt, run.dt);
            if (run.with_waves) field.step(run.dt);
        }
    }
    return record;
}

Decay measure_decay(const HeaveRecord& record, int crests) {
    std::vector<double> times, heights;
    const std::vector<double>& h = record.height;
    const double dt = record.time.size() > 1 ? record.time[1] - record.time[0] : 0;
    for (std::size_t i = 1; i + 1 < h.size() && int(times.size()) < crests; ++i)
        if (h[i] > h[i - 1] && h[i] >= h[i + 1]) {
            // The parabola through the three samples: its vertex's time and height.
            const double curve = h[i - 1] - 2 * h[i] + h[i + 1], slope = 0.5 * (h[i + 1] - h[i - 1]);
            const double shift = curve < 0 ? -slope / curve : 0;
            times.push_back(record.time[i] + shift * dt);
            heights.push_back(h[i] + 0.5 * slope * shift);
        }
    Decay d;
    d.crests = int(times.size());
    if (times.size() < 2) return d;
    d.period = (times.back() - times.front()) / double(times.size() - 1);
    const double delta = std::log(heights.front() / heights.back()) / double(times.size() - 1);
    d.damping_ratio = delta / std::sqrt(4 * ocean::kPi * ocean::kPi + delta * delta);
    d.natural_frequency = ocean::kTwoPi / d.period / std::sqrt(1 - d.damping_ratio * d.damping_ratio);
    return d;
}

}  // namespace step09
