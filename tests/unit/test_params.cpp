// The parameter registry: declarations, --set, validation, presets and their round trip.
#include "common/params.hpp"
#include "common/text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace {

struct Fixture : ::testing::Test {
    ocean::ParamRegistry params;
    // The defaults are the variables' values when they are declared.
    float amplitude = 1.5f;
    int count = 3;
    bool wireframe = false;
    int mode = 0;
    glm::vec3 colour{0.1f, 0.2f, 0.3f};
    std::string sky;

    Fixture() {
        params.add_float("amplitude", &amplitude, 0, 10, "metres");
        params.add_int("wave_count", &count, 1, 8, "waves");
        params.add_bool("wireframe", &wireframe, "edges only");
        params.add_choice("camera_mode", &mode, {"orbit", "fly"}, "camera");
        params.add_color("water_colour", &colour, "albedo").in_group("look");
        params.add_text("sky_image", &sky, "equirectangular sky").in_group("look");
    }

    std::string temp_path(const std::string& name) {
        return (std::filesystem::temp_directory_path() /
                (std::to_string(::getpid()) + "_" + name)).string();
    }
};

TEST_F(Fixture, DeclarationStoresTheDefault) {
    EXPECT_FLOAT_EQ(amplitude, 1.5f);
    EXPECT_EQ(count, 3);
    EXPECT_FALSE(wireframe);
    EXPECT_EQ(colour, glm::vec3(0.1f, 0.2f, 0.3f));
}

// A later chapter takes back what an earlier chapter's declaration gives and it does not show
// (step06 keeps step05's sea state, not the spectrum's shape): the name is then unknown, its
// variable keeps its default, and a name never declared is a programming error.
TEST_F(Fixture, RemovedParametersAreUnknownAndKeepTheirDefaults) {
    params.remove({"wave_count", "sky_image"});
    EXPECT_EQ(params.find("wave_count"), nullptr);
    EXPECT_EQ(params.all().size(), 4u);
    const auto error = params.set("wave_count", "5");
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("unknown parameter 'wave_count'"), std::string::npos) << *error;
    EXPECT_EQ(count, 3);
    EXPECT_FALSE(params.set("amplitude", "2").has_value());  // the others as before
    EXPECT_EQ(params.list_text().find("wave_count"), std::string::npos);
    EXPECT_THROW(params.remove({"no_such_parameter"}), std::logic_error);
}

// A program starts a parameter a part declared at its own default (step08's sea in a breeze):
// the value, the default --list-params prints and what every reset puts back; checked as --set
// checks, and a name never declared is a programming error.
TEST_F(Fixture, AProgramStartsADeclaredParameterAtItsOwnDefault) {
    ocean::Generation changes;
    double wind = 14;
    params.add_float("wind_speed", &wind, 1, 30, "m/s").bumps(changes);
    const unsigned before = changes.value;
    params.set_default("wind_speed", 6.0);
    params.set_default("camera_mode", "fly");
    EXPECT_EQ(wind, 6.0);
    EXPECT_EQ(mode, 1);
    EXPECT_GT(changes.value, before);  // what was built for 14 m/s is built again
    EXPECT_EQ(params.find("wind_speed")->default_text(), "6");
    EXPECT_EQ(params.find("camera_mode")->default_text(), "fly");
    const std::string list = params.list_text();
    std::istringstream row(list.substr(list.find("\nwind_speed ") + 1));
    std::string name, shown;
    row >> name >> shown;
    EXPECT_EQ(shown, "6") << list;
    EXPECT_FALSE(params.set("wind_speed", "20").has_value());
    params.reset_all();
    EXPECT_EQ(wind, 6.0);
    EXPECT_EQ(mode, 1);
    EXPECT_THROW(params.set_default("wind_speed", 40.0), std::logic_error);  // outside [1, 30]
    EXPECT_THROW(params.set_default("camera_mode", "drone"), std::logic_error);
    EXPECT_THROW(params.set_default("no_such_parameter", 1.0), std::logic_error);
    EXPECT_EQ(params.find("wind_speed")->default_text(), "6");
}

TEST_F(Fixture, SetsGoodValuesOfEveryType) {
    EXPECT_FALSE(params.set_assignment("amplitude=2.25"));
    EXPECT_FLOAT_EQ(amplitude, 2.25f);
    EXPECT_FALSE(params.set_assignment("wave_count=8"));
    EXPECT_EQ(count, 8);
    EXPECT_FALSE(params.set_assignment("wireframe=on"));
    EXPECT_TRUE(wireframe);
    EXPECT_FALSE(params.set_assignment("camera_mode=fly"));
    EXPECT_EQ(mode, 1);
    EXPECT_FALSE(params.set_assignment("water_colour=0,0.5,1"));
    EXPECT_EQ(colour, glm::vec3(0, 0.5f, 1));
    EXPECT_FALSE(params.set_assignment("amplitude= 1e-1 "));
    EXPECT_FLOAT_EQ(amplitude, 0.1f);
    EXPECT_FALSE(params.set_assignment("sky_image=/tmp/a sky.hdr"));
    EXPECT_EQ(sky, "/tmp/a sky.hdr");
}

TEST_F(Fixture, RefusesBadValuesWithAMessageNamingTheParameterAndRange) {
    struct Case { const char* assignment; const char* must_contain; };
    const Case cases[] = {
        {"nope=1", "unknown parameter 'nope'"},
        {"amplitud=1", "did you mean 'amplitude'"},
        {"amplitude=abc", "'amplitude' expects a number in [0, 10]"},
        {"amplitude=", "'amplitude' expects a number"},
        {"amplitude=nan", "'amplitude' must be a finite number in [0, 10]"},
        {"amplitude=inf", "must be a finite number"},
        {"amplitude=-1", "outside its range [0, 10]"},
        {"amplitude=1e300", "outside its range"},
        {"amplitude=1.5x", "expects a number"},
        {"wave_count=2.5", "'wave_count' expects an integer in [1, 8]"},
        {"wave_count=9", "outside its range [1, 8]"},
        {"wireframe=maybe", "expects true or false"},
        {"camera_mode=walk", "expects one of orbit|fly"},
        {"water_colour=1,2", "expects a colour r,g,b"},
        {"water_colour=0,0,1.5", "expects a colour r,g,b"},
        {"no_equals_sign", "--set expects name=value"},
        {"sky_image=a#b", "cannot hold '#'"},
    };
    for (const auto& c : cases) {
        const auto error = params.set_assignment(c.assignment);
        ASSERT_TRUE(error.has_value()) << c.assignment;
        EXPECT_NE(error->find(c.must_contain), std::string::npos) << *error;
        EXPECT_EQ(error->find('\n'), std::string::npos) << "one line: " << *error;
    }
    EXPECT_FLOAT_EQ(amplitude, 1.5f) << "refused values change nothing";
    EXPECT_EQ(count, 3);
}

TEST_F(Fixture, HugeInputIsShortenedInTheMessage) {
    const auto error = params.set_assignment("amplitude=" + std::string(100000, '9') + "x");
    ASSERT_TRUE(error);
    EXPECT_LT(error->size(), 200u);
}

TEST_F(Fixture, ResetRestoresDefaultsAndBumpsTheGeneration) {
    ocean::Generation changes;
    params.find("amplitude")->bumps(changes);
    params.set_assignment("amplitude=7");
    params.set_assignment("water_colour=1,1,1");
    const unsigned before = changes.value;
    EXPECT_GT(before, 1u);
    params.reset_all();
    EXPECT_GT(changes.value, before);
    EXPECT_FLOAT_EQ(amplitude, 1.5f);
    EXPECT_EQ(colour, glm::vec3(0.1f, 0.2f, 0.3f));
}

TEST_F(Fixture, PresetRoundTripRestoresEveryValueExactly) {
    params.set_assignment("amplitude=0.1");  // not exact in binary: must still round-trip
    params.set_assignment("wave_count=5");
    params.set_assignment("wireframe=true");
    params.set_assignment("camera_mode=fly");
    params.set_assignment("water_colour=0.3333333,0.7,0.9");
    params.set_assignment("sky_image=skies/noon.hdr");
    const std::string path = temp_path("roundtrip.preset");
    ASSERT_FALSE(params.save_preset(path, "test"));
    const float saved_amplitude = amplitude;
    const glm::vec3 saved_colour = colour;

    params.reset_all();
    ASSERT_NE(amplitude, saved_amplitude);
    const auto error = params.load_preset(path);
    ASSERT_FALSE(error) << *error;
    EXPECT_EQ(amplitude, saved_amplitude);
    EXPECT_EQ(count, 5);
    EXPECT_TRUE(wireframe);
    EXPECT_EQ(mode, 1);
    EXPECT_EQ(colour, saved_colour);
    EXPECT_EQ(sky, "skies/noon.hdr");
    std::remove(path.c_str());
}

TEST_F(Fixture, PresetAllowsCommentsBlankLinesAndMissingNames) {
    EXPECT_FALSE(params.apply_preset_text("# a comment\n\n  amplitude = 4   # trailing\n", "p"));
    EXPECT_FLOAT_EQ(amplitude, 4.0f);
    EXPECT_EQ(count, 3) << "names not in the preset keep their value";
}

TEST_F(Fixture, MalformedPresetIsRefusedWholeWithFileAndLine) {
    const auto error = params.apply_preset_text("amplitude = 4\nwave_count 5\n", "calm.preset");
    ASSERT_TRUE(error);
    EXPECT_NE(error->find("calm.preset:2:"), std::string::npos) << *error;
    EXPECT_FLOAT_EQ(amplitude, 1.5f) << "nothing applied when one line is bad";

    const auto out_of_range = params.apply_preset_text("amplitude = 4\nwave_count = 50\n", "p");
    ASSERT_TRUE(out_of_range);
    EXPECT_NE(out_of_range->find("p:2: parameter 'wave_count'"), std::string::npos) << *out_of_range;
    const auto unknown = params.apply_preset_text("nope = 1\n", "p");
    ASSERT_TRUE(unknown);
    EXPECT_NE(unknown->find("p:1: unknown parameter 'nope'"), std::string::npos);
    EXPECT_TRUE(params.apply_preset_text(std::string("amplitude = 1\0\x01\x02", 17), "bin"));
}

TEST_F(Fixture, PresetSavedWithAByteOrderMarkIsRead) {
    // Some editors write UTF-8 with EF BB BF first: the first name must still be known.
    EXPECT_FALSE(params.apply_preset_text("\xEF\xBB\xBF" "amplitude = 4\n", "bom.preset"));
    EXPECT_FLOAT_EQ(amplitude, 4.0f);
    // Only at the very start: elsewhere it is not part of a name.
    EXPECT_TRUE(params.apply_preset_text("amplitude = 4\n\xEF\xBB\xBF" "wave_count = 2\n", "p"));
}

TEST_F(Fixture, PresetsThatAreNotBoundedRegularFilesAreRefused) {
    // A device or a FIFO would never end or block: refused without reading.
    const auto device = params.load_preset("/dev/urandom");
    ASSERT_TRUE(device);
    EXPECT_NE(device->find("not a regular file"), std::string::npos) << *device;
    const std::string huge = temp_path("huge.preset");
    std::ofstream(huge) << std::string(ocean::kMaxTextFileBytes + 1, '#');
    const auto large = params.load_preset(huge);
    ASSERT_TRUE(large);
    EXPECT_NE(large->find("larger than"), std::string::npos) << *large;
    std::remove(huge.c_str());
}

TEST_F(Fixture, MissingOrDirectoryPresetFileIsAnError) {
    const auto missing = params.load_preset("/nonexistent/calm.preset");
    ASSERT_TRUE(missing);
    EXPECT_NE(missing->find("/nonexistent/calm.preset"), std::string::npos);
    EXPECT_TRUE(params.load_preset(std::filesystem::temp_directory_path().string()));
}

TEST_F(Fixture, ListNamesEveryParameterWithDefaultAndRange) {
    const std::string list = params.list_text();
    for (const char* expected : {"amplitude", "1.5", "[0, 10]", "wave_count", "orbit|fly", "water_colour"})
        EXPECT_NE(list.find(expected), std::string::npos) << expected;
}

// A group scope gives the declarations inside it their group and change counter, nests, and ends
// with its block: a parameter declared after it has neither.
TEST(ParamRegistry, AGroupScopeGroupsAndCountsOnlyWhatItsBlockDeclares) {
    ocean::ParamRegistry params;
    ocean::Generation waves, grid;
    float a = 0, b = 0, c = 0, d = 0;
    {
        const auto outer = params.group("waves", &waves);
        params.add_float("a", &a, 0, 1, "");
        {
            const auto inner = params.group("grid", &grid);
            params.add_float("b", &b, 0, 1, "");
        }
        params.add_float("c", &c, 0, 1, "");
    }
    params.add_float("d", &d, 0, 1, "");
    EXPECT_EQ(params.find("a")->group(), "waves");
    EXPECT_EQ(params.find("b")->group(), "grid");
    EXPECT_EQ(params.find("c")->group(), "waves") << "the outer scope came back";
    EXPECT_EQ(params.find("d")->group(), "") << "the scope ended with its block";
    const unsigned waves_before = waves.value, grid_before = grid.value;
    params.set_assignment("b=0.5");
    EXPECT_EQ(grid.value, grid_before + 1);
    EXPECT_EQ(waves.value, waves_before) << "the inner scope replaced the outer counter";
    params.set_assignment("c=0.5");
    EXPECT_EQ(waves.value, waves_before + 1) << "the outer scope's counter came back";
    params.set_assignment("d=0.5");
    EXPECT_EQ(waves.value, waves_before + 1);
    EXPECT_EQ(grid.value, grid_before + 1);
}

// A declaration's own group takes it out of the scope, counter too: step07's throttle, declared
// inside the bodies' scope with .in_group("steering"), once dropped the bodies at every move. A
// counter it should keep is said with .bumps().
TEST(ParamRegistry, ADeclarationsOwnGroupLeavesTheScopesCounter) {
    ocean::ParamRegistry params;
    ocean::Generation bodies;
    float size = 1, throttle = 0, density = 1;
    {
        const auto scope = params.group("bodies", &bodies);
        params.add_float("size", &size, 0, 10, "");
        params.add_float("throttle", &throttle, -1, 1, "").in_group("steering");
        params.add_float("density", &density, 0, 10, "").in_group("material").bumps(bodies);
    }
    EXPECT_EQ(params.find("throttle")->group(), "steering");
    const unsigned before = bodies.value;
    params.set_assignment("throttle=0.5");
    params.find("throttle")->set_number(-0.25);  // the panel's slider
    EXPECT_EQ(bodies.value, before) << "steering bumped the bodies' counter";
    params.set_assignment("size=2");
    EXPECT_EQ(bodies.value, before + 1);
    params.set_assignment("density=2");
    EXPECT_EQ(bodies.value, before + 2) << ".bumps() keeps a counter explicitly";
}

// The ends --list-params prints are accepted, compared in the type they were declared in: 0.2f is
// 0.200000003 as a double, so "0.2" was refused at the minimum it printed; 0.95f is 0.949999988.
TEST(ParamRegistry, AFloatRangesPrintedEndsAreAccepted) {
    ocean::ParamRegistry params;
    float diameter = 1, ratio = 0.5f;
    double stored_as_float = 1, full = 1;
    params.add_float("diameter", &diameter, 0.2f, 5, "");
    params.add_float("ratio", &ratio, 0.05f, 0.95f, "");
    params.add_float("stored_as_float", &stored_as_float, 0.1, 0.7, "");
    params.add_double("full", &full, 0.1, 0.7, "");
    for (const char* end : {"diameter=0.2", "diameter=5", "ratio=0.05", "ratio=0.95", "stored_as_float=0.1",
                            "stored_as_float=0.7", "full=0.1", "full=0.7"})
        EXPECT_EQ(params.set_assignment(end), std::nullopt) << end;
    EXPECT_EQ(diameter, 5.0f);
    EXPECT_EQ(ratio, 0.95f);
    for (const char* outside : {"diameter=0.19", "ratio=0.951", "ratio=0.0499", "full=0.70000001"})
        EXPECT_NE(params.set_assignment(outside), std::nullopt) << outside;
    EXPECT_NE(params.find("diameter")->range_text().find("[0.2, 5]"), std::string::npos);
}

TEST(ParamRegistry, DuplicateNamesAreAProgrammingError) {
    ocean::ParamRegistry params;
    float a = 0, b = 0;
    params.add_float("x", &a, 0, 1, "");
    EXPECT_THROW(params.add_float("x", &b, 0, 1, ""), std::logic_error);
}

}  // namespace

#include "common/camera.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace {

// 1000 km out a float's steps are 6 cm: a camera there is kept, written and read back to every digit
// of its double, and only a step that renders relative to the camera may go that far.
TEST(CameraReach, AFarCameraKeepsItsCentimetres) {
    ocean::ParamRegistry params;
    ocean::Camera camera;
    camera.declare_params(params, {{0, 0, 0}, 10, 0, 20}, ocean::kOceanReach);
    ASSERT_FALSE(params.set("camera_target_x", "1000123.41"));
    EXPECT_EQ(camera.target.x, 1000123.41);  // as a float it would be 1000123.375
    EXPECT_EQ(params.find("camera_target_x")->value_text(), "1000123.41");
    EXPECT_NEAR(camera.eye_world().x - camera.target.x, -camera.forward().x * 10, 1e-6);
    ocean::ParamRegistry near_params;
    ocean::Camera near_camera;
    near_camera.declare_params(near_params, {{0, 0, 0}, 10, 0, 20});
    EXPECT_TRUE(near_params.set("camera_target_x", "1000123.41")) << "beyond 10 km without camera-relative rendering";
}

TEST(CameraPresets, SetTheCameraParametersOrSayWhatExists) {
    ocean::ParamRegistry params;
    ocean::Camera camera;
    camera.declare_params(params, {{0, 0, 0}, 10, 0, 20});
    ASSERT_FALSE(ocean::apply_camera_preset(params, "deck"));
    EXPECT_FLOAT_EQ(camera.distance, 60);
    EXPECT_FLOAT_EQ(camera.pitch_deg, 12);
    ASSERT_FALSE(ocean::apply_camera_preset(params, "top"));
    EXPECT_FLOAT_EQ(camera.pitch_deg, 89);
    const auto unknown = ocean::apply_camera_preset(params, "nope");
    ASSERT_TRUE(unknown);
    EXPECT_NE(unknown->find("--camera expects one of overview|deck|low|top"), std::string::npos) << *unknown;
    ocean::ParamRegistry flat;  // step01 has no camera
    const auto none = ocean::apply_camera_preset(flat, "deck");
    ASSERT_TRUE(none);
    EXPECT_NE(none->find("no camera"), std::string::npos);
}

// The ray under the cursor starts on the near plane in front of the eye and goes where the view
// looks: through the window's middle along forward(), through its top left corner up and to the
// left. Built from a world origin near a camera 2000 km out, as a camera-relative frame draws.
TEST(CursorRay, GoesWhereTheWindowShows) {
    ocean::ParamRegistry params;
    ocean::Camera camera;
    camera.declare_params(params, {{0, 0, 0}, 10, 30, 20}, ocean::kOceanReach);
    camera.target = {1000000.25, 0, -2000000.5};
    const glm::dvec3 origin = glm::floor(camera.eye_world());
    const glm::dvec2 window(1280, 720);
    const float aspect = 16.0f / 9;
    const auto middle = ocean::cursor_ray(camera, aspect, origin, window / 2.0, window);
    ASSERT_TRUE(middle);
    EXPECT_NEAR(glm::length(middle->direction), 1, 1e-12);
    EXPECT_NEAR(glm::dot(middle->direction, glm::dvec3(camera.forward())), 1, 1e-6);
    EXPECT_NEAR(glm::length(middle->from - camera.eye_world()), camera.near_plane, 1e-3);
    const auto corner = ocean::cursor_ray(camera, aspect, origin, {0, 0}, window);
    ASSERT_TRUE(corner);
    const glm::dvec3 forward(camera.forward());
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, forward);
    EXPECT_LT(glm::dot(corner->direction, right), 0);
    EXPECT_GT(glm::dot(corner->direction, up), 0);
    EXPECT_FALSE(ocean::cursor_ray(camera, aspect, origin, {0, 0}, {0, 0})) << "a window of no size";
}

}  // namespace
