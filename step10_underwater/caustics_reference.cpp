#include "step10_underwater/caustics_reference.hpp"

#include "common/constants.hpp"
#include "step10_underwater/lens.hpp"
#include "step10_underwater/optics.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace step10 {

double SeabedIrradiance::mean() const {
    return std::accumulate(irradiance.begin(), irradiance.end(), 0.0) / double(irradiance.size());
}

double SeabedIrradiance::peak() const { return *std::max_element(irradiance.begin(), irradiance.end()); }

double SeabedIrradiance::peak_over_mean() const { return peak() / mean(); }

double SeabedIrradiance::contrast() const {
    const double m = mean();
    double sum = 0;
    for (double e : irradiance) sum += (e - m) * (e - m);
    return std::sqrt(sum / double(irradiance.size())) / m;
}

SeabedIrradiance seabed_irradiance(const CausticSea& sea) {
    const double wavelength = ocean::kTwoPi / sea.wavenumber;
    const double dx = wavelength / sea.rays;
    const double bin_width = wavelength / sea.bins;
    // x along the sea, y up. Sunlight travels down and, for a sun at the zenith angle, towards +x.
    const glm::dvec3 sun_ray{std::sin(sea.sun_zenith), -std::cos(sea.sun_zenith), 0};
    // The sun's irradiance on a plane facing it, such that a horizontal plane receives 1.
    const double facing_irradiance = 1 / std::cos(sea.sun_zenith);

    SeabedIrradiance result{std::vector<double>(sea.bins, 0.0)};
    for (int i = 0; i < sea.rays; ++i) {
        const double x = (i + 0.5) * dx;
        const double height = sea.amplitude * std::cos(sea.wavenumber * x);
        const double slope = -sea.amplitude * sea.wavenumber * std::sin(sea.wavenumber * x);
        // (-slope, 1) is the upward normal scaled by the surface's length per unit x: the sunlight
        // the piece of surface over dx intercepts is the facing irradiance times |ray . that| dx.
        const glm::dvec3 scaled_normal{-slope, 1, 0};
        const double power = facing_irradiance * std::abs(glm::dot(sun_ray, scaled_normal)) * dx;
        const glm::dvec3 normal = glm::normalize(scaled_normal);
        const double incidence = std::acos(std::min(1.0, -glm::dot(sun_ray, normal)));
        const double transmitted = 1 - fresnel_reflectance(incidence, 1.0, kWaterIndex);
        const glm::dvec3 down = *refract_air_to_water(sun_ray, normal);  // never total reflection from air

        // Straight down to the seabed at y = -depth, then folded back into one wavelength.
        const double travel = (height + sea.depth) / -down.y;
        const double landing = x + travel * down.x;
        const double folded = landing - wavelength * std::floor(landing / wavelength);
        const int bin = std::min(sea.bins - 1, static_cast<int>(folded / bin_width));
        result.irradiance[bin] += power * transmitted / bin_width;
    }
    return result;
}

double crest_focal_depth(const CausticSea& sea) { return crest_focal_depth(sea.amplitude, sea.wavenumber); }

}  // namespace step10
