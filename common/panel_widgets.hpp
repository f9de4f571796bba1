// ImGui widgets drawn from the parameter registry, for steps that show a parameter somewhere
// other than the main list.
#pragma once

#include "common/params.hpp"

namespace ocean {

bool param_widget(Param& param);        // one parameter; true when it changed
bool param_widgets(ParamRegistry& all); // every visible parameter, grouped; marks changes

}  // namespace ocean
