#include "step09_radiation/bodies_in_field.hpp"

#include "step09_radiation/hull_contact.hpp"

namespace step09 {

step08::FieldStep step_with(const BodiesInField& bodies, ContactStep& contact) {
    return [&bodies, &contact](WaveField& field, double h, Forcing& forcing, double from, double to) {
        const SeaBetween sea_from(*bodies.before, *bodies.now, from), sea_to(*bodies.before, *bodies.now, to);
        const double sea_interval = bodies.sea_interval * (to - from);
        for (const Radiating& buoy : bodies.radiating)
            buoy.sources->step(field, *buoy.body, sea_from, sea_to, h, sea_interval, forcing);
        if (bodies.in_contact.empty()) {
            field.step(h, forcing);
            contact.release();
        } else {
            step_with_bodies(field, contact, bodies.in_contact, sea_from, sea_to, h, sea_interval, forcing);
        }
    };
}

}  // namespace step09
