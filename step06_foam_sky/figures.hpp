// step06's teaching figures (figures.cpp): the cascades' bands, the glitter's slopes against Cox
// and Munk, Fresnel for water, and one frame's passes. ./ocean figures draws them into this folder
// for the lessons.
#pragma once

#include "tools/figure.hpp"

namespace step06 {

figures::FigureMakers teaching_figures();

}  // namespace step06
