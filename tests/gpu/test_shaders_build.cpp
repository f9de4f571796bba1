// Every shader in the repository compiles, and every program links. The list comes from CMake
// (add_step's SHADERS and the tests' own); programs are formed by file stem: ocean.vert +
// ocean.frag is the program "ocean"; a fragment shader with no vertex shader of its stem is a
// fullscreen pass and links with common/shaders/fullscreen.vert; a .comp links alone.
#include "common/error.hpp"
#include "common/program_library.hpp"
#include "common/shader.hpp"
#include "tests/gpu/gl_test_context.hpp"

#include <filesystem>
#include <fstream>
#include <map>

namespace fs = std::filesystem;

namespace {

std::vector<std::string> repository_shaders() {
    std::ifstream list(OCEAN_SHADER_LIST);
    std::vector<std::string> files;
    for (std::string line; std::getline(list, line);)
        if (!line.empty() && ocean::shader_stage_for(line) != 0) files.push_back(line);
    return files;
}

using ShaderBuild = ocean_test::GlTest;

TEST_F(ShaderBuild, TheListHasEveryStepsShaders) {
    const auto files = repository_shaders();
    EXPECT_GE(files.size(), 4u);
    bool has_step01 = false, has_step02 = false;
    for (const auto& f : files) {
        has_step01 = has_step01 || f.find("step01_sine2d/shaders/plot.frag") != std::string::npos;
        has_step02 = has_step02 || f.find("step02_sine3d/shaders/ocean.vert") != std::string::npos;
    }
    EXPECT_TRUE(has_step01 && has_step02);
}

TEST_F(ShaderBuild, EveryShaderCompilesAndEveryProgramLinks) {
    // folder/stem -> stage files; a compute shader is a program of its own (a shader.comp beside
    // a shader.frag of the same stem would be two programs, not one).
    std::map<std::string, std::vector<std::string>> programs;
    for (const auto& file : repository_shaders()) {
        const fs::path p(file);
        const bool compute = ocean::shader_stage_for(file) == GL_COMPUTE_SHADER;
        programs[(p.parent_path() / p.stem()).string() + (compute ? ".comp" : "")].push_back(file);
    }
    const std::string fullscreen = std::string(OCEAN_SOURCE_DIR) + "/common/shaders/fullscreen.vert";
    int built = 0;
    for (auto& [name, stages] : programs) {
        const bool has_vertex = std::any_of(stages.begin(), stages.end(), [](const std::string& s) {
            return ocean::shader_stage_for(s) == GL_VERTEX_SHADER;
        });
        const bool has_fragment = std::any_of(stages.begin(), stages.end(), [](const std::string& s) {
            return ocean::shader_stage_for(s) == GL_FRAGMENT_SHADER;
        });
        if (has_fragment && !has_vertex) stages.push_back(fullscreen);
        ocean::ShaderProgram program(name, stages);
        const auto error = program.build();
        EXPECT_FALSE(error) << name << ":\n" << error.value_or("");
        ++built;
    }
    EXPECT_GE(built, 3);
}

TEST_F(ShaderBuild, ABrokenEditKeepsTheLastGoodProgram) {
    const fs::path dir = fs::temp_directory_path() / ("ocean_reload_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path frag = dir / "pass.frag";
    std::ofstream(frag) << "#version 450 core\nout vec4 c;\nvoid main() { c = vec4(1); }\n";
    ocean::ShaderProgram program("pass", {std::string(OCEAN_SOURCE_DIR) + "/common/shaders/fullscreen.vert",
                                          frag.string()});
    ASSERT_FALSE(program.build());
    const GLuint good = program.id();
    EXPECT_FALSE(program.sources_changed());

    std::ofstream(frag) << "#version 450 core\nout vec4 c;\nvoid main() { c = oops; }\n";
    fs::last_write_time(frag, fs::last_write_time(frag) + std::chrono::seconds(2));
    EXPECT_TRUE(program.sources_changed());
    const auto error = program.build();
    ASSERT_TRUE(error);
    EXPECT_NE(error->find(frag.string() + ":3:"), std::string::npos) << "file:line of the edit: " << *error;
    EXPECT_EQ(program.id(), good) << "the last good program stays in use";

    std::ofstream(frag) << "#version 450 core\nout vec4 c;\nvoid main() { c = vec4(0.5); }\n";
    fs::last_write_time(frag, fs::last_write_time(frag) + std::chrono::seconds(4));
    EXPECT_FALSE(program.build());
    EXPECT_NE(program.id(), 0u);
    EXPECT_TRUE(program.last_error().empty());
    fs::remove_all(dir);
}

// A variant that does not build once the step runs: the library keeps drawing the last program of
// that name that built, which may be another variant, and its message says which.
TEST_F(ShaderBuild, AVariantThatDoesNotBuildSaysWhichProgramIsDrawnInstead) {
    const fs::path dir = fs::temp_directory_path() / ("ocean_variant_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "pass.frag") << "#version 450 core\nout vec4 c;\n"
                                        "void main() {\n#if VIEW == 1\n c = oops;\n#else\n c = vec4(1);\n#endif\n}\n";
    ocean::ProgramLibrary library;
    library.set_shader_dir(dir.string(), dir.string());
    ocean::ShaderProgram* good = library.get("pass", {"fullscreen.vert", "pass.frag"}, {"VIEW 0"});
    ASSERT_NE(good, nullptr);
    EXPECT_THROW(library.get("pass", {"fullscreen.vert", "pass.frag"}, {"VIEW 1"}), ocean::Error)
        << "before the first frame a program that does not build stops the step";
    library.set_running();
    ocean::ShaderProgram* drawn = library.get("pass", {"fullscreen.vert", "pass.frag"}, {"VIEW 1"});
    EXPECT_EQ(drawn, good) << "the last program of that name that built";
    EXPECT_NE(library.message().find("'pass [VIEW 1]' does not build; drawing 'pass [VIEW 0]'"), std::string::npos)
        << library.message();
    fs::remove_all(dir);
}

}  // namespace

// The portable profiles move layout(binding = N) to the host (apply_bindings): compiled as GL 4.1
// core (which this 4.5 context also takes), step06's sky pass reads the sky from unit UNIT_SKY (4),
// as its 4.5 text says, not from unit 0 where a sampler starts.
TEST_F(ShaderBuild, AProgramInTheGL41ProfileGetsItsBindingsFromTheHost) {
    const auto compile = [](const std::string& file) {
        const ocean::ShaderSource source = ocean::preprocess_shader(
            std::string(OCEAN_SOURCE_DIR) + "/" + file, ocean::default_include_dirs(), {}, ocean::GlProfile::Core41);
        std::string error;
        ocean::Shader shader = ocean::compile_shader_stage(ocean::shader_stage_for(file), source, &error);
        EXPECT_TRUE(shader) << file << ": " << error;
        return std::pair(std::move(shader), source.bindings);
    };
    auto [vertex, none] = compile("common/shaders/fullscreen.vert");
    auto [fragment, bindings] = compile("step06_foam_sky/shaders/sky.frag");
    ASSERT_TRUE(vertex && fragment);
    ASSERT_EQ(bindings.size(), 1u);
    EXPECT_EQ(bindings[0].name, "u_sky");
    EXPECT_EQ(bindings[0].unit, 4);
    ocean::Program program(glCreateProgram());
    glAttachShader(program.id(), vertex.id());
    glAttachShader(program.id(), fragment.id());
    glLinkProgram(program.id());
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    ASSERT_EQ(linked, GL_TRUE);
    const GLint location = glGetUniformLocation(program.id(), "u_sky");
    ASSERT_GE(location, 0);
    GLint unit = -1;
    glGetUniformiv(program.id(), location, &unit);
    EXPECT_EQ(unit, 0) << "without the host, a sampler starts on unit 0";
    ocean::apply_bindings(program.id(), bindings);
    glGetUniformiv(program.id(), location, &unit);
    EXPECT_EQ(unit, 4) << "UNIT_SKY, from step06's texture_units.h";
    GLint current = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    EXPECT_EQ(current, 0) << "apply_bindings leaves the program that was in use";
}
