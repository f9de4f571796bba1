#include "step06_foam_sky/foam.hpp"

#include "common/error.hpp"

#include <cmath>
#include <utility>

namespace step06 {

void FoamSimulation::resize(int n, int layers) {
    if (n == n_ && layers == layers_ && texture_) return;
    n_ = n;
    layers_ = layers;
    texture_ = ocean::make_texture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(texture_.id(), 1 + int(std::log2(double(n))), GL_R32F, n, n, layers);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
    fill(0);
    warm_start_ = true;
}

void FoamSimulation::fill(float value) {
    glClearTexImage(texture_.id(), 0, GL_RED, GL_FLOAT, &value);
    warm_start_ = false;
}

void FoamSimulation::update(const step05::GpuOcean& ocean, double dt, const FoamSettings& s,
                            const std::array<float, 4>& weights) {
    ocean::ShaderProgram* p = programs_("foam.comp", {"step06_foam_sky/shaders/foam.comp"}, {});
    if (p == nullptr) throw ocean::Error("foam.comp does not build");
    p->set("u_dt", float(dt));
    p->set("u_threshold", float(s.threshold));
    p->set("u_injection", float(s.injection));
    p->set("u_decay_rate", float(s.decay_rate));
    p->set("u_cascade_weight", std::vector<float>(weights.begin(), weights.end()));
    p->set("u_n", n_);
    p->set("u_layer_count", layers_);
    p->set("u_warm_start", int(std::exchange(warm_start_, false)));
    p->set("u_displacement", 0);
    p->set("u_slopes", 1);
    glBindTextureUnit(0, ocean.displacement_texture());
    glBindTextureUnit(1, ocean.slopes_texture());
    glBindImageTexture(0, texture_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32F);
    glUseProgram(p->id());
    const GLuint groups = GLuint((n_ + 7) / 8);
    glDispatchCompute(groups, groups, GLuint(layers_));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    glGenerateTextureMipmap(texture_.id());  // distant foam averages instead of sparkling
}

std::vector<float> FoamSimulation::read_layer(int layer) const {
    std::vector<float> values(std::size_t(n_) * n_);
    glGetTextureSubImage(texture_.id(), 0, 0, 0, layer, n_, n_, 1, GL_RED, GL_FLOAT,
                         GLsizei(values.size() * sizeof(float)), values.data());
    return values;
}

}  // namespace step06
