// step02_sine3d: a plane of vertices lifted by a sum of directional sines in the vertex shader.
// Notes section 1.2.2.
// New since step01: the waves get a direction d_i in the x-z plane, h = sum a_i sin(d_i.(x,z) w_i
// - t phi_i); a grid of (x_quads+1)(z_quads+1) vertices is displaced on the GPU (ocean.vert);
// an orbit/fly camera; a wireframe view.
// Controls: drag to orbit, wheel to zoom, C for the fly camera, the panel for everything else.
#include "common/app.hpp"
#include "common/grid.hpp"
#include "step02_sine3d/wave_params.hpp"

#include <imgui.h>

#include <cmath>

namespace {

class Sine3D : public ocean::App {
public:
    Sine3D()
        : App({"A sum of sines, in 3D", "1.2.2",
               "A plane of (x_quads+1)(z_quads+1) vertices, each lifted in the vertex shader by "
               "h = sum of a_i sin(d_i.(x,z) w_i - t phi_i). Every wave has a direction d_i. "
               "Shading is only height colour and flat facets: no light yet."}) {
        // The parameters: the waves (wave_params.hpp), the grid (common/grid.hpp), the view (here),
        // the camera (common/camera.cpp, by use_camera).
        waves_.declare(params());
        grid_params_.declare(params());
        params().add_bool("wireframe", &wireframe_, "draw the triangles' edges only").in_group("view");
        params().add_bool("facet_shading", &facet_shading_, "darken faces turned from a fixed direction")
            .in_group("view");
        // A ring of waves from a point, on top of the sum (ripple.glsl); none at amplitude 0.
        params().add_float("ripple_amplitude", &ripple_amplitude_, 0, 2,
                           "a ripple's amplitude one wavelength from its centre, metres (0: no ripple)")
            .in_group("ripple");
        params().add_float("ripple_wavelength", &ripple_wavelength_, 0.5f, 40, "the ripple's wavelength, metres")
            .in_group("ripple");
        params().add_float("ripple_x", &ripple_x_, -40, 40, "the ripple's centre, x, metres").in_group("ripple");
        params().add_float("ripple_z", &ripple_z_, -40, 40, "the ripple's centre, z, metres").in_group("ripple");
        use_camera(ocean::camera_view("overview"));
        offer_split_view([] {
            return SplitVariants{"solid", "wireframe", {"wireframe=false"}, {"wireframe=true"}};
        });
    }

private:

    void update(double /*time*/, double /*dt*/) override { grid_params_.update(grid_); }

    void render() override {
        clear_target({0.06f, 0.07f, 0.09f});
        ocean::ShaderProgram* ocean_program = program("ocean", {"ocean.vert", "ocean.frag"});
        step02::upload_waves(*ocean_program, waves_.waves(), time());
        // Deep-water speed, as the waves': sqrt(g wavelength / 2 pi), outwards.
        const double ripple_speed = std::sqrt(9.81 * double(ripple_wavelength_) / step02::kTwoPi);
        step02::upload_ripple(*ocean_program,
                              {ripple_x_, ripple_z_, ripple_wavelength_, ripple_amplitude_, ripple_speed}, time());
        ocean_program->set("u_height_extent", float(waves_.height_extent() + double(ripple_amplitude_)));
        ocean_program->set("u_facet_shading", int(facet_shading_));
        ocean_program->set("u_wireframe", int(wireframe_));
        ocean::draw_grid(grid_, *ocean_program, camera(), aspect(), timers(), wireframe_);
    }

    void ui() override {
        ImGui::Separator();
        ImGui::Text("%d vertices, %d triangles", grid_.vertex_count(), grid_params_.triangle_count());
    }

    ocean::GridMesh grid_;
    step02::WaveParams waves_;
    ocean::GridParams grid_params_;
    bool wireframe_ = false, facet_shading_ = true;
    float ripple_amplitude_ = 0, ripple_wavelength_ = 5, ripple_x_ = 0, ripple_z_ = 0;
};

}  // namespace

OCEAN_MAIN(Sine3D)
