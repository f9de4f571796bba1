#include "common/param_groups.hpp"

namespace ocean {

std::vector<ParamGroup> group_params(const std::vector<std::unique_ptr<Param>>& params) {
    // The ungrouped parameters first (they have no header: after another group's header they would
    // look folded into it), then the groups.
    std::vector<ParamGroup> groups{ParamGroup{"", {}}};
    for (const auto& p : params) {
        auto it = groups.begin();
        while (it != groups.end() && it->name != p->group()) ++it;
        if (it == groups.end()) it = groups.insert(groups.end(), ParamGroup{p->group(), {}});
        it->params.push_back(p.get());
    }
    if (groups.front().params.empty()) groups.erase(groups.begin());
    return groups;
}

}  // namespace ocean
