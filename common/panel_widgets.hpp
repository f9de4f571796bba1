// ImGui widgets drawn from the parameter registry, for steps that show a parameter somewhere
// other than the main list.
#pragma once

#include "common/params.hpp"

#include <functional>

namespace ocean {

bool param_widget(Param& param);        // one parameter; true when it changed
// Every visible parameter, grouped; marks changes. `after_each_row` runs after each group's header
// and each widget (the panel notes where it may end: PanelFit).
bool param_widgets(ParamRegistry& all, const std::function<void()>& after_each_row = {});

}  // namespace ocean
