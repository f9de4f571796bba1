// The FFT ocean's simulation as fragment passes: what OceanSimulation does with compute shaders,
// for the profiles that have none (macOS's GL 4.1, ES 3.0, WebGL 2). Each frame, per cascade:
//   evolve    one draw into two RGBA32F textures: the four packed spectra (evolve.frag);
//   transform the fragment FFT (fragment_fft.hpp) of each texture: two complex fields each;
//   assemble  one draw into the cascade's layer of the two maps the renderer samples (assemble.frag);
// then the maps' mipmaps. The maps are the same as OceanSimulation's: a 2D array texture each,
// one layer a cascade, (l Dx, h, l Dz, l dDx/dz) and (dh/dx, dh/dz, l dDx/dx, l dDz/dz).
// omega t is reduced modulo 2 pi on the CPU in double (ES has no doubles) and uploaded as a phase
// per mode, so the sea stays right after days of simulated time, as evolve.comp keeps it.
#pragma once

#include "common/gl_texture.hpp"
#include "common/shader.hpp"
#include "step05_fft/fragment_fft.hpp"
#include "step05_fft/simulation_maps.hpp"
#include "step05_fft/spectrum.hpp"

#include <array>
#include <memory>
#include <vector>

namespace step05 {

class FragmentSimulation {
public:
    explicit FragmentSimulation(ocean::ProgramFactory programs) : programs_(std::move(programs)) {}

    // Uploads h0 of each cascade (all of one resolution, 1 to 4 of them) and keeps their omega for
    // the phases. Call when the spectrum changes; the textures are re-made when the size or the
    // cascade count changes. The spectra must outlive the next simulate(). Throws ocean::Error
    // for no cascade, more than 4, mixed resolutions, or a GL that cannot render into or filter
    // 32-bit float textures.
    void set_spectra(const std::vector<const InitialSpectrum*>& cascades);

    // One frame: evolve to `time`, transform, assemble with choppiness `choppiness`, mipmaps. The
    // draw framebuffer, viewport and program in use are put back as they were.
    void simulate(double time, float choppiness);

    int resolution() const { return n_; }
    int cascade_count() const { return int(cascades_.size()); }
    GLuint displacement_texture() const { return displacement_.id(); }  // 2D array, a layer a cascade
    GLuint slopes_texture() const { return slopes_.id(); }
    // The two maps, for what reads them (SimulationMaps::bind); bind_maps(p) is maps().bind(p).
    SimulationMaps maps() const { return {displacement_.id(), slopes_.id()}; }
    void bind_maps(const ocean::ShaderProgram& program) const { maps().bind(program); }
    // One mip level of the displacement (or slopes) map, every cascade: layer major, RGBA (tests).
    std::vector<float> read_map(bool slopes, int level) const;

private:
    ocean::ShaderProgram& program(const std::string& name, const std::vector<std::string>& files);
    void allocate(int n, int cascades);
    void evolve(int cascade, double time);
    void assemble(int cascade, const ocean::Texture& fields_01, const ocean::Texture& fields_23, float choppiness);
    void draw_two_into_two(const ocean::Texture& in_0, const ocean::Texture& in_1, const ocean::Framebuffer& target);

    ocean::ProgramFactory programs_;
    std::vector<const InitialSpectrum*> cascades_;
    int n_ = 0;
    std::vector<ocean::Texture> h0_;     // per cascade: (h0(k), h0(-k)), RGBA32F, uploaded once
    std::vector<ocean::Texture> phase_;  // per cascade: omega t mod 2 pi, R32F, uploaded each frame
    std::vector<float> phase_scratch_;
    std::array<ocean::Texture, 2> spectra_;  // the four packed spectra of one cascade, two a texture
    ocean::Framebuffer evolve_target_;                 // its two attachments: spectra_
    std::vector<ocean::Framebuffer> assemble_targets_;  // per cascade: its layer of each map
    std::array<std::unique_ptr<FragmentFft>, 2> fft_;  // one a texture: each keeps its result
    ocean::Texture displacement_, slopes_;
    ocean::VertexArray no_vertices_;  // the full-screen triangle's vertices come from gl_VertexID
};

}  // namespace step05
