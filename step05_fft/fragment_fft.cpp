#include "step05_fft/fragment_fft.hpp"

#include "common/error.hpp"

#include <string>

namespace step05 {

FragmentFft::FragmentFft(ocean::ProgramFactory programs, int n) : programs_(std::move(programs)), n_(n) {
    if (n < 2 || n > 4096 || (n & (n - 1)) != 0)
        throw ocean::Error("the fragment FFT needs a power of two from 2 to 4096, not " + std::to_string(n));
    for (int t = 0; t < 2; ++t) {
        pair_[t] = ocean::make_float_texture_2d(GL_RGBA32F, n, n);
        framebuffers_[t] = ocean::make_framebuffer();
        if (!ocean::attach_texture_2d(framebuffers_[t], GL_COLOR_ATTACHMENT0, pair_[t]))
            throw ocean::Error("this GL cannot render into 32-bit float textures, the fragment FFT's"
                               " (ES needs EXT_color_buffer_float)");
    }
    no_vertices_ = ocean::make_vertex_array();
}

const ocean::Texture& FragmentFft::inverse(const ocean::Texture& source) {
    const ocean::OffscreenPassState keep(no_vertices_.id());  // what was bound, put back at the end
    glViewport(0, 0, n_, n_);
    glActiveTexture(GL_TEXTURE0);
    // Each stage reads the texture the last one wrote: the source, then the pair in turn.
    GLuint read = source.id();
    int write = 0;
    for (int axis = 0; axis < 2; ++axis)
        for (int span = 1; span < n_; span *= 2) {
            stage(read, write, axis, span);
            read = pair_[write].id();
            write = 1 - write;
        }
    glBindTexture(GL_TEXTURE_2D, 0);
    return pair_[1 - write];
}

void FragmentFft::stage(GLuint source, int target, int axis, int span) {
    ocean::ShaderProgram* program =
        programs_("fft_stockham.frag", {"common/shaders/fullscreen.vert", "step05_fft/shaders/fft_stockham.frag"}, {});
    if (program == nullptr) throw ocean::Error("shader fft_stockham.frag does not build");  // the log said why
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers_[target].id());
    glBindTexture(GL_TEXTURE_2D, source);
    glUseProgram(program->id());
    program->set("u_axis", axis);
    program->set("u_span", span);
    program->set("u_size", n_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace step05
