// The shader preprocessor (#include, #line tagging) and the mapping of driver messages back to
// file:line. CPU only: no GL needed.
#include "common/error.hpp"
#include "common/shader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

struct ShaderFiles : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("ocean_shader_test_" + std::to_string(::getpid()));
    ShaderFiles() { fs::create_directories(dir / "lib"); }
    ~ShaderFiles() override { fs::remove_all(dir); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return fs::canonical(dir / name).string();
    }
};

TEST_F(ShaderFiles, IncludesAreGuardedAndTaggedWithLineDirectives) {
    const auto common = write("lib/common.glsl", "float a;\nfloat b;\n");
    write("lib/more.glsl", "#include \"common.glsl\"\nfloat c;\n");
    const auto main = write("main.frag",
                            "#version 450 core\n#include \"lib/more.glsl\"\n#include \"lib/common.glsl\"\nvoid main() {}\n");
    const auto source = ocean::preprocess_shader(main, {}, {}, ocean::GlProfile::Core45);  // as written
    ASSERT_EQ(source.files.size(), 3u);
    EXPECT_EQ(source.files[0], main);
    EXPECT_EQ(source.files[2], common);
    const std::string common_copy = "#ifndef OCEAN_INCLUDED_2\n#define OCEAN_INCLUDED_2\n#line 1 2\nfloat a;\nfloat b;\n#endif\n";
    EXPECT_EQ(source.text,
              "#version 450 core\n#line 2 0\n"
              "#ifndef OCEAN_INCLUDED_1\n#define OCEAN_INCLUDED_1\n#line 1 1\n" +  // lib/more.glsl
                  common_copy +                                                  // its include, common.glsl
                  "#line 2 1\nfloat c;\n#endif\n"  // back in more.glsl, line 2
                  "#line 3 0\n" +                  // back in main, line 3: common again, its guard set
                  common_copy + "#line 4 0\nvoid main() {}\n");
}

// A file included first inside an #if that is compiled out, then again outside it, must reach the
// code after the second #include: the guard is GLSL's, read where the #if is. (Expanded once, its
// only copy sat in the dead block.)
TEST_F(ShaderFiles, AFileIncludedFirstUnderAFalseIfIsStillThereAfterIt) {
    write("units.h", "#define UNIT 3\n");
    write("maybe.glsl", "#if USE_IT\n#include \"units.h\"\n#endif\n");
    const auto main =
        write("main.frag", "#version 450 core\n#include \"maybe.glsl\"\n#include \"units.h\"\nint x = UNIT;\n");
    const std::string text = ocean::preprocess_shader(main, {}).text;
    const std::size_t second_copy = text.rfind("#define UNIT 3");
    ASSERT_NE(second_copy, std::string::npos);
    EXPECT_GT(second_copy, text.find("#endif\n#endif\n")) << text;  // after maybe.glsl's #if and guard close
    EXPECT_NE(text.find("#define UNIT 3"), second_copy) << "units.h written at both includes";
}

// An include cycle stops where it comes back to a file being expanded.
TEST_F(ShaderFiles, AnIncludeCycleStops) {
    write("a.glsl", "#include \"b.glsl\"\nfloat a;\n");
    write("b.glsl", "#include \"a.glsl\"\nfloat b;\n");
    const auto main = write("main.frag", "#version 450 core\n#include \"a.glsl\"\n");
    const std::string text = ocean::preprocess_shader(main, {}).text;
    EXPECT_NE(text.find("float a;"), std::string::npos);
    EXPECT_NE(text.find("float b;"), std::string::npos);
}

TEST_F(ShaderFiles, IncludeDirectoriesAreSearchedAfterTheIncludingFolder) {
    write("lib/found.glsl", "float x;\n");
    const auto main = write("main.vert", "#version 450 core\n#include \"found.glsl\"\n");
    const auto source = ocean::preprocess_shader(main, {(dir / "lib").string()});
    EXPECT_NE(source.text.find("float x;"), std::string::npos);
}

TEST_F(ShaderFiles, MissingIncludeNamesFileAndLine) {
    const auto main = write("main.frag", "#version 450 core\n\n#include \"absent.glsl\"\n");
    try {
        ocean::preprocess_shader(main, {});
        FAIL() << "expected an error";
    } catch (const ocean::Error& e) {
        EXPECT_EQ(std::string(e.what()), main + ":3: cannot find include \"absent.glsl\"");
    }
}

TEST_F(ShaderFiles, MissingVersionAndIncludedVersionAreErrors) {
    EXPECT_THROW(ocean::preprocess_shader(write("a.frag", "void main() {}\n"), {}), ocean::Error);
    write("v.glsl", "#version 450 core\n");
    EXPECT_THROW(ocean::preprocess_shader(write("b.frag", "#version 450 core\n#include \"v.glsl\"\n"), {}),
                 ocean::Error);
    EXPECT_THROW(ocean::preprocess_shader((dir / "missing.frag").string(), {}), ocean::Error);
}

TEST(ShaderLog, MesaAndNvidiaMessagesMapToFileAndLine) {
    const std::vector<std::string> files{"/s/ocean.frag", "/s/waves.glsl"};
    EXPECT_EQ(ocean::map_log_to_files("0:12(5): error: `x' undeclared\n", files),
              "/s/ocean.frag:12:5: error: `x' undeclared\n");
    EXPECT_EQ(ocean::map_log_to_files("1(7) : error C1008: undefined variable \"y\"\n", files),
              "/s/waves.glsl:7: error C1008: undefined variable \"y\"\n");
    EXPECT_EQ(ocean::map_log_to_files("9:1(1): error: z\n", files), "<source 9>:1:1: error: z\n");
}

TEST(ShaderLog, SummaryIsOneLineStartingAtTheFirstError) {
    EXPECT_EQ(ocean::first_line_summary("a.frag:1:1: warning: w\na.frag:2:1: error: e\nmore\n"),
              "a.frag:2:1: error: e (and 2 more lines of log)");
    EXPECT_EQ(ocean::first_line_summary("only\n"), "only");
}

TEST(ShaderStage, FromExtension) {
    EXPECT_EQ(ocean::shader_stage_for("a/ocean.vert"), GLenum(GL_VERTEX_SHADER));
#ifdef GL_COMPUTE_SHADER
    EXPECT_EQ(ocean::shader_stage_for("fft.comp"), GLenum(GL_COMPUTE_SHADER));
#else
    EXPECT_EQ(ocean::shader_stage_for("fft.comp"), 0u) << "GL 4.1 has no compute shaders";
#endif
#ifdef GL_TESS_EVALUATION_SHADER
    EXPECT_EQ(ocean::shader_stage_for("x.tese"), GLenum(GL_TESS_EVALUATION_SHADER));
#else
    EXPECT_EQ(ocean::shader_stage_for("x.tese"), 0u) << "ES 3.0 has no tessellation";
#endif
    EXPECT_EQ(ocean::shader_stage_for("waves.glsl"), 0u);
}

}  // namespace

// The portable profiles (common/gl_profile.hpp): the shader's #version 450 core becomes the
// profile's header, and each layout(binding = N) on a uniform moves to the host, N a number or a
// name #defined as one (step06's texture_units.h), wherever the #define came from.
namespace {

struct ProfileFiles : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("ocean_profile_test_" + std::to_string(::getpid()));
    ProfileFiles() { fs::create_directories(dir); }
    ~ProfileFiles() override { fs::remove_all(dir); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return fs::canonical(dir / name).string();
    }
    std::string shader() {
        write("units.h", "#define UNIT_SKY 4   // the sky\n");
        return write("main.frag",
                     "#version 450 core\n#include \"units.h\"\n"
                     "layout(binding = UNIT_SKY) uniform samplerCube u_sky;\n"
                     "layout(std140, binding = 2) uniform Waves {\n  vec4 w[4];\n};\n"
                     "layout(location = 0) out vec4 colour;\n"
                     "void main() { colour = texture(u_sky, w[0].xyz); }\n");
    }
};

TEST_F(ProfileFiles, TheDefaultProfileLeavesTheShaderAsWritten) {
    const auto source = ocean::preprocess_shader(shader(), {}, {}, ocean::GlProfile::Core45);
    EXPECT_EQ(source.text.rfind("#version 450 core\n", 0), 0u);
    EXPECT_NE(source.text.find("layout(binding = UNIT_SKY) uniform samplerCube u_sky;"), std::string::npos);
    EXPECT_TRUE(source.bindings.empty());
}

TEST_F(ProfileFiles, GL41TakesTheBindingsOutAndNamesThem) {
    const auto source = ocean::preprocess_shader(shader(), {}, {"EXTRA 1"}, ocean::GlProfile::Core41);
    EXPECT_EQ(source.text.rfind("#version 410 core\n#define OCEAN_GL_PORTABLE 1\n", 0), 0u) << source.text;
    EXPECT_NE(source.text.find("#define EXTRA 1"), std::string::npos) << "the step's defines still follow";
    EXPECT_NE(source.text.find("\nuniform samplerCube u_sky;\n"), std::string::npos) << source.text;
    EXPECT_NE(source.text.find("\nlayout(std140) uniform Waves {\n"), std::string::npos) << source.text;
    EXPECT_NE(source.text.find("layout(location = 0) out vec4 colour;"), std::string::npos) << "other layouts stay";
    EXPECT_EQ(source.text.find("binding"), std::string::npos);
    const std::vector<ocean::UniformBinding> expected{{"u_sky", 4, false}, {"Waves", 2, true}};
    EXPECT_EQ(source.bindings, expected);
}

TEST_F(ProfileFiles, ES30AddsPrecisionAndCoarseDerivativesBecomePlainOnes) {
    const auto source = ocean::preprocess_shader(shader(), {}, {}, ocean::GlProfile::Es30);
    EXPECT_EQ(source.text.rfind("#version 300 es\nprecision highp float;\n", 0), 0u) << source.text;
    EXPECT_NE(source.text.find("precision highp samplerCube;"), std::string::npos);
    EXPECT_NE(source.text.find("#define dFdxCoarse dFdx"), std::string::npos);
    EXPECT_EQ(source.bindings.size(), 2u);
}

TEST_F(ProfileFiles, ADefineTooLargeForAnIntIsNoUnitAndStopsNothing) {
    // A learner's `#define SEED 12345678901`: read in every profile; not a unit, not a crash.
    const auto main = write("big.frag", "#version 450 core\n#define SEED 123456789012345678901\n"
                                        "layout(binding = 99999999999) uniform sampler2D u_a;\nvoid main() {}\n");
    EXPECT_NO_THROW(ocean::preprocess_shader(main, {}, {}, ocean::GlProfile::Core45));
    try {
        ocean::preprocess_shader(main, {}, {}, ocean::GlProfile::Core41);
        FAIL() << "accepted a binding that is no int";
    } catch (const ocean::Error& e) {
        EXPECT_NE(std::string(e.what()).find("big.frag:3: binding = 99999999999"), std::string::npos) << e.what();
    }
}

TEST_F(ProfileFiles, ABindingThatIsNotANumberNamesItsLine) {
    const auto main = write("bad.frag", "#version 450 core\nlayout(binding = UNIT_NOWHERE) uniform sampler2D u_a;\nvoid main() {}\n");
    try {
        ocean::preprocess_shader(main, {}, {}, ocean::GlProfile::Core41);
        FAIL() << "accepted a binding it cannot read";
    } catch (const ocean::Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.frag:2: binding = UNIT_NOWHERE"), std::string::npos) << e.what();
    }
}

}  // namespace
