// step10's teaching figures (figures.cpp): Fresnel both ways across the surface, and the light a
// wave's crests focus on the floor at several depths. ./ocean figures draws them into this folder.
#pragma once

#include "tools/figure.hpp"

namespace step10 {

figures::FigureMakers teaching_figures();

}  // namespace step10
