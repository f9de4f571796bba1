// step02's teaching figures (figures.cpp): one directional wave from above, and the camera from
// the side. ./ocean figures draws them into this folder for the README.
#pragma once

#include "tools/figure.hpp"

namespace step02 {

figures::FigureMakers teaching_figures();

}  // namespace step02
