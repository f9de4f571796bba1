#include "step08_wakes/wake_scene.hpp"

#include "common/constants.hpp"

#include <algorithm>
#include <cmath>

namespace step08 {

double hull_pressure(const BoatSettings& boat, glm::dvec2 along_across) {
    const double sigma_along = boat.length / 4, sigma_across = boat.length / 12;
    const double a = along_across.x / sigma_along, b = along_across.y / sigma_across;
    return ocean::kGravity * boat.draft * std::exp(-0.5 * (a * a + b * b));
}

WakeScene::WakeScene(const WaveFieldSettings& field) : field_(field) {
    forcing_.pressure.assign(field_.heights().size(), 0.0);
}

glm::dvec2 WakeScene::boat_heading() const { return {std::cos(heading_), std::sin(heading_)}; }

void WakeScene::sail(double seconds, const BoatSettings& boat, double rudder) {
    if (!(seconds > 0)) return;
    const double cell = field_.settings().cell;
    const int steps = std::max(1, int(std::ceil(boat.speed * seconds / cell)));
    const double h = seconds / steps;
    const int n = field_.n();
    rudder = std::clamp(rudder, -1.0, 1.0);
    for (int s = 0; s < steps; ++s) {
        heading_ += rudder * boat.turn_rate * ocean::kPi / 180 * h;
        // The patch where the boat is in the middle of the step; the grid's centre a quarter of
        // its side behind, so that most of the grid holds the wake.
        const glm::dvec2 ahead = boat_heading(), middle = position_ + 0.5 * boat.speed * h * ahead;
        field_.follow(middle - 0.25 * field_.side() * ahead);
        const glm::dvec2 across(-ahead.y, ahead.x);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec2 d = field_.cell_centre(i, j) - middle;
                forcing_.pressure[std::size_t(j) * std::size_t(n) + std::size_t(i)] =
                    hull_pressure(boat, {d.x * ahead.x + d.y * ahead.y, d.x * across.x + d.y * across.y});
            }
        field_.step(h, forcing_);
        position_ += boat.speed * h * ahead;
    }
}

void WakeScene::drop_stone(glm::dvec2 at, double impulse, double radius) { field_.add_impulse(at, impulse, radius); }

}  // namespace step08
