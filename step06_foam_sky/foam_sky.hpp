// step06_foam_sky's program, FoamSky: the open sea under a sky (main.cpp runs it).
// Notes sections 5, 5.1-5.6.
// New since step05: four cascades of step05's simulation, each with its own tile and band of
// wavenumbers, transformed together; GPU tessellation of patches around the camera with frustum
// culling, shaded once per pixel (deferred: gbuffer.hpp); foam where the surface folds, kept and
// faded with time; water shading with subsurface scatter, GGX or Beckmann specular and the sky's
// reflection through Fresnel; a sky cubemap with sun and drifting clouds; height fog, bloom and a
// filmic tonemapper, in HDR.
// Controls: as step02 (drag, wheel, C for the fly camera); every term and pass in the panel.
#pragma once

#include "common/app.hpp"
#include "common/faster_of_two.hpp"
#include "common/frustum.hpp"
#include "common/text.hpp"
#include "step05_fft/export.hpp"
#include "step05_fft/ocean_simulation.hpp"
#include "step05_fft/ocean_params.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/combined_surface.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/gbuffer.hpp"
#include "step06_foam_sky/look_params.hpp"
#include "step06_foam_sky/patch_grid.hpp"
#include "step06_foam_sky/post.hpp"
#include "step06_foam_sky/short_waves.hpp"
#include "step06_foam_sky/sky.hpp"
#include "step06_foam_sky/surface_export.hpp"
#include "step06_foam_sky/tessellation.hpp"
#include "step06_foam_sky/texture_units.h"

#include <imgui.h>

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <iostream>
#include <limits>
#include <memory>
#include <utility>

namespace step06 {

// The `view` parameter's choices, in its order. Normals to TessellationLevel are also
// ocean_shade.frag's DEBUG_VIEW numbers.
enum View : int { kViewShaded, kViewNormals, kViewFoam, kViewJacobian, kViewTessellationLevel, kViewCascadeMap };

// Step06's program: step07 derives from it (its own StepInfo, drawing its bodies in the scene with
// draw_in_scene, and reading the sea through the protected members below).
class FoamSky : public ocean::App {
public:
    FoamSky() : FoamSky(step_info()) {}

protected:
    explicit FoamSky(ocean::StepInfo info) : App(drawn_off_screen(std::move(info))) { declare(params()); }

    // The scene is drawn into post_'s targets and reaches the window in the tonemapper's one
    // full-screen triangle: a multisampled window would only cost (on llvmpipe a tenth of the
    // windowed frame, the tonemapper writing four samples a pixel and the swap resolving them).
    static ocean::StepInfo drawn_off_screen(ocean::StepInfo info) {
        info.window_samples = 0;
        return info;
    }

    // Called after the sea is drawn into the HDR scene (its depth is there) and before the sky
    // behind it, with the frame's view-projection (from the world origin, world_origin()).
    virtual void draw_in_scene(const glm::mat4& /*view_projection*/) {}

    // Everything below is protected, not private: a later chapter's program is this one plus its
    // own objects, and reads the sea (gpu_, spectra_, cascade_view_) and the sky (sky_settings_).
    static ocean::StepInfo step_info() {
        return {"Foam and sky", "5, 5.1-5.6",
               "Four cascades of the FFT ocean (each its own band of waves), tessellated near the camera; foam "
               "where the Jacobian folds the surface; scatter + microfacet specular + sky reflection with "
               "Fresnel; a sky with sun and clouds; fog, bloom and a filmic tonemapper."};
    }

    // The parameters: step05's spectrum (step05_fft/ocean_params.hpp), the cascades' switches (here),
    // the foam (foam.hpp), the geometry and the backend (here), the look (look_params.hpp), the views
    // (here), the camera (common/camera.cpp).
    void declare(ocean::ParamRegistry& p) {
        step06::use_default_sea(ocean_params_);  // step05's spectrum, over a 500 m first tile, in a fresh breeze
        ocean_params_.declare(p);
        for (int c = 0; c < step06::kCascades; ++c)
            p.add_bool("cascade_" + std::to_string(c), &cascade_on_[c],
                       "draw cascade " + std::to_string(c) + " (0: the longest waves)").in_group("cascades");
        step06::declare_foam_params(p, foam_settings_);
        p.add_float("tess_scale", &tess_scale_, 0.5f, 64, "edge level = tess_scale * patch / distance")
            .in_group("geometry");
        p.add_float("tess_patch_size", &tess_patch_size_, 2, 200, "side of a tessellated patch, metres")
            .in_group("geometry")
            .bumps(patches_changed_);
        p.add_int("patch_count", &patch_count_, 4, 400, "patches per side around the camera")
            .in_group("geometry")
            .bumps(patches_changed_);
        p.add_bool("frustum_culling", &cull_, "discard patches outside the view").in_group("geometry");
        p.add_bool("wireframe", &wireframe_, "edges only, coloured by tessellation level").in_group("geometry");
        p.add_choice("backend", &backend_, step05::backend_names(kBackends),
                     "the simulation's transforms: auto times both on the first frames (again when the "
                     "resolution changes) and keeps the faster")
            .in_group("geometry");
        p.add_int("anisotropy", &anisotropy_, 1, 16,
                  "most samples of each cascade along a pixel's long footprint (1: isotropic trilinear)")
            .in_group("geometry");
        p.add_choice("surface", &surface_, {"cascades", "combined"},
                     "what the mesh and the shading read: the four cascades, or the cascades combined once a "
                     "frame into levels around the camera (Crest's design; README)")
            .in_group("geometry");
        p.add_choice("combined_size", &combined_size_, {"256", "512", "1024", "2048"},
                     "surface=combined: texels on a side of each level")
            .in_group("geometry");
        p.add_int("combined_cascades", &combined_cascades_, 1, step06::kCascades,
                  "surface=combined: the cascades (from the longest) summed into the levels; the finer ones "
                  "are read per pixel as before")
            .in_group("geometry");
        p.add_int("combined_texels", &combined_texels_, 0, 8192,
                  "0: off; n: the slopes only as fine as the cascades combined around the camera into "
                  "levels of n x n texels could show (Crest's design, measured; README)")
            .in_group("geometry");
        p.add_choice("shading", &shading_, {"auto", "fragment", "compute"},
                     "what runs the shading pass: a fragment shader over the screen, or a compute shader, a "
                     "thread a pixel (faster where few of a GPU's units can run fragment shaders; README); auto "
                     "times both on the first frames and keeps the compute shader if twice as fast")
            .in_group("geometry");
        p.add_int("bench_shading_repeats", &bench_shading_repeats_, 0, 100,
                  "--bench: the shading pass drawn again this many times on each timed frame, each between "
                  "two glFinish, and their median printed: the shading alone, quiet enough to measure a "
                  "shader change (docs/performance.md)")
            .in_group("geometry");
        look_.declare(p);
        p.add_choice("view", &view_, {"shaded", "normals", "foam", "jacobian", "tessellation", "cascade_map"},
                     "the final picture, or one ingredient");
        std::vector<std::string> split_choices;
        for (step06::Effect e : step06::kSplitEffects) split_choices.emplace_back(step06::effect_name(e));
        p.add_choice("split_effect", &split_effect_, split_choices,
                     "split view: the effect shown on the left and left out on the right");
        p.add_int("debug_cascade", &debug_cascade_, 0, step06::kCascades - 1, "view=cascade_map: which cascade");
        p.add_choice("debug_map", &debug_map_, step05::map_view_names(), "view=cascade_map: which map");
        // 5 m above the water, level with the crests; anywhere on an ocean (camera-relative rendering).
        use_camera(ocean::camera_view("low"), ocean::kOceanReach);
        offer_bench_figures([this] {
            const step05::BackendTimes times = step05::time_backends(*gpu_, time(), 5);  // all 4 cascades' maps
            for (const auto& line : times.lines()) std::cout << "bench: " << line << "\n";
            BenchFigures figures = times.figures();
            if (!shading_alone_ms_.empty()) {
                const double median = ocean::median(shading_alone_ms_);
                std::cout << "bench: the shading pass alone (ocean_shade.frag or .comp, drawn again "
                          << shading_alone_ms_.size() << " times, wall ms around glFinish): median " << median
                          << ", min "
                          << *std::min_element(shading_alone_ms_.begin(), shading_alone_ms_.end()) << "\n";
                figures.emplace_back("shading_alone_ms", median);
            }
            return figures;
        });
        offer_warm_up([this] {
            return (kBackends[std::size_t(backend_)] == step05::Backend::Auto && (!gpu_ || gpu_->auto_deciding())) ||
                   (shading_ == kShadingAuto && shading_choice_.deciding());
        });
        // The rendered surface (all cascades) and the foam, on one grid around the camera.
        offer_export([this](const std::string& dir) {
            ocean::ProgramFactory programs = program_factory();
            step06::export_surface(dir, programs, *gpu_, *foam_, cascade_view_, time(), ocean_params_.choppiness,
                                   short_wave_slope_variance_, params());
        });
        // With and without one effect (split_effect).
        offer_split_view([this] {
            const std::string effect = step06::effect_name(step06::kSplitEffects[split_effect_]);
            return SplitVariants{"with " + effect, "without " + effect, {"show_" + effect + "=true"},
                                 {"show_" + effect + "=false"}};
        });
    }

    void init() override {
        gpu_ = std::make_unique<step05::OceanSimulation>(program_factory());
        sky_ = std::make_unique<step06::Sky>(program_factory(), 128);
        foam_ = std::make_unique<step06::FoamSimulation>(program_factory());
        combined_ = std::make_unique<step06::CombinedSurface>(program_factory());
    }

    void update(double /*time*/, double dt) override {
        if (spectrum_built_for_ != ocean_params_.changes.value) {  // a spectrum parameter moved
            spectrum_built_for_ = ocean_params_.changes.value;
            spectra_.clear();
            std::vector<const step05::InitialSpectrum*> pointers;
            height_variance_ = 0;
            unresolved_by_level_.assign(std::size_t(step06::kCascades * step06::kMaxMipLevels), 0.0f);
            for (const auto& p : step06::cascade_spectra(ocean_params_.spectrum)) {
                spectra_.push_back(std::make_unique<step05::InitialSpectrum>(step05::initial_spectrum(p)));
                pointers.push_back(spectra_.back().get());
                height_variance_ += step05::resolved_variance(p);
                // What each of this cascade's mip levels averages away, from its spectrum; past the
                // last level (a pixel wider than the tile) all of it.
                const std::vector<double> by_level = step05::unresolved_slope_variance_by_level(p);
                const std::size_t base = (pointers.size() - 1) * step06::kMaxMipLevels;
                for (std::size_t l = 0; l < step06::kMaxMipLevels; ++l)
                    unresolved_by_level_[base + l] = float(by_level[std::min(l, by_level.size() - 1)]);
            }
            gpu_->set_spectra(pointers);
            foam_->resize(ocean_params_.spectrum.resolution);
            // The waves shorter than the last cascade, down to the capillaries (short_waves.hpp):
            // microfacets everywhere, whatever the pixel resolves.
            short_wave_slope_variance_ = step06::short_wave_slope_variance_beyond(ocean_params_.spectrum);
            wind_heading_ = step06::wind_heading(ocean_params_.spectrum);
            foam_->set_wind(wind_heading_, ocean_params_.spectrum.wind_speed);
            describe_cascades();
        }
        cascade_view_ = cascade_view();  // once a frame: the passes below and render() read it
        const glm::dvec3 eye = camera().eye_world();
        cascade_view_.place_origin(step06::world_origin_near({eye.x, eye.z}));
        if (sky_image_loaded_for_ != look_.sky_image_changes.value) {
            sky_image_loaded_for_ = look_.sky_image_changes.value;
            if (auto warning = sky_->use_image(look_.sky_image)) std::cerr << "warning: " << *warning << "\n";
        }
        if (patches_built_for_ != patches_changed_.value) {
            patches_built_for_ = patches_changed_.value;
            patches_.build(patch_count_, tess_patch_size_);
        }
        // Once a frame, whatever the split view shows: the sea, its foam and the sky move on.
        simulate();
        update_foam(dt);
        if (combined()) combine();
        ocean::GpuScope timed(timers(), "sky");
        sky_settings_ = look_.sky(time(), ocean_params_.spectrum.wind_direction);
        sky_->render(sky_settings_);
    }

    // backend: the chosen one, or for auto the faster at this resolution (found on the first
    // frames, printed once: on llvmpipe FFTW wins, on a real GPU the GPU FFT).
    void simulate() {
        ocean::GpuScope timed(timers(), "simulation");
        gpu_->simulate(time(), kBackends[std::size_t(backend_)], ocean_params_.choppiness);
        if (auto decision = gpu_->take_auto_decision()) std::cout << "backend auto " << *decision << "\n";
    }

    void update_foam(double dt) {
        ocean::GpuScope timed(timers(), "foam");
        const glm::dvec3 eye = camera().eye_world();
        const glm::vec3 forward = camera().forward();
        foam_->update(*gpu_, cascade_view_, {eye.x, eye.z}, {forward.x, forward.z}, dt, foam_settings_);
    }

    bool combined() const { return surface_ == kSurfaceCombined; }

    // surface=combined: the cascades summed into levels around the camera, enough of them to
    // hold the whole mesh (its half side, a patch for the grid's snap, and the sea's largest
    // displacement), the finest texel a power of two under the finest combined cascade's
    // (combined_surface.hpp).
    void combine() {
        ocean::GpuScope timed(timers(), "combine");
        const int n = 256 << combined_size_;
        // The finest texel of the cascades the levels hold.
        const double finest_texel = double(cascade_view_.patch_sizes[std::size_t(combined_cascades_ - 1)]) /
                                    ocean_params_.spectrum.resolution;
        const double texel0 = step06::combined_texel0(finest_texel);
        const double reach = 0.5 * patch_count_ * double(tess_patch_size_) + double(tess_patch_size_) +
                             step05::largest_displacement(height_variance_, ocean_params_.choppiness);
        combined_->resize(n, step06::combined_level_count(reach, n, texel0), texel0);
        const glm::dvec3 eye = camera().eye_world();
        combined_->update(*gpu_, cascade_view_, {eye.x, eye.z}, combined_cascades_);
    }

    // The defines and the textures of the surface the mesh and the shading read (surface=).
    std::string surface_define() const { return "COMBINED_SURFACE " + std::to_string(int(combined())); }
    void bind_surface(const ocean::ShaderProgram& p) const {
        if (combined()) combined_->bind(p);
    }

    // What the panel says of each cascade, made when the spectra are (not every frame in ui()).
    void describe_cascades() {
        cascade_lines_.clear();
        const auto sizes = step06::cascade_patch_sizes(ocean_params_.spectrum);
        const auto bands = step06::cascade_bands(sizes, ocean_params_.spectrum.resolution);
        for (std::size_t c = 0; c < std::size_t(step06::kCascades); ++c) {
            char line[128];
            std::snprintf(line, sizeof line, "cascade %zu: tile %.1f m, waves %.2f m .. %.2f m", c, sizes[c],
                          bands[c].high > 0 ? 2 * step05::kPi / bands[c].high : 0.0,
                          bands[c].low > 0 ? 2 * step05::kPi / bands[c].low : std::numeric_limits<double>::infinity());
            cascade_lines_.push_back(line);
        }
    }

    // The tiles of the simulated spectra (made in update()) and the cascade switches.
    step06::CascadeView cascade_view() const {
        step06::CascadeView view;
        for (int c = 0; c < step06::kCascades; ++c) {
            view.patch_sizes[std::size_t(c)] = float(spectra_[std::size_t(c)]->patch_size);
            view.enabled[std::size_t(c)] = cascade_on_[c];
        }
        return view;
    }

    // Units (texture_units.h): 0 and 1 the cascades' maps, then foam, sky, the bubble pattern.
    void bind_cascades(const ocean::ShaderProgram& p) {
        cascade_view_.upload(p);
        gpu_->bind_maps(p);
        foam_->bind(p, UNIT_FOAM);
        foam_->bind_pattern(p, UNIT_FOAM_PATTERN);
        sky_->bind();
        p.set("u_unresolved_slope_variance", unresolved_by_level_);
    }

    void draw_sea() {
        // Camera-relative: the view, the mesh and the shading work in metres from the world origin
        // near the camera (cascades.hpp), so their float positions stay small anywhere on the ocean.
        const glm::mat4 view_projection = camera().projection(aspect()) * camera().view(world_origin());
        {
            ocean::GpuScope timed(timers(), "ocean");
            if (wireframe_) {
                draw_mesh("ocean_wireframe", {"WIREFRAME 1"}, view_projection);
            } else {
                // Deferred (gbuffer.hpp): the mesh records where each pixel meets the sea, then
                // each of those pixels is shaded once.
                gbuffer_.resize(framebuffer_size(), post_.depth_texture());
                gbuffer_.bind();
                // The view coloured by tessellation level has the mesh record the level where the
                // shading otherwise reads the choppy normal's cross term (ocean.frag).
                if (view_ == kViewTessellationLevel) draw_mesh("ocean_levels", {"LEVEL_VIEW 1"}, view_projection);
                else draw_mesh("ocean", {}, view_projection);
                post_.bind_scene();
                shade_sea_as_chosen();
            }
        }
        if (timers().enabled() && !wireframe_) time_shading_alone();
        draw_in_scene(view_projection);
        ocean::GpuScope timed(timers(), "background");
        draw_background(view_projection);
    }

    // The sky behind the sea, drawn last and only where the sea left the depth at the far plane
    // (the full-screen triangle put there, depth test LEQUAL): drawn first under everything it
    // cost 10 ms a frame on llvmpipe, two thirds of it on pixels the sea then covered.
    void draw_background(const glm::mat4& view_projection) {
        ocean::ShaderProgram* sky = program("sky", {"fullscreen.vert", "sky.frag"});
        if (sky == nullptr) return;
        // The sun's disc is drawn here, not kept in the cubemap: the water's specular term is the
        // sun's reflection, and a disc in the reflected sky would count it twice.
        sky->set("u_to_sun", sky_settings_.to_sun);
        sky->set("u_sun_radiance", sky_settings_.sun_radiance);
        sky->set("u_sun_size", sky_settings_.sun_size);
        sky->set("u_draw_sun_disc", int(!sky_->uses_image()));
        sky->set("u_inverse_view_projection", glm::inverse(view_projection));
        sky_->bind();
        glUseProgram(sky->id());
        draw_at_far_plane(GL_LEQUAL);
    }

    // The full-screen triangle at the far plane (depth range 1..1), depth-tested with `test`
    // against the mesh's depth and not writing it: GL_GREATER runs where the sea is, GL_LEQUAL
    // where it is not.
    void draw_at_far_plane(GLenum test) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(test);
        glDepthMask(GL_FALSE);
        glDepthRange(1.0, 1.0);
        draw_fullscreen_triangle();
        glDepthRange(0.0, 1.0);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
    }

    // The tessellated patches around the camera (depth tested and written): ocean.frag records
    // the G-buffer, or with WIREFRAME 1 draws the edges.
    void draw_mesh(const std::string& name, const std::vector<std::string>& defines, const glm::mat4& view_projection) {
        std::vector<std::string> all_defines = defines;
        all_defines.push_back(surface_define());
        ocean::ShaderProgram* mesh = program(name, {"ocean.vert", "ocean.tesc", "ocean.tese", "ocean.frag"}, all_defines);
        if (mesh == nullptr) return;
        cascade_view_.upload(*mesh);
        gpu_->bind_maps(*mesh);
        bind_surface(*mesh);
        // The grid follows the camera in whole patches of the world (in double), then is placed
        // from the world origin.
        const glm::dvec3 eye = camera().eye_world();
        const glm::dvec2 grid_offset = glm::floor(glm::dvec2(eye.x, eye.z) / double(tess_patch_size_)) * double(tess_patch_size_);
        mesh->set("u_view_projection", view_projection);
        mesh->set("u_eye", eye_from_origin());
        mesh->set("u_grid_offset", glm::vec2(grid_offset - cascade_view_.origin));
        mesh->set("u_tess_patch_size", tess_patch_size_);
        mesh->set("u_tess_scale", tess_scale_);
        mesh->set("u_frustum", ocean::frustum_planes(view_projection));
        // The patches' boxes widened by how far the sea can move them (the choppiness may change
        // without the spectrum changing, so every frame).
        mesh->set("u_max_displacement", float(step05::largest_displacement(height_variance_, ocean_params_.choppiness)));
        mesh->set("u_cull", int(cull_));
        glEnable(GL_DEPTH_TEST);
        glUseProgram(mesh->id());
        if (wireframe_) glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        patches_.draw();
        if (wireframe_) glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glDisable(GL_DEPTH_TEST);
    }

    // The world origin of this frame (cascades.hpp), and the eye from it: what the shaders' positions are.
    glm::dvec3 world_origin() const { return {cascade_view_.origin.x, 0.0, cascade_view_.origin.y}; }
    glm::vec3 eye_from_origin() { return glm::vec3(camera().eye_world() - world_origin()); }

    // shading=auto: the fragment and the compute shader by turns on the first frames, each timed
    // alone, then the compute shader if it is at least twice as fast (printed once: on llvmpipe
    // the fragment shader, 1.4 times faster; on an H100 the compute shader, 20 times). The two
    // pictures differ by the texture levels the quads' differences give (ocean_shade.comp): RMSE
    // 0.5 of 255, so the margin keeps a machine's noise from switching between them.
    void shade_sea_as_chosen() {
        shading_in_compute_ =
            shading_ == kShadingCompute || (shading_ == kShadingAuto && shading_choice_.next() == 1);
        if (shading_ != kShadingAuto || !shading_choice_.deciding()) {
            shade_sea(shading_in_compute_);
            return;
        }
        shading_choice_.record(shading_in_compute_ ? 1 : 0,
                               ocean::wall_ms_around_finish([&] { shade_sea(shading_in_compute_); }));
        if (!shading_choice_.deciding())
            std::cout << "shading auto: " << shading_choice_.verdict("fragment shader", "compute shader") << "\n";
    }

    // ocean_shade.glsl at every pixel where the mesh wrote depth: a full-screen triangle
    // (ocean_shade.frag), or a thread a pixel (ocean_shade.comp).
    void shade_sea(bool compute) {
        const int debug = view_ >= kViewNormals && view_ <= kViewTessellationLevel ? view_ : 0;
        const std::vector<std::string> defines{
            "MICROFACET " + std::to_string(look_.microfacet), "DEBUG_VIEW " + std::to_string(debug),
            "ANISOTROPIC_TAPS " + std::to_string(anisotropy_),
            "COMBINED_LEVEL_TEXELS " + std::to_string(combined_texels_), surface_define(),
            "STREAKS " + std::to_string(int(foam_->streaks()))};
        ocean::ShaderProgram* shade = compute ? program("ocean_shade_compute", {"ocean_shade.comp"}, defines)
                                              : program("ocean_shade", {"fullscreen.vert", "ocean_shade.frag"}, defines);
        if (shade == nullptr) return;
        bind_cascades(*shade);
        bind_surface(*shade);
        look_.upload_shading(*shade);
        shade->set("u_short_wave_slope_variance",
                   glm::vec2(float(short_wave_slope_variance_.upwind), float(short_wave_slope_variance_.crosswind)));
        shade->set("u_wind_heading", glm::vec2(wind_heading_));
        shade->set("u_eye", eye_from_origin());
        shade->set("u_sky_max_lod", sky_->max_lod());
        glBindTextureUnit(UNIT_GBUFFER_WORLD, gbuffer_.world_texture());
        glBindTextureUnit(UNIT_GBUFFER_REST, gbuffer_.rest_texture());
        glUseProgram(shade->id());
        if (!compute) {
            draw_at_far_plane(GL_GREATER);
            return;
        }
        const glm::ivec2 size = framebuffer_size();
        glBindTextureUnit(UNIT_GBUFFER_DEPTH, post_.depth_texture());
        glBindImageTexture(0, post_.scene_texture(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glDispatchCompute(GLuint((size.x + 7) / 8), GLuint((size.y + 7) / 8), 1);
        // What follows draws into the scene (the background, step07's bodies) and reads it (bloom).
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    // bench_shading_repeats: the shading pass again on the same G-buffer (it writes the same pixels
    // the same way), each draw alone between two glFinish. The frame's ocean pass holds the mesh
    // too, and on a shared machine two whole frames drift apart by more than a shader change costs;
    // draws a few milliseconds apart see the same machine.
    void time_shading_alone() {
        for (int i = 0; i < bench_shading_repeats_; ++i)  // with what drew this frame
            shading_alone_ms_.push_back(ocean::wall_ms_around_finish([&] { shade_sea(shading_in_compute_); }));
    }

    void draw_cascade_map() {
        ocean::ShaderProgram* p = program("map_view", {"fullscreen.vert", "step05_fft/shaders/map_view.frag"});
        if (p == nullptr) return;  // first asked for after a shader broke: nothing to draw with
        p->set("u_map", debug_map_);
        p->set("u_range", debug_map_ <= 2 ? 1.0f : 0.5f);
        p->set("u_resolution", glm::vec2(framebuffer_size()));
        p->set("u_layer", debug_cascade_);
        // map_view.frag also declares step05's spectrum image (a sampler2D): left on unit 0 it
        // would share the unit with the displacement array, which GL refuses at the draw.
        p->set("u_spectrum_image", 3);
        gpu_->bind_maps(*p);
        glUseProgram(p->id());
        draw_fullscreen_triangle();
    }

    void render() override {
        if (view_ == kViewCascadeMap) {
            bind_target();
            clear_target({0, 0, 0});
            draw_cascade_map();
            return;
        }
        post_.resize(framebuffer_size());
        post_.bind_scene();
        clear_target({0, 0, 0});
        draw_sea();
        const bool bloom = look_.show(step06::Effect::Bloom) && view_ == kViewShaded;
        if (bloom) {
            ocean::GpuScope timed(timers(), "bloom");
            ocean::ShaderProgram* first = program("bloom_first", {"fullscreen.vert", "bloom_down.frag"}, {"FIRST_LEVEL 1"});
            ocean::ShaderProgram* down = program("bloom_down", {"fullscreen.vert", "bloom_down.frag"});
            ocean::ShaderProgram* up = program("bloom_up", {"fullscreen.vert", "bloom_up.frag"});
            if (first != nullptr && down != nullptr && up != nullptr)
                post_.bloom(*first, *down, *up, look_.bloom_threshold, fullscreen_vao());
        }
        ocean::GpuScope timed(timers(), "tonemap");
        bind_target();
        ocean::ShaderProgram* tonemap =
            program("tonemap", {"fullscreen.vert", "tonemap.frag"},
                    {"TONEMAPPER " + std::to_string(view_ == kViewShaded ? look_.tonemapper : 2),
                     // The debug views show their values as they are: no noise on them.
                     std::string("DITHER ") + (view_ == kViewShaded && look_.dither ? "1" : "0")});
        if (tonemap == nullptr) return;
        tonemap->set("u_scene", 0);
        tonemap->set("u_bloom", 1);
        tonemap->set("u_exposure", view_ == kViewShaded ? look_.exposure : 1.0f);
        tonemap->set("u_bloom_strength", bloom ? look_.bloom_strength : 0.0f);
        glBindTextureUnit(0, post_.scene_texture());
        glBindTextureUnit(1, post_.bloom_texture());
        glUseProgram(tonemap->id());
        draw_fullscreen_triangle();
    }

    void ui() override {
        ImGui::Separator();
        for (const auto& line : cascade_lines_) ImGui::TextUnformatted(line.c_str());
        ImGui::Text("%d patches of %.0f m; sky %s", patches_.patch_count(), double(tess_patch_size_),
                    sky_->uses_image() ? "from an image" : "procedural");
    }

    step05::OceanParams ocean_params_;
    step06::LookParams look_;
    step06::PatchGrid patches_;
    step06::PostProcess post_;
    step06::GBuffer gbuffer_;
    std::unique_ptr<step05::OceanSimulation> gpu_;
    std::unique_ptr<step06::Sky> sky_;
    std::vector<std::unique_ptr<step05::InitialSpectrum>> spectra_;
    std::unique_ptr<step06::FoamSimulation> foam_;
    std::unique_ptr<step06::CombinedSurface> combined_;
    unsigned sky_image_loaded_for_ = 0;
    step06::FoamSettings foam_settings_;
    unsigned spectrum_built_for_ = 0;
    ocean::Generation patches_changed_;  // patch_count, tess_patch_size
    unsigned patches_built_for_ = 0;
    step06::CascadeView cascade_view_;         // this frame's, made in update()
    std::vector<std::string> cascade_lines_;  // the panel's description, made with the spectra
    float tess_scale_ = 12, tess_patch_size_ = 16;
    double height_variance_ = 0;         // m^2, of the summed cascades
    std::vector<float> unresolved_by_level_;  // kMaxMipLevels per cascade
    step06::SlopeVariance short_wave_slope_variance_;
    glm::dvec2 wind_heading_{1.0, 0.0};  // made with the spectra (short_waves.hpp's wind_heading)
    step06::SkySettings sky_settings_;  // this frame's, as the cubemap was rendered with
    int split_effect_ = 0;
    int patch_count_ = 96, view_ = kViewShaded, debug_cascade_ = 0, debug_map_ = 0;
    bool cascade_on_[step06::kCascades] = {true, true, true, true};
    bool cull_ = true, wireframe_ = false;
    int anisotropy_ = 4;
    static constexpr int kSurfaceCombined = 1;  // the `surface` parameter's second choice
    // The cascades by default; when combined, levels of 512 texels holding the three longest cascades,
    // the finest read per pixel: what keeps the look (README, "The cascades combined around the camera").
    int surface_ = 0, combined_size_ = 1, combined_cascades_ = 3;
    enum Shading : int { kShadingAuto, kShadingFragment, kShadingCompute };
    int shading_ = kShadingAuto;
    // shading=auto: 0 the fragment shader, 1 the compute shader, kept only if twice as fast (the
    // pictures differ by RMSE 0.5: a machine should always draw the same one).
    ocean::FasterOfTwo shading_choice_{3, 2.0};
    bool shading_in_compute_ = false;    // what shaded this frame's sea
    int bench_shading_repeats_ = 0;
    std::vector<double> shading_alone_ms_;  // time_shading_alone's draws, for --bench
    int combined_texels_ = 0;  // 0: off (the README says why the cascades are not combined)
    // The backends step06 offers (not the naive DFT: its cascades are larger than it can do), in
    // the `backend` parameter's order; the first, auto, is the default.
    static constexpr std::array<step05::Backend, 3> kBackends = {step05::Backend::Auto, step05::Backend::GpuFft,
                                                                 step05::Backend::Fftw};
    int backend_ = 0;
};

}  // namespace step06
