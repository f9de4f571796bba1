// step06's sea, the first part of its program: step05's spectrum split into four cascades
// (cascades.hpp), simulated together each frame by step05's simulation, and the foam their
// sum leaves behind (foam.hpp). What the passes that draw it need, it binds.
//
// A program declares the sea's parameters in its constructor (declare), makes its GPU side once a
// GL context exists (init), then each frame: simulate, update_foam, and the bind_* calls of the
// passes that read it.
#pragma once

#include "common/params.hpp"
#include "common/shader.hpp"
#include "step05_fft/ocean_params.hpp"
#include "step05_fft/sea_simulation.hpp"
#include "step06_foam_sky/cascades.hpp"
#include "step06_foam_sky/extra_waves.hpp"
#include "step06_foam_sky/foam.hpp"
#include "step06_foam_sky/short_waves.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace step06 {

// The simulation the sea runs: step05's, as the profile chose it (sea_simulation.hpp: compute
// passes with a choice of transform in GL 4.5, fragment passes without compute shaders).
using step05::SeaSimulation;

class Sea {
public:
    Sea();  // step06's sea: a near gale (14 m/s) over a 500 m first tile (use_default_sea)

    // The sea state (wind, fetch, swell, choppiness, resolution), which cascades are drawn, and the
    // foam's two rates. The spectrum's shape (model, gamma, cut-offs, ...) is step05's lesson: its
    // parameters stay at their defaults here.
    void declare(ocean::ParamRegistry& p);
    void init(ocean::ProgramFactory programs);

    // The cascades' maps at `time`, around a world origin near the eye (x, z in metres, double:
    // anywhere on the ocean). New spectra first when a sea parameter moved.
    void simulate(double time, glm::dvec3 eye);
    // The foam grown and faded over dt seconds, kept around the camera and ahead of it.
    void update_foam(double dt, glm::dvec3 eye, glm::vec3 forward);

    // For the mesh: the tiles, the world origin and the cascades' maps (units 0 and 1).
    void bind_maps(const ocean::ShaderProgram& p) const;
    // For the shading: the maps, the foam and its bubble pattern, and what each pixel cannot
    // resolve (the slope variance per mip level, and the waves shorter than the last cascade).
    void bind_for_shading(const ocean::ShaderProgram& p) const;
    bool has_streaks() const { return foam_->streaks(); }  // the residual combed into streaks (Beaufort 7 and up)
    // Extra waves on a grid of their own (extra_waves.hpp), drawn, shaded and foaming with the
    // cascades from the next frame on; nullptr: none. The sea does not own them: they must outlive
    // it or be taken away first.
    void add_extra_waves(const ExtraWaves* waves) { extra_waves_ = waves; }
    // The variant every program that reads the maps is compiled in: with or without extra waves.
    std::vector<std::string> shader_defines() const;

    const CascadeView& cascades() const { return cascade_view_; }
    glm::dvec3 world_origin() const { return {cascade_view_.origin.x, 0.0, cascade_view_.origin.y}; }
    // How far the waves can move a point, metres: the mesh's culling boxes are widened by it.
    double largest_displacement() const;
    double height_variance() const { return height_variance_; }  // m^2, of the summed cascades' heights
    double choppiness() const { return params_.choppiness; }  // l: how far the crests are pulled together
    const step05::SpectrumParams& spectrum() const { return params_.spectrum; }
    double wind_direction() const { return params_.spectrum.wind_direction; }  // degrees, where it blows to
    std::vector<double> tile_sizes() const;  // metres, the four cascades'
    // A line per cascade (tile and band), for the panel.
    const std::vector<std::string>& description() const { return description_; }

    SeaSimulation& simulation() { return *simulation_; }
    const SeaSimulation& simulation() const { return *simulation_; }
#ifndef OCEAN_GL_PORTABLE
    // GL 4.5 only (compute shaders: step05's backends, the export's grid).
    // Whether backend auto is still timing the two transforms (--bench waits for it).
    bool choosing_backend() const { return !simulation_ || simulation_->auto_deciding(); }
    // --bench's extra figures: the four cascades' transforms through each backend and the FFTW
    // floor (step05's time_backends), printed as `bench:` lines and returned as (label, ms).
    std::vector<std::pair<std::string, double>> time_backends(double time);
    // --export: the summed surface and the foam on one grid around the camera (surface_export.hpp).
    void export_surface(const std::string& dir, ocean::ProgramFactory& programs, double time,
                        const ocean::ParamRegistry& params) const;
#endif

private:
    void make_spectra();

    step05::OceanParams params_;
    FoamSettings foam_settings_;
    int cascade_shown_ = 0;  // 0: all; c + 1: cascade c alone
    std::unique_ptr<SeaSimulation> simulation_;
    std::unique_ptr<FoamSimulation> foam_;
    std::vector<std::unique_ptr<step05::InitialSpectrum>> spectra_;
    unsigned spectra_made_for_ = 0;  // params_.changes when the spectra were made
    CascadeView cascade_view_;       // this frame's, made by simulate()
    double height_variance_ = 0;     // m^2, of the summed cascades
    std::vector<float> unresolved_by_level_;  // kMaxMipLevels per cascade
    SlopeVariance short_wave_slope_variance_;
    glm::dvec2 wind_heading_{1.0, 0.0};
    const ExtraWaves* extra_waves_ = nullptr;
    std::vector<std::string> description_;
};

}  // namespace step06
