// The inverse 2D FFT as fragment passes (shaders/fft_stockham.frag): what a profile without compute
// shaders (macOS's GL 4.1, ES 3.0, WebGL 2) has in place of fft.comp, the way the WebGL oceans do
// it. Two complex N x N fields travel together in a GL_RGBA32F texture ((re, im) of one in .rg,
// of the other in .ba); each radix-2 Stockham stage is one full-screen draw into the other
// texture of a pair, 2 log2 N draws in all.
#pragma once

#include "common/gl_texture.hpp"
#include "common/shader.hpp"

namespace step05 {

class FragmentFft {
public:
    // `n`: a power of two from 2 to 4096.
    FragmentFft(ocean::ProgramFactory programs, int n);
    int size() const { return n_; }

    // The inverse 2D FFT, y[x, z] = sum over (m, l) of x[m, l] e^{+2 pi i (m x + l z) / N}
    // (unnormalised, like FFTW_BACKWARD and fft.comp), of the two fields in `source` (N x N,
    // GL_RGBA32F, only read). Returns the texture of this object's pair that holds the result,
    // valid until the next call. The draw framebuffer, viewport, blending and program in use are
    // put back as they were.
    const ocean::Texture& inverse(const ocean::Texture& source);

private:
    // One stage: `source` read, texture `target` of the pair written, along `axis` with span M.
    void stage(GLuint source, int target, int axis, int span);

    ocean::ProgramFactory programs_;
    int n_;
    ocean::Texture pair_[2];
    ocean::Framebuffer framebuffers_[2];
    ocean::VertexArray no_vertices_;  // the full-screen triangle's vertices come from gl_VertexID
};

}  // namespace step05
