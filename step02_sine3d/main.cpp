// step02_sine3d: a plane of vertices lifted by a sum of directional sines in the vertex shader.
// Seed section 1.2.2.
// New since step01: the waves get a direction d_i in the x-z plane, h = sum a_i sin(d_i.(x,z) w_i
// + t phi_i); a grid of (x_quads+1)(z_quads+1) vertices is displaced on the GPU (ocean.vert);
// an orbit/fly camera; a wireframe view.
// Controls: drag to orbit, wheel to zoom, C for the fly camera, the panel for everything else.
#include "common/app.hpp"
#include "common/grid.hpp"
#include "step02_sine3d/wave_uniforms.hpp"

#include <imgui.h>

#include <array>
#include <cmath>

namespace {

class Sine3D : public ocean::App {
public:
    Sine3D()
        : App({"A sum of sines, in 3D", "1.2.2",
               "A plane of (x_quads+1)(z_quads+1) vertices, each lifted in the vertex shader by "
               "h = sum of a_i sin(d_i.(x,z) w_i + t phi_i). Every wave has a direction d_i. "
               "Shading is only height colour and flat facets: light comes in step03."}) {
        auto& p = params();
        p.add_int("wave_count", &wave_count_, 4, 1, step02::kMaxWaves, "number of waves in the sum");
        p.add_float("amplitude", &amplitude_, 1, 0, 10, "scale applied to every wave's amplitude");
        for (int i = 0; i < step02::kMaxWaves; ++i) {
            const std::string prefix = "wave" + std::to_string(i) + "_";
            const std::string group = "wave " + std::to_string(i);
            // Defaults: a long swell and shorter waves turning away from it, deep-water speeds.
            const float wavelength = 18.0f * std::pow(0.68f, float(i));
            auto visible = [this, i] { return i < wave_count_; };
            p.add_float(prefix + "direction", &waves_[i].direction, std::fmod(20.0f + 67.0f * float(i), 360.0f),
                        0, 360, "angle of the direction d in the x-z plane, degrees (0 = +x, 90 = +z); crests travel along -d")
                .in_group(group).visible_if(visible);
            p.add_float(prefix + "wavelength", &waves_[i].wavelength, wavelength, 0.1f, 200,
                        "distance between crests, metres").in_group(group).visible_if(visible).logarithmic();
            p.add_float(prefix + "amplitude", &waves_[i].amplitude, 0.055f * wavelength, 0, 10,
                        "height of a crest above rest, metres").in_group(group).visible_if(visible);
            p.add_float(prefix + "speed", &waves_[i].speed, std::sqrt(9.81f * wavelength / 6.2831853f), -30, 30,
                        "crest speed, metres per second (positive: along -d, the seed's sign)").in_group(group).visible_if(visible);
        }
        p.add_float("plane_size", &plane_size_, 80, 1, 1000, "side of the square plane, metres").in_group("grid");
        p.add_int("x_quads", &x_quads_, 160, 1, 2048, "grid cells along x (vertices: x_quads + 1)").in_group("grid");
        p.add_int("z_quads", &z_quads_, 160, 1, 2048, "grid cells along z (vertices: z_quads + 1)").in_group("grid");
        p.add_bool("wireframe", &wireframe_, false, "draw the triangles' edges only").in_group("view");
        p.add_bool("facet_shading", &facet_shading_, true, "darken faces turned from a fixed direction")
            .in_group("view");
        use_camera({0, 0, 0}, 70, 35, 28);
    }

private:
    struct WaveParams { float direction, wavelength, amplitude, speed; };

    void init() override { ocean_ = &load_program("ocean", {"ocean.vert", "ocean.frag"}); }

    std::vector<step02::DirectionalWave> waves() const {
        std::vector<step02::DirectionalWave> out;
        for (int i = 0; i < wave_count_; ++i)
            out.push_back({waves_[i].direction, waves_[i].wavelength,
                           double(amplitude_) * waves_[i].amplitude, waves_[i].speed});
        return out;
    }

    void update(double /*time*/, double /*dt*/) override {
        const std::array<float, 3> wanted{plane_size_, float(x_quads_), float(z_quads_)};
        if (wanted != grid_built_for_) {
            grid_.build({plane_size_, plane_size_}, x_quads_, z_quads_);
            grid_built_for_ = wanted;
        }
    }

    void render() override {
        glClearColor(0.06f, 0.07f, 0.09f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);

        const auto list = waves();
        double extent = 0;
        for (const auto& wave : list) extent += std::abs(wave.amplitude);
        step02::upload_waves(*ocean_, list, time());
        ocean_->set("u_view_projection", camera().projection(aspect()) * camera().view());
        ocean_->set("u_height_extent", float(extent));
        ocean_->set("u_facet_shading", int(facet_shading_));
        ocean_->set("u_wireframe", int(wireframe_));
        ocean_->set("u_eye", camera().eye());

        ocean::GpuScope timed(timers(), "ocean");
        glUseProgram(ocean_->id());
        glPolygonMode(GL_FRONT_AND_BACK, wireframe_ ? GL_LINE : GL_FILL);
        grid_.draw();
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glDisable(GL_DEPTH_TEST);
    }

    void ui() override {
        ImGui::Separator();
        ImGui::Text("%d vertices, %d triangles", grid_.vertex_count(), 2 * x_quads_ * z_quads_);
    }

    ocean::ShaderProgram* ocean_ = nullptr;
    ocean::GridMesh grid_;
    std::array<float, 3> grid_built_for_{-1, -1, -1};
    int wave_count_ = 4;
    float amplitude_ = 1;
    std::array<WaveParams, step02::kMaxWaves> waves_{};
    float plane_size_ = 80;
    int x_quads_ = 160, z_quads_ = 160;
    bool wireframe_ = false, facet_shading_ = true;
};

}  // namespace

OCEAN_MAIN(Sine3D)
