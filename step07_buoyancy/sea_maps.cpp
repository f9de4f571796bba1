#include "step07_buoyancy/sea_maps.hpp"

namespace step07 {

CascadeMaps cascade_maps(const step05::OceanMaps& maps, double choppiness) {
    using step05::Field;
    CascadeMaps out;
    out.n = maps.n;
    out.tile = maps.patch_size;
    const std::size_t texels = std::size_t(maps.n) * std::size_t(maps.n);
    out.displacement.resize(texels * 4);
    out.slopes.resize(texels * 4);
    const double l = choppiness;
    for (std::size_t t = 0; t < texels; ++t) {
        const double d[4] = {l * maps[Field::DisplacementX][t], maps[Field::Height][t], l * maps[Field::DisplacementZ][t],
                             l * maps[Field::DDxDz][t]};
        const double s[4] = {maps[Field::SlopeX][t], maps[Field::SlopeZ][t], l * maps[Field::DDxDx][t],
                             l * maps[Field::DDzDz][t]};
        for (int c = 0; c < 4; ++c) {
            out.displacement[t * 4 + std::size_t(c)] = float(d[c]);
            out.slopes[t * 4 + std::size_t(c)] = float(s[c]);
        }
    }
    return out;
}

MapSea reference_sea(const std::vector<step05::InitialSpectrum>& cascades, double time, double choppiness) {
    std::vector<CascadeMaps> maps;
    for (const auto& spectrum : cascades) maps.push_back(cascade_maps(step05::simulate_cpu(spectrum, time), choppiness));
    return MapSea(std::move(maps));
}

MapSea sea_from_layers(const std::vector<float>& displacement, const std::vector<float>& slopes, int n,
                       const std::vector<double>& tiles) {
    std::vector<CascadeMaps> maps;
    const std::size_t layer = std::size_t(n) * std::size_t(n) * 4;
    for (std::size_t c = 0; c < tiles.size(); ++c) {
        CascadeMaps m;
        m.n = n;
        m.tile = tiles[c];
        m.displacement.assign(displacement.begin() + long(c * layer), displacement.begin() + long((c + 1) * layer));
        m.slopes.assign(slopes.begin() + long(c * layer), slopes.begin() + long((c + 1) * layer));
        maps.push_back(std::move(m));
    }
    return MapSea(std::move(maps));
}

}  // namespace step07
