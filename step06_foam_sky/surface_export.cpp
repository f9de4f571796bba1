#include "step06_foam_sky/surface_export.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "step05_fft/export.hpp"

namespace step06 {

void export_surface(const std::string& dir, ocean::ProgramFactory& programs, const step05::OceanSimulation& ocean,
                    const FoamSimulation& foam, const CascadeView& cascades, double time, double choppiness,
                    const SlopeVariance& short_waves, const ocean::ParamRegistry& params) {
    ocean::ShaderProgram* p = programs("surface_grid.comp", {"step06_foam_sky/shaders/surface_grid.comp"}, {});
    if (p == nullptr) throw ocean::Error("surface_grid.comp does not build");
    const FoamWindow& window = foam.window(kExportedFoamLevel);
    const int n = window.n;
    ocean::Texture displacement = ocean::make_texture(GL_TEXTURE_2D), slopes = ocean::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(displacement.id(), 1, GL_RGBA32F, n, n);
    glTextureStorage2D(slopes.id(), 1, GL_RGBA32F, n, n);
    cascades.upload(*p);
    p->set("u_n", n);
    p->set("u_origin", window.origin - window.cell_of(cascades.origin));  // the shader's positions are from the world origin
    p->set("u_texel_size", float(window.texel_size));
    ocean.bind_maps(*p);
    glBindImageTexture(0, displacement.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, slopes.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUseProgram(p->id());
    glDispatchCompute(GLuint((n + 7) / 8), GLuint((n + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);

    std::vector<float> d(std::size_t(n) * n * 4), s(d.size());
    glGetTextureImage(displacement.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(d.size() * sizeof(float)), d.data());
    glGetTextureImage(slopes.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(s.size() * sizeof(float)), s.data());
    const glm::dvec2 first = window.cell_centre(0, 0);
    step05::write_export(dir, n, d, s, window.texel_size * n, time, choppiness, params,
                         {{"export.surface", "sum of the enabled cascades, as rendered and as the foam sees it"},
                          {"export.periodic", "0"},
                          {"export.foam_level", std::to_string(kExportedFoamLevel)},
                          {"export.origin_x", ocean::format_number(first.x)},
                          {"export.origin_z", ocean::format_number(first.y)},
                          {"export.spacing", ocean::format_number(window.texel_size)},
                          {"export.short_wave_slope_variance_upwind", ocean::format_number(short_waves.upwind)},
                          {"export.short_wave_slope_variance_crosswind", ocean::format_number(short_waves.crosswind)}},
                         {{"foam.pfm", "the active foam a, 0..1 (before the renderer's cover)", foam.read_level(kExportedFoamLevel)},
                          {"foam_whole.pfm", "the foam as a whole f, 0..1 (the residual is f - a)", foam.read_whole(kExportedFoamLevel)}});
}

}  // namespace step06
