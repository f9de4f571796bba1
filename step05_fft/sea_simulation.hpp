// The simulation a program runs, chosen once by the profile it is built for: the compute passes
// of ocean_simulation.hpp in the GL 4.5 profile (with their choice of transform), the same passes
// as fragment passes (fragment_simulation.hpp) where there are no compute shaders (macOS's GL 4.1,
// ES 3.0, WebGL 2). The same maps come out of both, so what reads them names only SeaSimulation.
#pragma once

#ifdef OCEAN_GL_PORTABLE
#include "step05_fft/fragment_simulation.hpp"
#else
#include "step05_fft/ocean_simulation.hpp"
#endif

namespace step05 {

#ifdef OCEAN_GL_PORTABLE
using SeaSimulation = FragmentSimulation;
#else
using SeaSimulation = OceanSimulation;
#endif

}  // namespace step05
