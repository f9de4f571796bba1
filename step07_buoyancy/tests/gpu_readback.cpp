// The GPU's maps read back through a pixel buffer and a fence (map_readback.hpp): what arrives is
// the sea of the frame it was asked for (against the double reference at that time), one frame
// late, so a query from it differs from the current frame's CPU answer by no more than the
// surface moves in one frame.
#include "step06_foam_sky/cascades.hpp"
#include "step07_buoyancy/gpu_queries.hpp"
#include "step07_buoyancy/map_readback.hpp"
#include "step07_buoyancy/sea_maps.hpp"
#include "step07_buoyancy/sea_query.hpp"
#include "tests/gpu/gl_test_context.hpp"
#include "tests/gpu/program_cache.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <iostream>

namespace {

struct Step07Gpu : ocean_test::GlTest {
    ocean_test::ProgramCache cache;
    // step06's four cascades at `resolution` in a `wind` m/s sea, their tiles, and the simulation.
    std::vector<step05::InitialSpectrum> spectra;
    std::vector<double> tiles;
    std::unique_ptr<step05::OceanSimulation> simulation;
    void make_sea(int resolution, double wind) {
        step05::SpectrumParams params;
        params.resolution = resolution;
        params.wind_speed = wind;
        for (const auto& c : step06::cascade_spectra(params)) {
            spectra.push_back(step05::initial_spectrum(c));
            tiles.push_back(c.patch_size);
        }
        std::vector<const step05::InitialSpectrum*> pointers;
        for (const auto& s : spectra) pointers.push_back(&s);
        simulation = std::make_unique<step05::OceanSimulation>(cache.factory());
        simulation->set_spectra(pointers);
    }
};

TEST_F(Step07Gpu, AQueryReadBackAFrameLateIsOffByOneFramesMotion) {
    make_sea(32, 12);
    step05::OceanSimulation& ocean = *simulation;
    const double t0 = 7.0, dt = 1.0 / 60, choppiness = 1.2;

    step07::MapReadback readback;
    ocean.simulate(t0, step05::Backend::GpuFft, float(choppiness));
    readback.request(ocean, t0);
    std::optional<step07::ArrivedMaps> arrived;
    int frames = 0;
    for (double t = t0 + dt; !arrived && frames < 3; t += dt, ++frames) {
        ocean.simulate(t, step05::Backend::GpuFft, float(choppiness));  // the next frame's work
        arrived = readback.take();
    }
    ASSERT_TRUE(arrived.has_value()) << "nothing arrived in 3 frames";
    EXPECT_EQ(arrived->time, t0);
    EXPECT_EQ(frames, 1) << "the copy should land by the next frame on a GPU that keeps up";

    const step07::MapSea late = step07::sea_from_layers(arrived->displacement, arrived->slopes, arrived->n, tiles);
    const step07::MapSea then = step07::reference_sea(spectra, t0, choppiness);
    const step07::MapSea now = step07::reference_sea(spectra, t0 + dt, choppiness);
    double worst_same_time = 0, worst_late = 0, moved = 0;
    for (double x = -40; x < 40; x += 3.1)
        for (double z = -40; z < 40; z += 3.7) {
            const double h_late = step07::query(late, {x, z}).height, h_then = step07::query(then, {x, z}).height,
                         h_now = step07::query(now, {x, z}).height;
            worst_same_time = std::max(worst_same_time, std::abs(h_late - h_then));
            worst_late = std::max(worst_late, std::abs(h_late - h_now));
            moved = std::max(moved, std::abs(h_now - h_then));
        }
    std::cout << "read back a frame late: " << worst_same_time << " m from the reference at its time, " << worst_late
              << " m from the current frame, which moved " << moved << " m\n";
    EXPECT_LT(worst_same_time, 2e-3) << "the GPU's float maps against the double reference, metres";
    EXPECT_GT(moved, 0.0);
    EXPECT_LE(worst_late, moved + worst_same_time) << "one frame late: off by the frame's motion, " << moved << " m";
}

TEST_F(Step07Gpu, BatchQueriesOnTheGpuAnswerAsTheCpuDoes) {
    // The same maps (FFTW's, uploaded) queried on both sides, 3000 points around an origin 12 km
    // out: the GPU's Newton steps in float against sea_query.cpp in double, within 1 mm (float
    // texture coordinates and weights: height_query.comp weighs the texels itself, since an H100's
    // filter, with 8-bit weights, was 3.1 mm off and left 165 queries unsettled).
    make_sea(64, 14);
    step05::OceanSimulation& ocean = *simulation;
    step06::CascadeView view;
    for (std::size_t c = 0; c < tiles.size(); ++c) view.patch_sizes[c] = float(tiles[c]);
    view.place_origin({12000.0, -3000.0});
    ocean.simulate(4.0, step05::Backend::Fftw, 1.3f);
    const step05::CpuSimulation* cpu = ocean.maps_on_cpu();
    ASSERT_NE(cpu, nullptr);
    const step07::MapSea sea = step07::sea_from_layers(cpu->levels()[0].displacement, cpu->levels()[0].slopes, 64, tiles);

    std::vector<glm::vec2> points;
    std::vector<glm::dvec2> world;
    for (int i = 0; i < 3000; ++i) {
        points.emplace_back(float((i % 60) * 1.37 - 40), float((i / 60) * 1.61 - 40));
        world.push_back(view.origin + glm::dvec2(points.back()));
    }
    step07::GpuQueries queries(cache.factory());
    queries.submit(points, ocean, view, 4.0, 4);
    std::optional<step07::GpuAnswers> answers;
    for (int frame = 0; frame < 3 && !answers; ++frame) {
        glFinish();
        answers = queries.take();
    }
    ASSERT_TRUE(answers.has_value());
    const std::vector<step07::SeaPoint> expected = step07::query_many(sea, world);
    double worst = 0, worst_normal = 0;
    int converged = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        worst = std::max(worst, std::abs(double(answers->answers[i].height) - expected[i].height));
        worst_normal = std::max(worst_normal, std::abs(double(answers->answers[i].normal_x) - expected[i].normal.x));
        converged += answers->answers[i].miss < 1e-3f ? 1 : 0;
    }
    std::cout << "GPU batch: worst height " << worst << " m, normal " << worst_normal << ", " << converged
              << " of 3000 within 1 mm\n";
    EXPECT_LT(worst, 1e-3) << "metres";
    EXPECT_LT(worst_normal, 5e-3);
    EXPECT_GT(converged, 2950) << "of 3000 within 1 mm after 4 steps";
}

}  // namespace
