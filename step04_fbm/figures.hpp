// step04's teaching figure (figures.cpp): domain warping along one line of the default sea.
// ./ocean figures draws it into this folder for the README.
#pragma once

#include "tools/figure.hpp"

namespace step04 {

figures::FigureMakers teaching_figures();

}  // namespace step04
