// The panel's groups (common/param_groups.hpp): the ungrouped parameters first, then one header
// per group, in the order the groups first appear, with every parameter of the group under it
// wherever it was declared (step05 declares "grid" in its grid block and again for
// frustum_culling, after "view").
#include <gtest/gtest.h>

#include "common/param_groups.hpp"

namespace {

std::vector<std::string> names(const ocean::ParamGroup& group) {
    std::vector<std::string> out;
    for (const ocean::Param* p : group.params) out.push_back(p->name());
    return out;
}

TEST(PanelGroups, AGroupDeclaredInTwoPlacesAppearsOnceWithAllItsParameters) {
    ocean::ParamRegistry params;
    float a = 0, b = 0, c = 0, e = 0;
    int d = 0;
    bool f = false, g = false;
    params.add_float("time_scale", &a, 0, 1, "ungrouped");
    {
        const auto scope = params.group("grid");
        params.add_float("grid_size", &b, 0, 1, "grid");
        params.add_int("grid_lod", &d, 0, 4, "grid");
    }
    params.add_bool("wireframe", &f, "view").in_group("view");
    params.add_bool("frustum_culling", &g, "grid again").in_group("grid");
    params.add_float("exposure", &c, 0, 1, "view again").in_group("view");
    params.add_float("speed", &e, 0, 1, "ungrouped again");

    const auto groups = ocean::group_params(params.all());
    ASSERT_EQ(groups.size(), 3u) << "one entry per group: '', grid, view";
    EXPECT_EQ(groups[0].name, "");
    EXPECT_EQ(groups[1].name, "grid");
    EXPECT_EQ(groups[2].name, "view");
    EXPECT_EQ(names(groups[0]), (std::vector<std::string>{"time_scale", "speed"}));
    EXPECT_EQ(names(groups[1]), (std::vector<std::string>{"grid_size", "grid_lod", "frustum_culling"}));
    EXPECT_EQ(names(groups[2]), (std::vector<std::string>{"wireframe", "exposure"}));
}

TEST(PanelGroups, EveryParameterOnceInDeclarationOrderWithinItsGroup) {
    ocean::ParamRegistry params;
    std::vector<float> values(6);
    const char* group_of[] = {"b", "a", "b", "", "a", "b"};
    for (std::size_t i = 0; i < values.size(); ++i)
        params.add_float("p" + std::to_string(i), &values[i], 0, 1, "x").in_group(group_of[i]);
    const auto groups = ocean::group_params(params.all());
    ASSERT_EQ(groups.size(), 3u);
    EXPECT_EQ(groups[0].name, "") << "the ungrouped parameters first: no header would tell them apart";
    EXPECT_EQ(names(groups[0]), (std::vector<std::string>{"p3"}));
    EXPECT_EQ(names(groups[1]), (std::vector<std::string>{"p0", "p2", "p5"}));
    EXPECT_EQ(names(groups[2]), (std::vector<std::string>{"p1", "p4"}));
    EXPECT_TRUE(ocean::group_params({}).empty());
}

}  // namespace
