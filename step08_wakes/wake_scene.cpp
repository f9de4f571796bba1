#include "step08_wakes/wake_scene.hpp"

#include "common/constants.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace step08 {

double hull_pressure(const BoatSettings& boat, glm::dvec2 along_across) {
    const double sigma_along = boat.length / 4, sigma_across = boat.length / 12;
    const double a = along_across.x / sigma_along, b = along_across.y / sigma_across;
    return ocean::kGravity * boat.draft * std::exp(-0.5 * (a * a + b * b));
}

BoatSettings hull_of(double length, double submerged_volume) {
    BoatSettings hull;
    hull.length = length;
    hull.draft = 24 * submerged_volume / (ocean::kPi * length * length);
    return hull;
}

WakeScene::WakeScene(const WaveFieldSettings& field) : field_(field) {
    forcing_.pressure.assign(field_.heights().size(), 0.0);
}

glm::dvec2 WakeScene::boat_heading() const { return {std::cos(heading_), std::sin(heading_)}; }

void WakeScene::sail(double seconds, const BoatSettings& boat, double rudder) {
    if (!(seconds > 0)) return;
    const int steps = std::max(1, int(std::ceil(boat.speed * seconds / field_.settings().cell)));
    const double h = seconds / steps;
    rudder = std::clamp(rudder, -1.0, 1.0);
    for (int s = 0; s < steps; ++s) {
        heading_ += rudder * boat.turn_rate * ocean::kPi / 180 * h;
        const glm::dvec2 ahead = boat_heading();
        press_once(h, position_ + 0.5 * boat.speed * h * ahead, ahead, boat);
        position_ += boat.speed * h * ahead;
    }
}

void WakeScene::place(glm::dvec2 position, glm::dvec2 heading) {
    position_ = position;
    heading_ = std::atan2(heading.y, heading.x);
    field_.follow(position_ - 0.25 * field_.side() * boat_heading());
}

void WakeScene::press(double seconds, glm::dvec2 to, glm::dvec2 heading, const BoatSettings& hull,
                      const FieldStep& step) {
    if (!(seconds > 0)) return;
    const glm::dvec2 from = position_;
    const double from_heading = heading_;
    // The turn taken the short way round.
    const double turn = std::remainder(std::atan2(heading.y, heading.x) - from_heading, 2 * ocean::kPi);
    const int steps = std::max(1, int(std::ceil(glm::length(to - from) / field_.settings().cell)));
    const double h = seconds / steps;
    for (int s = 0; s < steps; ++s) {
        const double middle = (s + 0.5) / steps;
        heading_ = from_heading + middle * turn;
        press_once(h, from + middle * (to - from), boat_heading(), hull, step, double(s) / steps, double(s + 1) / steps);
    }
    position_ = to;
    heading_ = from_heading + turn;
}

void WakeScene::press_once(double h, glm::dvec2 middle, glm::dvec2 ahead, const BoatSettings& hull,
                           const FieldStep& step, double from, double to) {
    field_.follow(middle - 0.25 * field_.side() * ahead);
    const int n = field_.n();
    const glm::dvec2 across(-ahead.y, ahead.x);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 d = field_.cell_centre(i, j) - middle;
            forcing_.pressure[std::size_t(j) * std::size_t(n) + std::size_t(i)] =
                hull_pressure(hull, {d.x * ahead.x + d.y * ahead.y, d.x * across.x + d.y * across.y});
        }
    forcing_.source.clear();
    if (step)
        step(field_, h, forcing_, from, to);
    else
        field_.step(h, forcing_);
}

void WakeScene::drop_stone(glm::dvec2 at, double impulse, double radius) { field_.add_impulse(at, impulse, radius); }

}  // namespace step08
