#include "step06_foam_sky/sea.hpp"

#include "step05_fft/spectrum.hpp"
#include "step06_foam_sky/texture_units.h"
#ifndef OCEAN_GL_PORTABLE
#include "step06_foam_sky/surface_export.hpp"
#endif

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <limits>

namespace step06 {

Sea::Sea() { use_default_sea(params_); }

void Sea::declare(ocean::ParamRegistry& p) {
    params_.declare(p);
    p.remove({"model", "gamma", "energy", "spread", "depth", "tma", "patch_size", "seed", "amplitude_scale",
              "low_cutoff", "high_cutoff"});
    p.add_choice("cascade", &cascade_shown_, {"all", "0", "1", "2", "3"},
                 "the cascades drawn: all, or one alone (0: the longest waves)")
        .in_group("spectrum");
    p.add_float("foam_threshold", &foam_settings_.threshold, -1, 2, "Jacobian below which foam appears (bias)")
        .in_group("foam");
    p.add_float("foam_decay", &foam_settings_.decay_rate, 0, 20,
                "the active whitecap stops breaking as exp(-decay t), per second")
        .in_group("foam");
    p.add_float("foam_residual_decay", &foam_settings_.residual_decay, 0, 20,
                "the residual foam it leaves fades as exp(-decay t), per second")
        .in_group("foam");
}

void Sea::init(ocean::ProgramFactory programs) {
    simulation_ = std::make_unique<SeaSimulation>(programs);
    foam_ = std::make_unique<FoamSimulation>(programs);
}

// The four cascades' spectra from the one the parameters describe, and what the shading needs of
// them: the slope variance each mip level averages away, and the waves shorter than the last.
void Sea::make_spectra() {
    spectra_.clear();
    std::vector<const step05::InitialSpectrum*> pointers;
    height_variance_ = 0;
    unresolved_by_level_.assign(std::size_t(kCascades * kMaxMipLevels), 0.0f);
    description_.clear();
    for (const auto& p : cascade_spectra(params_.spectrum)) {
        spectra_.push_back(std::make_unique<step05::InitialSpectrum>(step05::initial_spectrum(p)));
        pointers.push_back(spectra_.back().get());
        height_variance_ += step05::resolved_variance(p);
        // What each of this cascade's mip levels averages away; past the last level (a pixel
        // wider than the tile) all of it.
        const std::vector<double> by_level = step05::unresolved_slope_variance_by_level(p);
        const std::size_t base = (pointers.size() - 1) * kMaxMipLevels;
        for (std::size_t l = 0; l < kMaxMipLevels; ++l)
            unresolved_by_level_[base + l] = float(by_level[std::min(l, by_level.size() - 1)]);
        // For the panel: the cascade's tile and the wavelengths of its band (2 pi / |k|).
        char line[128];
        std::snprintf(line, sizeof line, "cascade %zu: tile %.1f m, waves %.2f m .. %.2f m", pointers.size() - 1,
                      p.patch_size, 2 * step05::kPi / p.high_cutoff,
                      p.low_cutoff > 0 ? 2 * step05::kPi / p.low_cutoff : std::numeric_limits<double>::infinity());
        description_.push_back(line);
    }
    simulation_->set_spectra(pointers);
    foam_->resize(params_.spectrum.resolution);
    // The waves shorter than the last cascade, down to the capillaries (short_waves.hpp):
    // microfacets everywhere, whatever the pixel resolves.
    short_wave_slope_variance_ = short_wave_slope_variance_beyond(params_.spectrum);
    wind_heading_ = wind_heading(params_.spectrum);
    foam_->set_wind(wind_heading_, params_.spectrum.wind_speed);

}

void Sea::simulate(double time, glm::dvec3 eye) {
    if (spectra_made_for_ != params_.changes.value || spectra_.empty()) {
        spectra_made_for_ = params_.changes.value;
        make_spectra();
    }
    for (int c = 0; c < kCascades; ++c) {
        cascade_view_.patch_sizes[std::size_t(c)] = float(spectra_[std::size_t(c)]->patch_size);
        cascade_view_.enabled[std::size_t(c)] = cascade_shown_ == 0 || cascade_shown_ == c + 1;
    }
    cascade_view_.place_origin(world_origin_near({eye.x, eye.z}));
#ifdef OCEAN_GL_PORTABLE
    simulation_->simulate(time, params_.choppiness);
#else
    // backend auto: FFTW and the GPU FFT timed on the first frames, the faster kept (step05).
    simulation_->simulate(time, step05::Backend::Auto, params_.choppiness);
    if (auto decision = simulation_->take_auto_decision()) std::cout << "backend auto " << *decision << std::endl;  // flushed: a log follows the run
#endif
}

void Sea::update_foam(double dt, glm::dvec3 eye, glm::vec3 forward) {
    foam_->update(simulation_->maps(), cascade_view_, {eye.x, eye.z}, {forward.x, forward.z}, dt, foam_settings_,
                  extra_waves_);
}

std::vector<std::string> Sea::shader_defines() const {
    return {"EXTRA_WAVES " + std::to_string(int(extra_waves_ != nullptr && !extra_waves_->empty()))};
}

void Sea::bind_maps(const ocean::ShaderProgram& p) const {
    cascade_view_.upload(p);
    simulation_->bind_maps(p);
    if (extra_waves_ != nullptr && !extra_waves_->empty()) extra_waves_->bind(p, cascade_view_.origin);
}

void Sea::bind_for_shading(const ocean::ShaderProgram& p) const {
    bind_maps(p);
    foam_->bind(p, UNIT_FOAM);
    foam_->bind_pattern(p, UNIT_FOAM_PATTERN);
    foam_->bind_streak_lines(p, UNIT_STREAK_LINES);
    p.set("u_unresolved_slope_variance", unresolved_by_level_);
    p.set("u_short_wave_slope_variance",
          glm::vec2(float(short_wave_slope_variance_.upwind), float(short_wave_slope_variance_.crosswind)));
    p.set("u_wind_heading", glm::vec2(wind_heading_));
}

double Sea::largest_displacement() const {
    return step05::largest_displacement(height_variance_, params_.choppiness);
}

std::vector<double> Sea::tile_sizes() const {
    std::vector<double> tiles;
    for (const auto& s : spectra_) tiles.push_back(s->patch_size);
    return tiles;
}

#ifndef OCEAN_GL_PORTABLE
std::vector<std::pair<std::string, double>> Sea::time_backends(double time) {
    const step05::BackendTimes times = step05::time_backends(*simulation_, time, 5);
    for (const auto& line : times.lines()) std::cout << "bench: " << line << "\n";
    return times.figures();
}

void Sea::export_surface(const std::string& dir, ocean::ProgramFactory& programs, double time,
                         const ocean::ParamRegistry& params) const {
    step06::export_surface(dir, programs, *simulation_, *foam_, cascade_view_, time, params_.choppiness,
                           short_wave_slope_variance_, params);
}
#endif

}  // namespace step06
