// The panel's parameter list, grouped: the ungrouped parameters first (shown without a header),
// then one entry per group, in the order the groups first appear among the declarations, each
// with every parameter of that group in declaration order, wherever it was declared (step05
// declares "grid" in two places; the panel shows one "grid" header).
// No ImGui here: the grouping is tested on its own (tests/unit/test_panel_groups.cpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/params.hpp"

namespace ocean {

struct ParamGroup {
    std::string name;            // "" for the parameters declared outside any group (no header)
    std::vector<Param*> params;  // in declaration order
};

std::vector<ParamGroup> group_params(const std::vector<std::unique_ptr<Param>>& params);

}  // namespace ocean
