// step08's teaching figure (figures.cpp): Kelvin's angle by the group velocity. ./ocean figures
// draws it into this folder for the README.
#pragma once

#include "tools/figure.hpp"

namespace step08 {

figures::FigureMakers teaching_figures();

}  // namespace step08
