// step03's teaching figure (figures.cpp): the vectors of the lighting model at one point of a
// wave. ./ocean figures draws it into this folder for the README.
#pragma once

#include "tools/figure.hpp"

namespace step03 {

figures::FigureMakers teaching_figures();

}  // namespace step03
