#include "step07_buoyancy/sea_query.hpp"

#include <cmath>

namespace step07 {

glm::dvec3 surface_normal(const SurfaceAt& s) {
    const glm::dvec3 along_x = glm::dvec3(1, 0, 0) + s.d_dx;
    const glm::dvec3 along_z = glm::dvec3(0, 0, 1) + s.d_dz;
    return glm::normalize(glm::cross(along_z, along_x));
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
            // J = I + dD/dx: columns are d/dx and d/dz of (x + Dx, z + Dz).
            const double a = 1 + s.d_dx.x, b = s.d_dz.x, c = s.d_dx.z, d = 1 + s.d_dz.z;
            const double det = a * d - b * c;
            if (options.method == Inversion::Newton && det > 0.05)
                x -= glm::dvec2(d * r.x - b * r.y, -c * r.x + a * r.y) / det;
            else
                x = p - glm::dvec2(s.displacement.x, s.displacement.z);  // the fixed point
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

glm::dvec3 water_velocity(const Surface& before, const Surface& now, double dt, glm::dvec2 rest) {
    return (now.at(rest).displacement - before.at(rest).displacement) / dt;
}

}  // namespace step07
