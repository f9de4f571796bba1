// step06's light on water on the GPU (shading.glsl) against its CPU reference (shading.hpp):
// Schlick's Fresnel, Smith's Lambda, the microfacet distribution (isotropic, and anisotropic along
// and across a wind), the sun's specular and the subsurface scatter, for GGX and Beckmann, at normals, eyes and suns spread over the hemisphere
// (grazing ones included). Limit: 1e-4 relative to the largest value of each quantity (float).
#include "common/gl.hpp"
#include "common/shader.hpp"
#include "step06_foam_sky/shading.hpp"
#include "tests/gpu/gl_test_context.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <random>

namespace {

using ShadingReadback = ocean_test::GlTest;
using step03::Vec3;

Vec3 random_direction(std::mt19937& random, double min_y) {
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (;;) {
        const Vec3 d{uniform(random), uniform(random), uniform(random)};
        const double length2 = step03::dot(d, d);
        if (length2 > 1e-3 && length2 <= 1 && d.y / std::sqrt(length2) >= min_y) return step03::normalize(d);
    }
}

TEST_F(ShadingReadback, LightOnWaterMatchesTheCpu) {
    constexpr int kSamples = 2048;
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0, 1);
    struct Input {
        Vec3 n, v, l;
        double alpha, height, bubbles;
        step06::Roughness roughness;
    };
    std::vector<Input> inputs;
    std::vector<glm::vec4> packed;
    for (int i = 0; i < kSamples; ++i) {
        // Normals tilted up to ~60 degrees, eyes anywhere above the horizon, suns anywhere (below
        // the surface too: the terms must give nothing there).
        // Alpha along the wind up to 3 times alpha across it, the wind from any heading.
        const double alpha = 0.02 + 0.6 * unit(random), heading = 2 * ocean::kPi * unit(random);
        const Input in{random_direction(random, 0.5), random_direction(random, 0.02), random_direction(random, -1.0),
                       alpha, 1.2 * unit(random), unit(random),
                       {alpha, alpha * (0.33 + 0.67 * unit(random)), std::cos(heading), std::sin(heading)}};
        inputs.push_back(in);
        packed.emplace_back(float(in.n.x), float(in.n.y), float(in.n.z), float(in.alpha));
        packed.emplace_back(float(in.v.x), float(in.v.y), float(in.v.z), float(in.height));
        packed.emplace_back(float(in.l.x), float(in.l.y), float(in.l.z), float(in.bubbles));
        packed.emplace_back(float(in.roughness.along), float(in.roughness.across), float(in.roughness.wind_x),
                            float(in.roughness.wind_z));
    }
    // The inputs as the GPU holds them (float), so both sides see the same directions.
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const glm::vec4 &a = packed[4 * i], &b = packed[4 * i + 1], &c = packed[4 * i + 2], &d = packed[4 * i + 3];
        inputs[i] = {{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}, a.w, b.w, c.w, {d.x, d.y, d.z, d.w}};
    }
    ocean::Buffer in = ocean::make_buffer(), out = ocean::make_buffer();
    glNamedBufferStorage(in.id(), GLsizeiptr(packed.size() * sizeof(glm::vec4)), packed.data(), 0);
    glNamedBufferStorage(out.id(), GLsizeiptr(kSamples * 3 * sizeof(glm::vec4)), nullptr, 0);
    const step06::ScatterSettings s{3.0, 0.35, 0.25, 0.3, {0.05, 0.32, 0.36}, {0.2, 0.45, 0.45}, {0.15, 0.75, 0.6}};
    const Vec3 sun{6.0, 5.5, 4.8};
    for (step06::Microfacet m : {step06::Microfacet::Ggx, step06::Microfacet::Beckmann}) {
        ocean::ShaderProgram program("eval_shading", {std::string(OCEAN_SOURCE_DIR) + "/step06_foam_sky/tests/eval_shading.comp"},
                                     {}, {"MICROFACET " + std::to_string(int(m))});
        ASSERT_FALSE(program.build()) << program.last_error();
        program.set("u_count", kSamples);
        program.set("u_k", glm::vec4(float(s.scatter_crest), float(s.scatter_view), float(s.scatter_lambert), float(s.scatter_bubbles)));
        auto to_glm = [](const Vec3& c) { return glm::vec3(float(c.x), float(c.y), float(c.z)); };
        program.set("u_scatter_colour", to_glm(s.scatter_colour));
        program.set("u_bubble_colour", to_glm(s.bubble_colour));
        program.set("u_crest_colour", to_glm(s.crest_colour));
        program.set("u_sun", to_glm(sun));
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
        glUseProgram(program.id());
        glDispatchCompute(kSamples / 64, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<glm::vec4> gpu(kSamples * 3);
        glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(glm::vec4)), gpu.data());

        const char* names[] = {"Fresnel",   "Lambda",    "D",         "specular",  "scatter r",
                               "scatter g", "scatter b", "D aniso", "Lambda(v) aniso", "Lambda(l) aniso"};
        constexpr int kQuantities = 10;
        double worst[kQuantities] = {}, largest[kQuantities] = {};
        for (int i = 0; i < kSamples; ++i) {
            const Input& q = inputs[std::size_t(i)];
            const Vec3 h = step03::normalize({q.v.x + q.l.x, q.v.y + q.l.y, q.v.z + q.l.z});
            const Vec3 scatter = step06::scatter_term(q.n, q.v, q.l, q.height, q.roughness, q.bubbles, s, sun, m);
            const double cpu[kQuantities] = {step06::fresnel_schlick(step03::dot(q.n, q.v), 0.02),
                                             step06::smith_lambda(step03::dot(q.n, q.v), q.alpha, m),
                                             step06::microfacet_distribution(std::max(step03::dot(q.n, h), 0.0), q.alpha, m),
                                             step06::specular_factor(q.n, q.v, q.l, q.roughness, 0.02, m),
                                             scatter.x, scatter.y, scatter.z,
                                             step06::anisotropic_distribution(q.n, h, q.roughness, m),
                                             step06::anisotropic_lambda(q.n, q.v, q.roughness, m),
                                             step06::anisotropic_lambda(q.n, q.l, q.roughness, m)};
            const float got[kQuantities] = {gpu[3 * i].x,     gpu[3 * i].y,     gpu[3 * i].z,     gpu[3 * i].w,
                                            gpu[3 * i + 1].x, gpu[3 * i + 1].y, gpu[3 * i + 1].z, gpu[3 * i + 1].w,
                                            gpu[3 * i + 2].x, gpu[3 * i + 2].y};
            for (int k = 0; k < kQuantities; ++k) {
                worst[k] = std::max(worst[k], std::abs(got[k] - cpu[k]));
                largest[k] = std::max(largest[k], std::abs(cpu[k]));
            }
        }
        for (int k = 0; k < kQuantities; ++k) {
            EXPECT_GT(largest[k], 0.0) << names[k] << ": the samples never exercise it";
            EXPECT_LT(worst[k] / largest[k], 1e-4) << names[k] << (m == step06::Microfacet::Ggx ? " (GGX)" : " (Beckmann)");
            std::printf("%s %-16s worst %.2e of largest %.3g\n", m == step06::Microfacet::Ggx ? "GGX     " : "Beckmann",
                        names[k], worst[k], largest[k]);
        }
    }
}

}  // namespace
