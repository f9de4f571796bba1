// step06's sea drawn into the HDR scene, the third part of its program: the patches around the
// camera, tessellated by distance and culled by the view (ocean.vert/.tesc/.tese), record where
// each pixel meets the sea (deferred: gbuffer.hpp); then each of those pixels is shaded once
// (ocean_shade.frag): foam, scatter, microfacet specular, the sky's reflection, fog.
#pragma once

#include "common/params.hpp"
#include "common/shader.hpp"
#include "step06_foam_sky/gbuffer.hpp"
#include "step06_foam_sky/look_params.hpp"
#ifdef OCEAN_GL_ES
#include "step06_foam_sky/patch_lod.hpp"
#else
#include "step06_foam_sky/patch_grid.hpp"
#endif
#include "step06_foam_sky/sea.hpp"
#include "step06_foam_sky/sky.hpp"

#include <glm/mat4x4.hpp>

#include <string>
#include <vector>

namespace step06 {

// The patches around the camera: cut by the tessellator where there are tessellation shaders
// (GL 4.x), on the CPU where there are none (ES 3.0, WebGL 2: patch_lod.hpp). Both draw into the
// same G-buffer with the same ocean.frag.
#ifdef OCEAN_GL_ES
using SeaPatches = PatchLod;
#else
using SeaPatches = PatchGrid;
#endif

// The `view` parameter's choices, in its order: the picture, or one of its ingredients. They are
// also ocean_shade.glsl's DEBUG_VIEW numbers (0: the shaded picture).
enum View : int { kViewShaded, kViewNormals, kViewFoam, kViewJacobian, kViewTessellationLevel };

// What a frame gives the renderer: where the camera is (the eye in world metres, double) and the
// view-projection from the sea's world origin (Sea::world_origin).
struct SeaFrame {
    glm::mat4 view_projection;
    glm::dvec3 eye;
    glm::ivec2 size;  // pixels
    GLuint scene;        // the HDR scene's framebuffer, which the shading draws into
    GLuint scene_depth;  // and its depth texture, shared with the G-buffer
    GLuint fullscreen_vao;
};

class SeaRenderer {
public:
    // The mesh (tessellation, patches, wireframe), the filtering of the maps, and the view.
    void declare(ocean::ParamRegistry& p);
    void init(ocean::ProgramFactory programs) { programs_ = std::move(programs); }

    // Draws the sea: into the G-buffer, then shaded into the HDR scene where the mesh wrote depth
    // (the wireframe straight into the scene).
    void draw(const Sea& sea, const Sky& sky, const LookParams& look, const SeaFrame& frame);

    // The two halves of draw(), for a program that shades the G-buffer its own way (SeaScene's
    // FrameAdditions::shade_sea: a compute pass, say): the
    // mesh into the G-buffer (the wireframe straight into the scene), and what the shading reads:
    // its variant's defines, and its textures and uniforms bound to `shade`.
    void record(const Sea& sea, const SeaFrame& frame);
    std::vector<std::string> shading_defines(const Sea& sea, const LookParams& look) const;
    void bind_shading(const ocean::ShaderProgram& shade, const Sea& sea, const Sky& sky, const LookParams& look,
                      const SeaFrame& frame) const;

    View view() const { return View(view_); }
    bool wireframe() const { return wireframe_; }
    int patch_count() const { return patches_.patch_count(); }
    float patch_size() const { return tess_patch_size_; }

private:
    void draw_mesh(const std::string& name, const std::vector<std::string>& defines, const Sea& sea,
                   const SeaFrame& frame);

    ocean::ProgramFactory programs_;
    SeaPatches patches_;
    GBuffer gbuffer_;
    ocean::Generation patch_changes_;  // patch_count, tess_patch_size
    unsigned patches_made_for_ = 0;
    float tess_scale_ = 12, tess_patch_size_ = 16;
    int patch_count_ = 96;
    bool wireframe_ = false;
    int anisotropy_ = 4;  // cascades_visible.glsl's ANISOTROPIC_TAPS: a sea seen at a grazing angle
    int view_ = kViewShaded;
};

}  // namespace step06
