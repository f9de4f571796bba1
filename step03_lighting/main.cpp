// step03_lighting: step02's waves, lit. Normals from analytic derivatives; Lambert, Blinn-Phong
// and ambient light.
// Seed sections 2, 2.1-2.4.
// New since step02: the partial derivatives of the height, summed in the same loop
// (wave_gradient.glsl); N = normalize(-dh/dx, 1, -dh/dz); the seed's finite-difference slope as a
// switch, with a view of the angle between the two normals; diffuse + specular + ambient, each
// alone if you like; lighting per vertex or per pixel.
// Controls: as step02; the panel's "light" and "normals" groups.
#include "common/app.hpp"
#include "common/grid.hpp"
#include "step02_sine3d/wave_params.hpp"
#include "step03_lighting/light_uniforms.hpp"

#include <imgui.h>

namespace {

glm::vec3 srgb_to_linear(glm::vec3 c) {
    for (int i = 0; i < 3; ++i)
        c[i] = c[i] <= 0.04045f ? c[i] / 12.92f : std::pow((c[i] + 0.055f) / 1.055f, 2.4f);
    return c;
}

class Lighting : public ocean::App {
public:
    Lighting()
        : App({"Lighting the waves", "2, 2.1-2.4",
               "Normals from the partial derivatives dh/dx and dh/dz, summed in the same loop as the "
               "height: N = normalize(-dh/dx, 1, -dh/dz). Light = ambient + Lambert diffuse (blue) + "
               "Blinn-Phong specular. Compare with the seed's finite-difference slope and with "
               "per-vertex lighting."}) {
        waves_.declare(params());
        grid_params_.declare(params());
        auto& p = params();
        p.add_choice("normals", &normal_method_, 0, {"analytic", "finite_difference"},
                     "normals from the analytic derivatives, or from central differences of the height")
            .in_group("normals");
        p.add_float("fd_step", &fd_step_, 1, 0.001f, 5, "finite-difference step, metres (the seed uses 1)")
            .in_group("normals").logarithmic();
        p.add_float("angle_scale", &angle_scale_, 10, 0.01f, 90,
                    "normal_difference view: degrees between the normals shown as full red")
            .in_group("normals").logarithmic();
        p.add_choice("lighting", &lighting_, 0, {"per_pixel", "per_vertex"},
                     "evaluate the light at every pixel, or at vertices and interpolate").in_group("light");
        p.add_choice("view", &view_, 0, {"lit", "ambient", "diffuse", "specular", "normals", "normal_difference"},
                     "the whole light, one term alone, the normals as colours, or the analytic/finite-difference angle")
            .in_group("light");
        p.add_float("sun_azimuth", &sun_azimuth_, 305, 0, 360, "sun heading, degrees (0 = +x, 90 = +z)")
            .in_group("light");
        p.add_float("sun_elevation", &sun_elevation_, 25, -10, 90, "sun height above the horizon, degrees")
            .in_group("light");
        p.add_color("sun_colour", &sun_colour_, {1.0f, 0.96f, 0.88f}, "colour of the sunlight (sRGB)")
            .in_group("light");
        p.add_color("water_colour", &water_colour_, {0.10f, 0.42f, 0.66f}, "diffuse tint of the water (sRGB)")
            .in_group("light");
        p.add_color("ambient_colour", &ambient_colour_, {0.04f, 0.14f, 0.24f}, "light from the whole sky (sRGB)")
            .in_group("light");
        p.add_float("shininess", &shininess_, 160, 1, 4096, "Blinn-Phong exponent: larger, smaller highlight")
            .in_group("light").logarithmic();
        p.add_bool("wireframe", &wireframe_, false, "draw the triangles' edges only").in_group("view");
        const auto& c = step02::kDefaultCamera;
        use_camera(c.target, c.distance, c.yaw_deg, c.pitch_deg);
    }

private:
    void init() override {}

    // The compile-time variant for the current choices (see surface.glsl for why).
    ocean::ShaderProgram* ocean_variant() {
        return program_variant("ocean", {"ocean.vert", "ocean.frag"},
                               {"NORMAL_METHOD " + std::to_string(normal_method_), "VIEW " + std::to_string(view_),
                                "PER_PIXEL " + std::to_string(int(lighting_ == 0))});
    }

    void update(double /*time*/, double /*dt*/) override { grid_params_.update(grid_); }

    step03::Light light() const {
        auto colour = [](glm::vec3 srgb) {
            const glm::vec3 c = srgb_to_linear(srgb);
            return step03::Colour{c.r, c.g, c.b};
        };
        return {step03::sun_direction(sun_azimuth_, sun_elevation_), colour(sun_colour_), colour(water_colour_),
                colour(ambient_colour_), shininess_};
    }

    void render() override {
        const glm::vec3 background = srgb_to_linear({0.55f, 0.66f, 0.76f});
        const glm::vec3 clear = glm::vec3(0.55f, 0.66f, 0.76f);
        glClearColor(clear.r, clear.g, clear.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);

        if (ocean::ShaderProgram* variant = ocean_variant()) ocean_ = variant;
        step02::upload_waves(*ocean_, waves_.waves(), time());
        step03::upload_light(*ocean_, light());
        ocean_->set("u_view_projection", camera().projection(aspect()) * camera().view());
        ocean_->set("u_eye", camera().eye());
        ocean_->set("u_fd_step", fd_step_);
        ocean_->set("u_angle_scale", angle_scale_);
        ocean_->set("u_wireframe", int(wireframe_));
        ocean_->set("u_background", background);

        ocean::GpuScope timed(timers(), "ocean");
        glUseProgram(ocean_->id());
        glPolygonMode(GL_FRONT_AND_BACK, wireframe_ ? GL_LINE : GL_FILL);
        grid_.draw();
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glDisable(GL_DEPTH_TEST);
    }

    void ui() override {
        ImGui::Separator();
        ImGui::Text("%d vertices, %d triangles", grid_.vertex_count(), grid_params_.triangle_count());
        const auto l = light().to_sun;
        ImGui::Text("L = (%.2f, %.2f, %.2f)", l.x, l.y, l.z);
    }

    ocean::ShaderProgram* ocean_ = nullptr;
    ocean::GridMesh grid_;
    step02::WaveParams waves_;
    step02::GridParams grid_params_;
    int normal_method_ = 0, lighting_ = 0, view_ = 0;
    float fd_step_ = 1, angle_scale_ = 10;
    float sun_azimuth_ = 305, sun_elevation_ = 25, shininess_ = 160;
    glm::vec3 sun_colour_{1.0f}, water_colour_{0.0f}, ambient_colour_{0.0f};
    bool wireframe_ = false;
};

}  // namespace

OCEAN_MAIN(Lighting)
