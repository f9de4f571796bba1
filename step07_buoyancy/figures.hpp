// step07's teaching figure (figures.cpp): the controls on a flat sea, a push and the arrows.
// ./ocean figures draws it into this folder for the README.
#pragma once

#include "tools/figure.hpp"

namespace step07 {

figures::FigureMakers teaching_figures();

}  // namespace step07
