#include "step05_fft/fragment_simulation.hpp"

#include "step05_fft/box_mipmaps.hpp"
#include "step05_fft/ocean_maps.hpp"

#include "common/error.hpp"

#include <string>

namespace step05 {

ocean::ShaderProgram& FragmentSimulation::program(const std::string& name, const std::vector<std::string>& files) {
    ocean::ShaderProgram* p = programs_(name, files, {});
    if (p == nullptr) throw ocean::Error("shader " + name + " does not build");
    return *p;
}

void FragmentSimulation::allocate(int n, int cascades) {
    n_ = 0;  // until every texture is made: a throw below leaves no half-made simulation to run
    h0_.clear();
    phase_.clear();
    for (int c = 0; c < cascades; ++c) {
        h0_.push_back(ocean::make_float_texture_2d(GL_RGBA32F, n, n));
        phase_.push_back(ocean::make_float_texture_2d(GL_R32F, n, n));
    }
    phase_scratch_.assign(std::size_t(n) * std::size_t(n), 0.0f);
    evolve_target_ = ocean::make_framebuffer();
    for (int t = 0; t < 2; ++t) {
        spectra_[std::size_t(t)] = ocean::make_float_texture_2d(GL_RGBA32F, n, n);
        if (!ocean::attach_texture_2d(evolve_target_, GL_COLOR_ATTACHMENT0 + GLenum(t), spectra_[std::size_t(t)]))
            throw ocean::Error("this GL cannot render into 32-bit float textures, the fragment simulation's"
                               " (ES needs EXT_color_buffer_float)");
        fft_[std::size_t(t)] = std::make_unique<FragmentFft>(programs_, n);
    }
    displacement_ = ocean::make_map_texture_2d_array(GL_RGBA32F, n, cascades, mip_levels(n));
    slopes_ = ocean::make_map_texture_2d_array(GL_RGBA32F, n, cascades, mip_levels(n));
    // One framebuffer a cascade, made once: its two attachments are that cascade's layer of each map.
    assemble_targets_.clear();
    for (int c = 0; c < cascades; ++c) {
        assemble_targets_.push_back(ocean::make_framebuffer());
        if (!ocean::attach_texture_layer(assemble_targets_.back(), GL_COLOR_ATTACHMENT0, displacement_, 0, c) ||
            !ocean::attach_texture_layer(assemble_targets_.back(), GL_COLOR_ATTACHMENT1, slopes_, 0, c))
            throw ocean::Error("this GL cannot render into the simulation's maps (32-bit float array layers)");
    }
    // The maps are sampled with linear filtering and mipmaps: core in GL, an extension in ES 3.0.
    if (!ocean::float_textures_filterable())
        throw ocean::Error("this GL cannot filter 32-bit float textures (ES needs OES_texture_float_linear)");
    no_vertices_ = ocean::make_vertex_array();
    n_ = n;
}

void FragmentSimulation::set_spectra(const std::vector<const InitialSpectrum*>& cascades) {
    if (cascades.empty() || cascades.size() > 4) throw ocean::Error("the fragment simulation takes 1 to 4 cascades");
    const int n = cascades.front()->n;
    for (const InitialSpectrum* s : cascades)
        if (s->n != n) throw ocean::Error("the fragment simulation's cascades must share one resolution");
    if (n != n_ || cascades.size() != cascades_.size()) allocate(n, int(cascades.size()));
    cascades_ = cascades;
    // Each texel holds its mode and the mode at -k, which evolve_mode pairs with it.
    std::vector<float> h0(std::size_t(n) * std::size_t(n) * 4);
    for (std::size_t c = 0; c < cascades.size(); ++c) {
        const InitialSpectrum& s = *cascades[c];
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::size_t here = std::size_t(j * n + i);
                const std::size_t mirror = std::size_t(((n - j) % n) * n + (n - i) % n);
                h0[4 * here + 0] = float(s.h0[here].real());
                h0[4 * here + 1] = float(s.h0[here].imag());
                h0[4 * here + 2] = float(s.h0[mirror].real());
                h0[4 * here + 3] = float(s.h0[mirror].imag());
            }
        ocean::upload_float_texture_2d(h0_[c], GL_RGBA32F, n, n, h0.data());
    }
}

void FragmentSimulation::evolve(int cascade, double time) {
    const InitialSpectrum& s = *cascades_[std::size_t(cascade)];
    for (std::size_t m = 0; m < phase_scratch_.size(); ++m) phase_scratch_[m] = float(reduced_phase(s.omega[m], time));
    ocean::upload_float_texture_2d(phase_[std::size_t(cascade)], GL_R32F, n_, n_, phase_scratch_.data());

    ocean::ShaderProgram& p = program("evolve.frag", {"common/shaders/fullscreen.vert", "step05_fft/shaders/evolve.frag"});
    glUseProgram(p.id());
    p.set("u_n", n_);
    p.set("u_patch_size", float(s.patch_size));
    p.set("u_h0", 0);
    p.set("u_phase", 1);
    draw_two_into_two(h0_[std::size_t(cascade)], phase_[std::size_t(cascade)], evolve_target_);
}

void FragmentSimulation::assemble(int cascade, const ocean::Texture& fields_01, const ocean::Texture& fields_23,
                                  float choppiness) {
    ocean::ShaderProgram& p = program("assemble.frag", {"common/shaders/fullscreen.vert", "step05_fft/shaders/assemble.frag"});
    glUseProgram(p.id());
    p.set("u_choppiness", choppiness);
    p.set("u_fields_01", 0);
    p.set("u_fields_23", 1);
    draw_two_into_two(fields_01, fields_23, assemble_targets_[std::size_t(cascade)]);
}

// Both passes read two textures (units 0 and 1) and write two attachments in one draw.
void FragmentSimulation::draw_two_into_two(const ocean::Texture& in_0, const ocean::Texture& in_1,
                                           const ocean::Framebuffer& target) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.id());
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, both);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, in_0.id());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, in_1.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, 0);  // unbound again: a later pass may write what these held
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void FragmentSimulation::simulate(double time, float choppiness) {
    if (n_ == 0) throw ocean::Error("FragmentSimulation::simulate before set_spectra");
    const ocean::OffscreenPassState keep(no_vertices_.id());  // what was bound, put back at the end
    for (int c = 0; c < cascade_count(); ++c) {
        glViewport(0, 0, n_, n_);
        evolve(c, time);
        const ocean::Texture& fields_01 = fft_[0]->inverse(spectra_[0]);
        const ocean::Texture& fields_23 = fft_[1]->inverse(spectra_[1]);
        assemble(c, fields_01, fields_23, choppiness);
    }
    ocean::generate_mipmaps(displacement_, GL_TEXTURE_2D_ARRAY);
    ocean::generate_mipmaps(slopes_, GL_TEXTURE_2D_ARRAY);
}

std::vector<float> FragmentSimulation::read_map(bool slopes, int level) const {
    std::vector<float> texels;
    for (int c = 0; c < cascade_count(); ++c) {
        const std::vector<float> layer =
            ocean::read_texture_layer(slopes ? slopes_.id() : displacement_.id(), level, c, std::max(1, n_ >> level));
        texels.insert(texels.end(), layer.begin(), layer.end());
    }
    return texels;
}

}  // namespace step05
