#include "step10_underwater/lens.hpp"

#include "step10_underwater/optics.hpp"

#include <cmath>

namespace step10 {

double crest_focal_depth(double amplitude, double wavenumber) {
    // The crest's radius of curvature: 1 / |h''| at the top, h'' = -a k^2. A sphere of radius R
    // between air and a medium of index n focuses parallel light n R / (n - 1) behind it.
    const double radius = 1 / (amplitude * wavenumber * wavenumber);
    return kWaterIndex * radius / (kWaterIndex - 1);
}

double slanted_crest_focal_depth(double amplitude, double wavenumber, double sun_zenith) {
    // Light meeting a curved surface at incidence i comes to its tangential focus (Coddington's
    // equation for a refracting surface, parallel light) at a distance s along the refracted ray:
    //   n cos^2 t / s = (n cos t - cos i) / R,   sin t = sin i / n;
    // the crest is a cylinder, curved only in the plane the sun shines in, so that focus is the
    // line. It lies s cos t below the crest. Overhead (i = t = 0) it is n R / (n - 1) again.
    const double radius = 1 / (amplitude * wavenumber * wavenumber);
    const double cos_i = std::cos(sun_zenith);
    const double sin_t = std::sin(sun_zenith) / kWaterIndex, cos_t = std::sqrt(1 - sin_t * sin_t);
    const double along_ray = kWaterIndex * cos_t * cos_t * radius / (kWaterIndex * cos_t - cos_i);
    return along_ray * cos_t;
}

}  // namespace step10
