#include "step06_foam_sky/sea_renderer.hpp"

#include "common/frustum.hpp"
#include "common/gl_texture.hpp"
#include "step06_foam_sky/far_plane.hpp"
#include "step06_foam_sky/texture_units.h"

namespace step06 {

void SeaRenderer::declare(ocean::ParamRegistry& p) {
    {
        const auto mesh_group = p.group("mesh");
        p.add_float("tess_scale", &tess_scale_, 0.5f, 64, "edge level = tess_scale * patch / distance");
        p.add_float("tess_patch_size", &tess_patch_size_, 2, 200, "side of a tessellated patch, metres")
            .bumps(patch_changes_);
        p.add_int("patch_count", &patch_count_, 4, 400, "patches per side around the camera").bumps(patch_changes_);
        p.add_bool("wireframe", &wireframe_, "edges only, coloured by tessellation level");
        p.add_int("anisotropy", &anisotropy_, 1, 16,
                  "most samples of each cascade along a pixel's long footprint (1: isotropic trilinear)");
    }
    p.add_choice("view", &view_, {"shaded", "normals", "foam", "jacobian", "tessellation"},
                 "the final picture, or one ingredient");
}

void SeaRenderer::draw(const Sea& sea, const Sky& sky, const LookParams& look, const SeaFrame& frame) {
    record(sea, frame);
    if (wireframe_) return;
    // ocean_shade.frag at every pixel where the mesh wrote depth.
    ocean::ShaderProgram* shade = programs_("ocean_shade", {"fullscreen.vert", "step06_foam_sky/shaders/ocean_shade.frag"},
                                            shading_defines(sea, look));
    if (shade == nullptr) return;
    bind_shading(*shade, sea, sky, look, frame);
    glUseProgram(shade->id());
    draw_at_far_plane(GL_GREATER, frame.fullscreen_vao);
}

void SeaRenderer::record(const Sea& sea, const SeaFrame& frame) {
    if (patches_made_for_ != patch_changes_.value) {
        patches_made_for_ = patch_changes_.value;
        patches_.build(patch_count_, tess_patch_size_);
    }
    if (wireframe_) {
        draw_mesh("ocean_wireframe", {"WIREFRAME 1"}, sea, frame);
        return;
    }
    // Deferred (gbuffer.hpp): the mesh records where each pixel meets the sea; the shading then
    // reads it back, one pixel at a time, into the scene.
    gbuffer_.resize(frame.size, frame.scene_depth);
    gbuffer_.bind();
    // The view coloured by tessellation level has the mesh record the level where the shading
    // otherwise reads the choppy normal's cross term (ocean.frag).
    if (view_ == kViewTessellationLevel) draw_mesh("ocean_levels", {"LEVEL_VIEW 1"}, sea, frame);
    else draw_mesh("ocean", {}, sea, frame);
    glBindFramebuffer(GL_FRAMEBUFFER, frame.scene);
    glViewport(0, 0, frame.size.x, frame.size.y);
}

// The patches around the camera (depth tested and written): ocean.frag records the G-buffer, or
// with WIREFRAME 1 draws the edges.
void SeaRenderer::draw_mesh(const std::string& name, const std::vector<std::string>& defines, const Sea& sea,
                            const SeaFrame& frame) {
    std::vector<std::string> variant = defines;
    for (const std::string& d : sea.shader_defines()) variant.push_back(d);  // extra waves or none
    ocean::ShaderProgram* mesh = programs_(name, SeaPatches::mesh_shaders(), variant);
    if (mesh == nullptr) return;
    sea.bind_maps(*mesh);
    // The grid follows the camera in whole patches of the world (in double), then is placed
    // from the world origin.
    const double patch = double(tess_patch_size_);
    const glm::dvec2 grid_offset = glm::floor(glm::dvec2(frame.eye.x, frame.eye.z) / patch) * patch;
    const PatchView view{frame.view_projection, glm::vec3(frame.eye - sea.world_origin()),
                         glm::vec2(grid_offset - sea.cascades().origin), float(sea.largest_displacement())};
    mesh->set("u_view_projection", view.view_projection);
    mesh->set("u_eye", view.eye);
    mesh->set("u_grid_offset", view.grid_offset);
    mesh->set("u_tess_patch_size", tess_patch_size_);
    mesh->set("u_tess_scale", tess_scale_);
    mesh->set("u_frustum", ocean::frustum_planes(frame.view_projection));
    // The patches' boxes widened by how far the sea can move them.
    mesh->set("u_max_displacement", view.max_displacement);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(mesh->id());
    patches_.draw(*mesh, view, tess_scale_, wireframe_);
    glDisable(GL_DEPTH_TEST);
}

std::vector<std::string> SeaRenderer::shading_defines(const Sea& sea, const LookParams& look) const {
    std::vector<std::string> defines = {"MICROFACET " + std::to_string(look.microfacet), "DEBUG_VIEW " + std::to_string(view_),
                                        "ANISOTROPIC_TAPS " + std::to_string(anisotropy_),
                                        "STREAKS " + std::to_string(int(sea.has_streaks()))};
    for (const std::string& d : sea.shader_defines()) defines.push_back(d);  // extra waves or none
    return defines;
}

void SeaRenderer::bind_shading(const ocean::ShaderProgram& shade, const Sea& sea, const Sky& sky,
                               const LookParams& look, const SeaFrame& frame) const {
    sea.bind_for_shading(shade);
    sky.bind();
    look.upload_shading(shade);
    shade.set("u_eye", glm::vec3(frame.eye - sea.world_origin()));
    shade.set("u_sky_max_lod", sky.max_lod());
    ocean::bind_texture(UNIT_GBUFFER_WORLD, GL_TEXTURE_2D, gbuffer_.world_texture());
    ocean::bind_texture(UNIT_GBUFFER_REST, GL_TEXTURE_2D, gbuffer_.rest_texture());
}

}  // namespace step06
