// The two maps a simulation leaves for the renderer (OceanSimulation's compute passes and
// FragmentSimulation's fragment passes make the same two): 2D array textures, a layer a cascade,
//   displacement (l Dx, h, l Dz, l dDx/dz) and slopes (dh/dx, dh/dz, l dDx/dx, l dDz/dz).
// What reads them (the sea's draw, a foam pass, height queries on the CPU) takes this, not the
// simulation, so it reads the maps of either.
#pragma once

#include "common/gl_texture.hpp"
#include "common/shader.hpp"

namespace step05 {

struct SimulationMaps {
    GLuint displacement = 0, slopes = 0;

    // Binds them to texture units 0 and 1 and points `program`'s u_displacement and u_slopes at
    // them (a program without one of them ignores it).
    void bind(const ocean::ShaderProgram& program) const {
        program.set("u_displacement", 0);
        program.set("u_slopes", 1);
        ocean::bind_texture(0, GL_TEXTURE_2D_ARRAY, displacement);
        ocean::bind_texture(1, GL_TEXTURE_2D_ARRAY, slopes);
    }
};

}  // namespace step05
