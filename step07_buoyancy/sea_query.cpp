#include "step07_buoyancy/sea_query.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace step07 {

glm::dvec3 surface_normal(const SurfaceAt& s) {
    const glm::dvec3 along_x = glm::dvec3(1, 0, 0) + s.d_dx;
    const glm::dvec3 along_z = glm::dvec3(0, 0, 1) + s.d_dz;
    return glm::normalize(glm::cross(along_z, along_x));
}

glm::dvec2 newton_step(glm::dvec2 x, glm::dvec2 p, const SurfaceAt& s) {
    const glm::dvec2 miss = x + glm::dvec2(s.displacement.x, s.displacement.z) - p;
    // J = I + dD/dx: its columns are d/dx and d/dz of (x + Dx, z + Dz).
    const double a = 1 + s.d_dx.x, b = s.d_dz.x, c = s.d_dx.z, d = 1 + s.d_dz.z;
    const double det = a * d - b * c;
    if (det <= 0.05) return p - glm::dvec2(s.displacement.x, s.displacement.z);
    return x - glm::dvec2(d * miss.x - b * miss.y, -c * miss.x + a * miss.y) / det;
}

SeaPoint query(const Surface& sea, glm::dvec2 p, const QueryOptions& options) {
    SeaPoint out;
    glm::dvec2 x = p;
    SurfaceAt s = sea.at(x);
    const auto miss = [&] { return x + glm::dvec2(s.displacement.x, s.displacement.z) - p; };
    if (options.method != Inversion::None) {
        out.converged = false;
        for (int i = 0; i < options.max_iterations; ++i) {
            const glm::dvec2 r = miss();
            if (glm::length(r) < options.tolerance) {
                out.converged = true;
                break;
            }
            x = options.method == Inversion::Newton ? newton_step(x, p, s)
                                                    : p - glm::dvec2(s.displacement.x, s.displacement.z);  // the fixed point
            s = sea.at(x);
            ++out.iterations;
        }
        if (!out.converged) out.converged = glm::length(miss()) < options.tolerance;
    }
    out.rest = x;
    out.height = s.displacement.y;
    out.normal = surface_normal(s);
    return out;
}

std::vector<SeaPoint> query_many(const Surface& sea, const std::vector<glm::dvec2>& points, const QueryOptions& options) {
    std::vector<SeaPoint> out(points.size());
    const auto range = [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) out[i] = query(sea, points[i], options);
    };
    // Worth a thread from a few hundred queries on (a thread costs tens of microseconds).
    const std::size_t threads = points.size() < 512 ? 1 : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> workers;
    const std::size_t share = (points.size() + threads - 1) / threads;
    for (std::size_t t = 1; t < threads; ++t)
        workers.emplace_back(range, std::min(points.size(), t * share), std::min(points.size(), (t + 1) * share));
    range(0, std::min(points.size(), share));
    for (auto& w : workers) w.join();
    return out;
}

glm::dvec3 water_velocity(const Surface& before, const Surface& now, double dt, glm::dvec2 rest,
                          double depth) {
    return (now.displacement_below(rest, depth) - before.displacement_below(rest, depth)) / dt;
}

}  // namespace step07
