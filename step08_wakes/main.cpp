// step08_wakes: the waves a boat makes, on step06's sea.
// Beyond the notes. The program composes the earlier chapters' parts: step06's sea, sky, renderer
// and post-processing, step07's bodies and the feed of the sea they float on. To them it adds the
// wave field around step07's boat (wave_field.hpp: each Fourier mode turned at its own frequency
// sqrt(g k tanh kh)), pushed each frame by the boat's hull, a patch of pressure that displaces the
// water the hull does (wake_scene.hpp), and by stones dropped with a click. The field becomes two
// maps in step05's layout (wake_maps.hpp) that step06's shaders add to the cascades
// (extra_waves.glsl): the wake moves the mesh, shades the pixels and folds into foam; the buoy and
// the raft float on the sea with the wake in it (wake_sea.hpp).
// `plan` shows the wake alone from above, a boat at a set speed on still water (plan_view.hpp):
// the lesson's laboratory, where Kelvin's angle is measured.
// The frame, top to bottom, is wake_program.cpp's: step06's frame (its SeaScene, sea_scene.hpp)
// with the bodies drawn into it, and each frame's physics, the bodies and the wake, in a part of
// its own (boat_and_wake.hpp). How the field and the bodies other than the boat take a frame is a
// part again (bodies_and_field.hpp), which a program built on this one may give otherwise.
// Controls: step06's; the arrows (held) steer the boat; a left click drops a stone.
#include "common/app.hpp"
#include "step08_wakes/bodies_and_field.hpp"
#include "step08_wakes/wake_program.hpp"

#include <memory>

namespace {

class Wakes : public step08::WakeProgram {
public:
    Wakes()
        : WakeProgram({"Wakes", "",
                       "The waves a boat makes, on step06's sea: a field of heights and potentials around step07's "
                       "boat, each wave turned at its own frequency sqrt(g k tanh kh), drawn with the sea, foaming "
                       "where it folds, rocking the buoy. Arrows: steer the boat; left click: drop a stone; plan: the "
                       "wake alone, from above.",
                       /*window_samples=*/0},
                      std::make_unique<step08::BodiesAndField>()) {}
};

}  // namespace

OCEAN_MAIN(Wakes)
