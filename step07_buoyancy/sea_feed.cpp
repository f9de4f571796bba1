#include "step07_buoyancy/sea_feed.hpp"

#include "step07_buoyancy/sea_maps.hpp"

namespace step07 {

bool SeaFeed::update(const step06::Sea& sea, double time) {
    std::optional<TimedSea> arrived = newest(sea, time);
    arrived_ = arrived.has_value();
    if (arrived_) {
        before_ = now_ ? std::move(now_) : arrived;
        now_ = std::move(arrived);
    }
    return arrived_;
}

std::optional<SeaFeed::TimedSea> SeaFeed::newest(const step06::Sea& sea, double time) {
    const std::vector<double> tiles = sea.tile_sizes();
    // Each cascade's orbits shrink with depth by its band's wavenumber (sea_maps.hpp).
    const std::vector<double> wavenumbers = band_wavenumbers(sea.spectrum());
#ifndef OCEAN_GL_PORTABLE  // the FFTW backend's maps are on the CPU already
    if (const step05::CpuSimulation* cpu = sea.simulation().maps_on_cpu()) {
        readback_.forget();  // auto's trial frames switch backends: no older GPU maps after these
        const auto& level = cpu->levels()[0];
        latency_frames_ = 0;
        return TimedSea{sea_from_layers(level.displacement, level.slopes, level.size, tiles, wavenumbers), time};
    }
#endif
    std::optional<ArrivedMaps> arrived;
    latency_frames_ = now_ ? 1 : 0;
    if (!now_) {
        arrived = MapReadback::read_now(sea.simulation(), time);
    } else {
        arrived = readback_.take();
        readback_.request(sea.simulation(), time);
    }
    if (!arrived) return std::nullopt;
    return TimedSea{sea_from_layers(arrived->displacement, arrived->slopes, arrived->n, tiles, wavenumbers),
                    arrived->time};
}

}  // namespace step07
