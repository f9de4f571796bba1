#include "step05_fft/spectrum_view.hpp"

#include "common/gl_texture.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace step05 {

void SpectrumView::update(const SpectrumParams& p, const InitialSpectrum& s) {
    peak_omega_ = peak_omega_of(p);
    omega_max_ = peak_omega_ > 0 ? 4 * peak_omega_ : 4;
    model_ = p.model == SpectrumModel::Jonswap ? "JONSWAP" : "Phillips";
    // S(omega) = F(k) dk/domega: the omnidirectional energy per unit angular frequency.
    plot_.assign(200, 0.0f);
    for (std::size_t i = 1; i < plot_.size(); ++i) {
        const double omega = omega_max_ * double(i) / double(plot_.size() - 1);
        // Invert the dispersion relation by bisection (it is monotonic in k).
        double lo = 0, hi = 1e4;
        for (int it = 0; it < 80; ++it) {
            const double mid = 0.5 * (lo + hi);
            (dispersion(mid, p.depth) < omega ? lo : hi) = mid;
        }
        const double k = 0.5 * (lo + hi);
        const double dk_domega = 1.0 / dispersion_derivative(k, p.depth);
        plot_[i] = float(p.amplitude_scale * p.amplitude_scale * omnidirectional_k(p, k) * dk_domega);
    }
    significant_height_ = 4 * std::sqrt(resolved_variance(p));
    growth_law_height_ = 4 * std::sqrt(growth_law_variance(p.wind_speed, p.fetch));
    cem_height_ = cem_significant_height(p.wind_speed, p.fetch);

    // The tile's spectrum as an image, k = 0 in the middle: log10 of each mode's energy over 6 decades.
    n_ = s.n;
    double top = 0;
    for (double d : s.density) top = std::max(top, d);
    std::vector<std::uint8_t> pixels(std::size_t(n_) * n_ * 4, 0);
    for (int y = 0; y < n_; ++y)
        for (int x = 0; x < n_; ++x) {
            const int i = (x + n_ / 2) % n_, j = (y + n_ / 2) % n_;  // shift k = 0 to the centre
            const double d = s.density[std::size_t(j) * n_ + i];
            const double t = d > 0 && top > 0 ? std::clamp(1 + std::log10(d / top) / 6, 0.0, 1.0) : 0.0;
            std::uint8_t* px = &pixels[(std::size_t(y) * n_ + x) * 4];
            px[0] = std::uint8_t(255 * std::pow(t, 1.5));
            px[1] = std::uint8_t(255 * t);
            px[2] = std::uint8_t(255 * std::sqrt(t));
            px[3] = 255;
        }
    texture_ = ocean::make_colour_texture_2d(n_, n_, pixels.data());
}

void SpectrumView::draw_ui() const {
    if (!ImGui::CollapsingHeader("spectrum plot", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const float top = plot_.empty() ? 1.0f : *std::max_element(plot_.begin(), plot_.end());
    ImGui::Text("%s S(omega), omega from 0 to %.2f rad/s", model_.c_str(), omega_max_);
    ImGui::PlotLines("##S", plot_.data(), int(plot_.size()), 0, nullptr, 0.0f, std::max(top, 1e-9f), ImVec2(ImGui::GetContentRegionAvail().x, 80));
    // Mark omega_p with a vertical line over the plot.
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    const float x = min.x + float(peak_omega_ / omega_max_) * (max.x - min.x);
    ImGui::GetWindowDrawList()->AddLine(ImVec2(x, min.y), ImVec2(x, max.y), IM_COL32(255, 200, 60, 255));
    if (peak_omega_ > 0)
        ImGui::Text("omega_p = %.3f rad/s (T_p %.1f s, wavelength %.0f m)", peak_omega_, 2 * kPi / peak_omega_,
                    2 * kPi * kGravity / (peak_omega_ * peak_omega_));
    ImGui::Text("Hs = 4 sqrt(variance) = %.2f m on this tile", significant_height_);
    // What observed seas of this wind and fetch have (README, "Heights against observations").
    ImGui::Text("observed seas: %.2f m (JONSWAP growth law), %.2f m (CEM)", growth_law_height_, cem_height_);
    if (texture_) {
        ImGui::TextUnformatted("log10 energy per mode, k = 0 at the centre:");
        ImGui::Image(reinterpret_cast<ImTextureID>(std::uintptr_t(texture_.id())), ImVec2(160, 160));
    }
}

}  // namespace step05
