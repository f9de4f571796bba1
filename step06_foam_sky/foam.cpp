#include "step06_foam_sky/foam.hpp"

#include "step06_foam_sky/extra_waves.hpp"

#include "step05_fft/box_mipmaps.hpp"
#include "step06_foam_sky/foam_pattern.hpp"
#include "step06_foam_sky/texture_units.h"

#include "common/error.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <string>
#include <utility>

namespace step06 {

FoamWindow foam_window(int level, int n, glm::dvec2 centre) { return window_around(centre, foam_extent(level) / n, n); }

glm::dvec2 foam_window_centre(int level, glm::dvec2 eye_xz, glm::dvec2 forward_xz) {
    const double length = glm::length(forward_xz);
    if (!(length > 1e-6)) return eye_xz;  // looking straight down (or NaN): centred on the camera
    return eye_xz + forward_xz / length * (0.3 * foam_extent(level));
}

std::array<double, kFoamLevels> foam_level_weights(glm::dvec2 p, const std::array<FoamWindow, kFoamLevels>& windows) {
    std::array<double, kFoamLevels> weights{};
    double left = 1;  // the weight the finer levels did not take
    for (int level = 0; level < kFoamLevels; ++level) {
        const FoamWindow& w = windows[std::size_t(level)];
        const double extent = w.texel_size * w.n;
        const glm::dvec2 offset = glm::abs(p - w.centre());
        const double inside = 0.5 * extent - std::max(offset.x, offset.y);  // metres from the edge
        const double weight = std::clamp(inside / (0.1 * extent), 0.0, 1.0);
        weights[std::size_t(level)] = left * weight;
        left *= 1 - weight;
    }
    return weights;
}

void FoamSimulation::resize(int n) {
    if (n == n_ && textures_[0]) return;
    n_ = 0;  // until both textures are made
    for (std::size_t t = 0; t < 2; ++t) {
        // R: the active foam a (stage A); G: the foam as a whole f (the residual, stage B, is f - a),
        // read with it in one fetch. Trilinear and repeating: the toroidal addressing.
        textures_[t] = ocean::make_map_texture_2d_array(GL_RG32F, n, kFoamLevels, step05::mip_levels(n));
        for (int level = 0; level < kFoamLevels; ++level) {
            level_targets_[t][std::size_t(level)] = ocean::make_framebuffer();
            if (!ocean::attach_texture_layer(level_targets_[t][std::size_t(level)], GL_COLOR_ATTACHMENT0, textures_[t],
                                             0, level))
                throw ocean::Error("this GL cannot render into 32-bit float textures (the foam's)");
        }
    }
    no_vertices_ = ocean::make_vertex_array();
    n_ = n;
    fill(0);
    warm_start_ = true;
}

void FoamSimulation::fill(float value) {
    const float both[4] = {value, value, 0, 0};  // the active foam and the foam as a whole
    for (const auto& targets : level_targets_)
        for (const ocean::Framebuffer& target : targets) {
            const ocean::detail::BindForEdit edit(GL_DRAW_FRAMEBUFFER, target.id());
            glClearBufferfv(GL_COLOR, 0, both);
        }
    warm_start_ = false;
}

void FoamSimulation::update(const step05::SimulationMaps& maps, const CascadeView& cascades, glm::dvec2 eye_xz,
                            glm::dvec2 forward_xz, double dt, const FoamSettings& s, const ExtraWaves* extra) {
    const bool with_extra = extra != nullptr && !extra->empty();
    ocean::ShaderProgram* p = programs_("foam.frag", {"common/shaders/fullscreen.vert", "step06_foam_sky/shaders/foam.frag"},
                                        {"EXTRA_WAVES " + std::to_string(int(with_extra))});
    if (p == nullptr) throw ocean::Error("foam.frag does not build");
    const ocean::OffscreenPassState keep(no_vertices_.id());  // what was bound, put back at the end
    glUseProgram(p->id());
    const bool first = std::exchange(warm_start_, false);
    const bool placed = windows_[0].n == n_;  // false before the first update: nothing to move from
    origin_ = cascades.origin;
    for (int level = 0; level < kFoamLevels; ++level) {
        const FoamWindow now = foam_window(level, n_, foam_window_centre(level, eye_xz, forward_xz));
        const FoamWindow& before = placed ? windows_[std::size_t(level)] : now;
        // The shader's cells count from the world origin (a whole number of windows away: the
        // toroidal addressing is the same from either).
        const glm::ivec2 origin_cell = now.cell_of(origin_);
        const std::string index = "[" + std::to_string(level) + "]";
        p->set("u_origin" + index, now.origin - origin_cell);
        p->set("u_previous_origin" + index, before.origin - origin_cell);
        p->set("u_texel_size" + index, float(now.texel_size));
        windows_[std::size_t(level)] = now;
    }
    cascades.upload(*p);
    p->set("u_dt", float(dt));
    p->set("u_threshold", float(s.threshold));
    p->set("u_injection", float(s.injection));
    p->set("u_decay_rate", float(s.decay_rate));
    p->set("u_residual_decay", float(s.residual_decay));
    p->set("u_n", n_);
    p->set("u_warm_start", int(first));
    maps.bind(*p);
    if (with_extra) extra->bind(*p, origin_);
    // Read last frame's foam, write each level of the other texture, then swap.
    const std::size_t next = 1 - current_;
    p->set("u_foam_before", UNIT_FOAM);
    ocean::bind_texture(UNIT_FOAM, GL_TEXTURE_2D_ARRAY, textures_[current_].id());
    glViewport(0, 0, n_, n_);
    for (int level = 0; level < kFoamLevels; ++level) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, level_targets_[next][std::size_t(level)].id());
        p->set("u_level", level);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    ocean::bind_texture(UNIT_FOAM, GL_TEXTURE_2D_ARRAY, 0);  // unbound: the next update writes it
    current_ = next;
    // Distant foam averages instead of sparkling.
    step05::make_mipmaps(programs_, textures_[current_], GL_TEXTURE_2D_ARRAY);
}

FoamSimulation::FoamSimulation(ocean::ProgramFactory programs) : programs_(std::move(programs)) {
    const FoamPatternSettings settings;
    const std::vector<std::uint8_t> texels = foam_pattern_texture(settings);  // r p, g noise, b p^2, a noise
    pattern_ = ocean::make_tiling_colour_texture_2d(settings.size, settings.size, texels.data());
    const std::vector<std::uint8_t> lines = streak_lines_texture(settings);
    streak_lines_ = ocean::make_tiling_colour_texture_2d(settings.size, settings.size, lines.data());
}

void FoamSimulation::bind_streak_lines(const ocean::ShaderProgram& program, int unit) const {
    program.set("u_streak_lines", unit);
    ocean::bind_texture(GLuint(unit), GL_TEXTURE_2D, streak_lines_.id());
}

void FoamSimulation::bind_pattern(const ocean::ShaderProgram& program, int unit) const {
    program.set("u_foam_pattern", unit);
    program.set("u_foam_pattern_size", kPatternSize);
    // World (x, z) to the pattern's coordinates of the streaks' lines, meander and breaks
    // (foam_pattern.hpp): the wind's heading and the heading across it, each over its tile's metres.
    const glm::vec2 along = wind_along_, across(-along.y, along.x);
    program.set("u_streak_along", along / float(kPatternSize * kStreakLength));
    program.set("u_streak_across", across / float(kPatternSize * kStreakSpacing));
    program.set("u_meander_along", along / float(kMeanderLength));
    program.set("u_meander_across", across / float(kMeanderWidth));
    program.set("u_break_along", along / float(kBreakLength));
    program.set("u_break_across", across / float(kBreakWidth));
    program.set("u_streak_meander", float(kStreakMeander));
    program.set("u_streak_share", float(streak_share_));
    ocean::bind_texture(GLuint(unit), GL_TEXTURE_2D, pattern_.id());
}

void FoamSimulation::set_wind(glm::dvec2 heading, double speed) {
    wind_along_ = glm::vec2(heading);
    streak_share_ = foam_streak_share(speed);
}

void FoamSimulation::bind(const ocean::ShaderProgram& program, int unit) const {
    std::vector<glm::vec2> centres;
    std::vector<float> extents;
    for (const FoamWindow& w : windows_) {
        centres.emplace_back(w.centre() - origin_);  // relative to the world origin, as the shaders' positions are
        extents.push_back(float(w.texel_size * w.n));
    }
    program.set("u_foam", unit);
    program.set("u_foam_centre", centres);
    program.set("u_foam_extent", extents);
    ocean::bind_texture(GLuint(unit), GL_TEXTURE_2D_ARRAY, texture());
}

std::vector<float> FoamSimulation::read_channel(int level, int channel) const {
    const std::vector<float> texels = ocean::read_texture_layer(texture(), 0, level, n_);  // RGBA
    std::vector<float> stored(std::size_t(n_) * n_);
    for (std::size_t i = 0; i < stored.size(); ++i) stored[i] = texels[4 * i + std::size_t(channel)];
    return in_world_order(stored, level);
}

std::vector<float> FoamSimulation::read_whole(int level) const { return read_channel(level, 1); }

std::vector<float> FoamSimulation::read_level(int level) const { return read_channel(level, 0); }

std::vector<float> FoamSimulation::in_world_order(const std::vector<float>& stored, int level) const {
    std::vector<float> world(stored.size());
    const glm::ivec2 origin = windows_[std::size_t(level)].origin;
    for (int j = 0; j < n_; ++j)
        for (int i = 0; i < n_; ++i) {
            const int ti = (origin.x + i) & (n_ - 1), tj = (origin.y + j) & (n_ - 1);  // toroidal texel
            world[std::size_t(j) * n_ + i] = stored[std::size_t(tj) * n_ + ti];
        }
    return world;
}

}  // namespace step06
