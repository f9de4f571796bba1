#include "step06_foam_sky/extra_waves.hpp"

#include "step06_foam_sky/texture_units.h"

namespace step06 {

void ExtraWaves::upload(const ExtraWaveMaps& maps) {
    if (maps.n <= 0) {
        n_ = 0;
        return;
    }
    if (maps.n != n_) {
        displacement_ = ocean::make_float_texture_2d(GL_RGBA32F, maps.n, maps.n);
        slopes_ = ocean::make_float_texture_2d(GL_RGBA32F, maps.n, maps.n);
        n_ = maps.n;
    }
    ocean::upload_float_texture_2d(displacement_, GL_RGBA32F, n_, n_, maps.displacement.data());
    ocean::upload_float_texture_2d(slopes_, GL_RGBA32F, n_, n_, maps.slopes.data());
    cell_ = maps.cell;
    first_cell_ = maps.first_cell;
}

void ExtraWaves::bind(const ocean::ShaderProgram& p, glm::dvec2 world_origin) const {
    ocean::bind_texture(UNIT_EXTRA_DISPLACEMENT, GL_TEXTURE_2D, displacement_.id());
    ocean::bind_texture(UNIT_EXTRA_SLOPES, GL_TEXTURE_2D, slopes_.id());
    // From the world origin near the camera, in double, then float: small numbers anywhere.
    p.set("u_extra_first_cell", glm::vec2(first_cell_ - world_origin));
    p.set("u_extra_cell", float(cell_));
}

}  // namespace step06
