#include "step08_wakes/bodies_and_field.hpp"

#include "step08_wakes/wake_maps.hpp"

namespace step08 {

step06::ExtraWaveMaps BodiesAndField::drawn_wake(const WakeFrame& frame) const {
    return step08::wake_maps(frame.wake.field(), frame.choppiness);
}

}  // namespace step08
