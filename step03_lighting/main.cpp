// step03_lighting: step02's waves, lit. Normals from analytic derivatives; Lambert, Blinn-Phong
// and ambient light.
// Notes sections 2, 2.1-2.4.
// New since step02: the partial derivatives of the height, summed in the same loop
// (wave_gradient.glsl); N = normalize(-dh/dx, 1, -dh/dz); the notes' finite-difference slope as a
// switch, with a view of the angle between the two normals; diffuse + specular + ambient, each
// alone if you like; lighting per vertex or per pixel.
// Controls: as step02; the panel's "light" and "normals" groups.
#include "common/app.hpp"
#include "common/grid.hpp"
#include "step02_sine3d/wave_params.hpp"
#include "step03_lighting/light_params.hpp"
#include "step03_lighting/light_uniforms.hpp"

#include <imgui.h>

namespace {

class Lighting : public ocean::App {
public:
    Lighting()
        : App({"Lighting the waves", "2, 2.1-2.4",
               "Normals from the partial derivatives dh/dx and dh/dz, summed in the same loop as the "
               "height: N = normalize(-dh/dx, 1, -dh/dz). Light = ambient + Lambert diffuse (blue) + "
               "Blinn-Phong specular. Compare with the notes' finite-difference slope and with "
               "per-vertex lighting."}) {
        // The parameters: step02's waves (step02_sine3d/wave_params.hpp) and the grid (common/grid.hpp);
        // the normals and the view (here); the light (light_params.hpp); the camera (common/camera.cpp).
        waves_.declare(params());
        grid_params_.declare(params());
        auto& p = params();
        p.add_choice("normals", &normal_method_, {"analytic", "finite_difference"},
                     "normals from the analytic derivatives, or from central differences of the height")
            .in_group("normals");
        p.add_float("fd_step", &fd_step_, 0.001f, 5, "finite-difference step, metres (the notes use 1)")
            .in_group("normals").logarithmic();
        p.add_float("angle_scale", &angle_scale_, 0.01f, 90,
                    "normal_difference view: degrees between the normals shown as full red")
            .in_group("normals").logarithmic();
        p.add_choice("lighting", &lighting_, {"per_pixel", "per_vertex"},
                     "evaluate the light at every pixel, or at vertices and interpolate").in_group("light");
        p.add_choice("view", &view_, {"lit", "ambient", "diffuse", "specular", "normals", "normal_difference"},
                     "the whole light, one term alone, the normals as colours, or the analytic/finite-difference angle")
            .in_group("light");
        p.add_choice("specular", &specular_, {"blinn_phong", "phong"},
                     "the glint: Blinn-Phong's (N against the halfway vector) or Phong's (the eye against the "
                     "sun mirrored about N), as wide in the plane of N and the sun at the same shininess")
            .in_group("light");
        light_.declare(p);
        p.add_bool("wireframe", &wireframe_, "draw the triangles' edges only").in_group("view");
        use_camera(ocean::camera_view("overview"));
        offer_split_view([] {
            return SplitVariants{"analytic normals", "finite differences", {"normals=analytic"},
                                 {"normals=finite_difference"}};
        });
    }

private:
    // The compile-time variant for the current choices (see surface.glsl for why).
    ocean::ShaderProgram* ocean_variant() {
        return program("ocean", {"ocean.vert", "ocean.frag"},
                       {"NORMAL_METHOD " + std::to_string(normal_method_), "VIEW " + std::to_string(view_),
                        "PER_PIXEL " + std::to_string(int(lighting_ == 0)), "SPECULAR " + std::to_string(specular_)});
    }

    void init() override { ocean_variant(); }  // the default variant must build before the first frame

    void update(double /*time*/, double /*dt*/) override { grid_params_.update(grid_); }

    void render() override {
        const glm::vec3 clear = step03::LightParams::background_srgb();
        clear_target(clear);
        ocean::ShaderProgram* ocean_program = ocean_variant();
        step02::upload_waves(*ocean_program, waves_.waves(), time());
        step03::upload_light(*ocean_program, light_.light());
        ocean_program->set("u_fd_step", fd_step_);
        ocean_program->set("u_angle_scale", angle_scale_);
        ocean_program->set("u_wireframe", int(wireframe_));
        ocean_program->set("u_background", step03::srgb_to_linear(clear));
        ocean::draw_grid(grid_, *ocean_program, camera(), aspect(), timers(), wireframe_);
    }

    void ui() override {
        ImGui::Separator();
        ImGui::Text("%d vertices, %d triangles", grid_.vertex_count(), grid_params_.triangle_count());
        const auto l = light_.light().to_sun;
        ImGui::Text("L = (%.2f, %.2f, %.2f)", l.x, l.y, l.z);
    }

    ocean::GridMesh grid_;
    step02::WaveParams waves_;
    ocean::GridParams grid_params_;
    int normal_method_ = 0, lighting_ = 0, view_ = 0, specular_ = 0;
    float fd_step_ = 1, angle_scale_ = 10;
    step03::LightParams light_;
    bool wireframe_ = false;
};

}  // namespace

OCEAN_MAIN(Lighting)
