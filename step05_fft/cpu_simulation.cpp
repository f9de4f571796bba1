#include "step05_fft/cpu_simulation.hpp"

#include "common/error.hpp"
#include "common/platform.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <unordered_map>

namespace step05 {

std::string default_wisdom_file() {
    const auto exe = ocean::platform::executable_path();
    if (exe.empty()) return "";
    return (exe.parent_path() / "fftwf.wisdom").string();
}

CpuSimulation::CpuSimulation(int n, int cascades, std::string wisdom_file)
    : n_(n), layers_(4 * cascades), fft_(n, 4 * cascades, wisdom_file), data_(fft_.data()) {
    threads_ = fft_.threads();
}

CpuSimulation::~CpuSimulation() = default;

void CpuSimulation::set_spectra(const std::vector<const InitialSpectrum*>& cascades) {
    if (int(cascades.size()) * 4 != layers_) throw ocean::Error("CPU simulation: cascade count changed");
    modes_.clear();
    modes_.reserve(std::size_t(layers_ / 4) * n_ * n_);
    omegas_.clear();
    std::unordered_map<double, std::uint32_t> phase_of;  // exact omegas: symmetric k give equal ones
    for (const InitialSpectrum* s : cascades) {
        if (s->n != n_) throw ocean::Error("CPU simulation: resolution changed");
        for (int j = 0; j < n_; ++j)
            for (int i = 0; i < n_; ++i) {
                const std::size_t index = std::size_t(j) * n_ + i;
                const std::size_t minus = std::size_t((n_ - j) % n_) * n_ + std::size_t((n_ - i) % n_);
                const double kx = wavenumber(i, n_, s->patch_size), kz = wavenumber(j, n_, s->patch_size);
                const double k = std::hypot(kx, kz);
                Mode m;
                m.h0 = std::complex<float>(s->h0[index]);
                m.h0_minus_conj = std::complex<float>(std::conj(s->h0[minus]));
                const auto [entry, added] = phase_of.try_emplace(s->omega[index], std::uint32_t(omegas_.size()));
                if (added) omegas_.push_back(s->omega[index]);
                m.phase = entry->second;
                m.ux = k > 0 ? float(kx / k) : 0.0f;
                m.uz = k > 0 ? float(kz / k) : 0.0f;
                m.kx = float(kx);
                m.kz = float(kz);
                if (k == 0) m.h0 = m.h0_minus_conj = 0.0f;  // the mean level: zero
                modes_.push_back(m);
            }
    }
    phases_.assign(omegas_.size(), 1.0f);
}

template <class Work>
void CpuSimulation::in_parallel(int parts, const Work& work) const {
    const int workers = std::min(threads_, parts);
    std::vector<std::thread> helpers;
    for (int w = 1; w < workers; ++w)
        helpers.emplace_back([&work, parts, workers, w] {
            for (int part = w; part < parts; part += workers) work(part);
        });
    for (int part = 0; part < parts; part += workers) work(part);
    for (std::thread& helper : helpers) helper.join();
}

void CpuSimulation::evolve_range(std::size_t begin, std::size_t end) {
    const std::size_t area = std::size_t(n_) * n_;
    for (std::size_t index = begin; index < end; ++index) {
        const Mode& q = modes_[index];
        const std::size_t c = index / area, m = index - c * area;
        std::complex<float>* f0 = data_ + std::size_t(c * 4) * area;  // h + i Dx
        std::complex<float>* f1 = f0 + area;                         // Dz + i dh/dx
        std::complex<float>* f2 = f1 + area;                         // dh/dz + i dDx/dx
        std::complex<float>* f3 = f2 + area;                         // dDz/dz + i dDx/dz
        const float cs = phases_[q.phase].real(), sn = phases_[q.phase].imag();
        // h = h0 e^{-i phase} + conj(h0(-k)) e^{+i phase}: crests along +k.
        const float hr = q.h0.real() * cs + q.h0.imag() * sn + q.h0_minus_conj.real() * cs - q.h0_minus_conj.imag() * sn;
        const float hi = q.h0.imag() * cs - q.h0.real() * sn + q.h0_minus_conj.imag() * cs + q.h0_minus_conj.real() * sn;
        // i * a * h = (-a hi, a hr); with D = +i k/|k| h and slopes i k h (ocean_maps.cpp's packing).
        const float dxr = -q.ux * hi, dxi = q.ux * hr, dzr = -q.uz * hi, dzi = q.uz * hr;
        const float sxr = -q.kx * hi, sxi = q.kx * hr, szr = -q.kz * hi, szi = q.kz * hr;
        const float dxxr = -q.kx * q.ux * hr, dxxi = -q.kx * q.ux * hi;
        const float dzzr = -q.kz * q.uz * hr, dzzi = -q.kz * q.uz * hi;
        const float dxzr = -q.kx * q.uz * hr, dxzi = -q.kx * q.uz * hi;
        // a + i b for complex a, b: (a.re - b.im, a.im + b.re).
        f0[m] = {hr - dxi, hi + dxr};
        f1[m] = {dzr - sxi, dzi + sxr};
        f2[m] = {szr - dxxi, szi + dxxr};
        f3[m] = {dzzr - dxzi, dzzi + dxzr};
    }
}

void CpuSimulation::run(double time) {
    // Every mode is independent: the work is split evenly between the cores, as FFTW's threads.
    const int parts = threads_;
    const double turns_per_radian = 1.0 / (2 * kPi);
    in_parallel(parts, [&](int part) {
        const std::size_t count = omegas_.size();
        for (std::size_t i = count * std::size_t(part) / std::size_t(parts); i < count * std::size_t(part + 1) / std::size_t(parts); ++i) {
            // The phase reduced in double (omega t grows without bound: days of clock), the rest
            // in float, as evolve.comp. Whole turns removed by floor: cheaper than fmod, same result.
            const double radians = omegas_[i] * time;
            const float p = float(radians - 2 * kPi * std::floor(radians * turns_per_radian));
            phases_[i] = {std::cos(p), std::sin(p)};
        }
    });
    in_parallel(parts, [&](int part) {
        const std::size_t count = modes_.size();
        evolve_range(count * std::size_t(part) / std::size_t(parts), count * std::size_t(part + 1) / std::size_t(parts));
    });
    fft_.run();
}

void CpuSimulation::assemble_layer(int cascade, float l) {
    const std::size_t area = std::size_t(n_) * n_;
    const std::complex<float>* f0 = data_ + std::size_t(cascade * 4) * area;  // (h, Dx)
    const std::complex<float>* f1 = f0 + area;                               // (Dz, dh/dx)
    const std::complex<float>* f2 = f1 + area;                               // (dh/dz, dDx/dx)
    const std::complex<float>* f3 = f2 + area;                               // (dDz/dz, dDx/dz)
    float* displacement = levels_[0].displacement.data() + std::size_t(cascade) * area * 4;
    float* slopes = levels_[0].slopes.data() + std::size_t(cascade) * area * 4;
    for (std::size_t m = 0; m < area; ++m) {
        const float d[4] = {l * f0[m].imag(), f0[m].real(), l * f1[m].real(), l * f3[m].imag()};
        const float s[4] = {f1[m].imag(), f2[m].real(), l * f2[m].imag(), l * f3[m].real()};
        std::copy(d, d + 4, displacement + 4 * m);
        std::copy(s, s + 4, slopes + 4 * m);
    }
    for (std::size_t level = 1; level < levels_.size(); ++level) {
        const MipLevel& above = levels_[level - 1];
        MipLevel& below = levels_[level];
        const std::size_t from = std::size_t(above.size), to = std::size_t(below.size);
        for (std::vector<float> MipLevel::*map : {&MipLevel::displacement, &MipLevel::slopes}) {
            const float* a = (above.*map).data() + std::size_t(cascade) * from * from * 4;
            float* b = (below.*map).data() + std::size_t(cascade) * to * to * 4;
            for (std::size_t j = 0; j < to; ++j)
                for (std::size_t i = 0; i < to; ++i)
                    for (std::size_t channel = 0; channel < 4; ++channel) {
                        const std::size_t top = ((2 * j) * from + 2 * i) * 4 + channel, bottom = top + from * 4;
                        b[(j * to + i) * 4 + channel] = 0.25f * (a[top] + a[top + 4] + a[bottom] + a[bottom + 4]);
                    }
        }
    }
}

void CpuSimulation::assemble(float choppiness) {
    const int cascades = layers_ / 4;
    if (levels_.empty())
        for (int size = n_; size >= 1; size /= 2) {
            const std::size_t floats = std::size_t(cascades) * std::size_t(size) * std::size_t(size) * 4;
            levels_.push_back({size, std::vector<float>(floats), std::vector<float>(floats)});
        }
    in_parallel(cascades, [&](int cascade) { assemble_layer(cascade, choppiness); });
}

void CpuSimulation::transform_only() { fft_.run(); }

const float* CpuSimulation::fields() const { return reinterpret_cast<const float*>(data_); }

}  // namespace step05
