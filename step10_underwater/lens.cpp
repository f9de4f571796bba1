#include "step10_underwater/lens.hpp"

#include "step10_underwater/optics.hpp"

namespace step10 {

double crest_focal_depth(double amplitude, double wavenumber) {
    // The crest's radius of curvature: 1 / |h''| at the top, h'' = -a k^2. A sphere of radius R
    // between air and a medium of index n focuses parallel light n R / (n - 1) behind it.
    const double radius = 1 / (amplitude * wavenumber * wavenumber);
    return kWaterIndex * radius / (kWaterIndex - 1);
}

}  // namespace step10
