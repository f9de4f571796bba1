// Shaders: a small #include preprocessor, compile errors reported as file:line of the original
// file, and programs that hot-reload when one of their files changes, keeping the last good
// program when the edit does not compile.
#pragma once

#include "common/gl.hpp"
#include "common/gl_profile.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace ocean {

// A sampler's texture unit or a uniform block's binding point, which GLSL 4.2 and later write in
// the shader (layout(binding = N)) and an older profile sets from the host after linking.
struct UniformBinding {
    std::string name;    // the sampler uniform, or the uniform block
    int unit = 0;
    bool block = false;  // a uniform block (glUniformBlockBinding), else a sampler (glUniform1i)
    bool operator==(const UniformBinding& o) const { return name == o.name && unit == o.unit && block == o.block; }
};

struct ShaderSource {
    std::string text;                // what the driver compiles, with #line directives
    std::vector<std::string> files;  // source-string number (in #line) -> file path
    std::vector<UniformBinding> bindings;  // taken out of the text (profiles before 4.2 only)
};

// Expands `#include "name"` (looked up beside the including file, then in include_dirs), each
// file at most once per shader, and tags every piece with `#line N file-number` so that error
// messages can be mapped back. Throws ocean::Error naming file:line on a missing include.
// `defines` ("NAME VALUE" or "NAME") become #define lines right after #version: how a step
// builds compile-time variants of one shader.
//
// For a profile other than 4.5 core, the shader's `#version 450 core` becomes that profile's
// header (`#version 410 core`, or `#version 300 es` with its precision statements), followed by
// `#define OCEAN_GL_PORTABLE 1`; and each `binding = N` in a uniform's layout is taken out and
// returned in `bindings` (N a number or a name #defined as one, such as step06's texture_units.h).
ShaderSource preprocess_shader(const std::string& path, const std::vector<std::string>& include_dirs,
                               const std::vector<std::string>& defines = {},
                               GlProfile profile = kBuildProfile);

// Rewrites driver messages ("0:12(5): error" from Mesa, "0(12) : error" from NVIDIA) into
// "path:12:5: error" using the file table of preprocess_shader.
std::string map_log_to_files(const std::string& log, const std::vector<std::string>& files);

// GL_VERTEX_SHADER for ".vert", and so on for .frag .comp .geom .tesc .tese; 0 otherwise (and for
// .comp in a profile without compute shaders).
GLenum shader_stage_for(const std::string& path);

// The include directories every shader gets: the repository root, so a later chapter includes
// an earlier one's GLSL as "step02_sine3d/shaders/waves.glsl", and common/shaders.
std::vector<std::string> default_include_dirs();

class ShaderProgram {
public:
    // `feedback_varyings` are captured by transform feedback (used by the read-back tests);
    // `defines` select a compile-time variant (see preprocess_shader).
    ShaderProgram(std::string name, std::vector<std::string> stage_paths,
                  std::vector<std::string> feedback_varyings = {}, std::vector<std::string> defines = {});

    // Compiles and links every stage. On failure the previous program (if any) stays in use
    // and the message (file:line form) is returned and kept in last_error().
    std::optional<std::string> build();
    // True when a file this program was built from has a new modification time.
    bool sources_changed() const;

    GLuint id() const { return program_.id(); }
    const std::string& name() const { return name_; }
    const std::string& last_error() const { return last_error_; }
    const std::vector<std::string>& stage_paths() const { return stage_paths_; }

    GLint location(const std::string& uniform) const;
    void set(const std::string& uniform, float v) const;
    void set(const std::string& uniform, int v) const;
    void set(const std::string& uniform, const glm::vec2& v) const;
    void set(const std::string& uniform, const glm::ivec2& v) const;
    void set(const std::string& uniform, const glm::vec3& v) const;
    void set(const std::string& uniform, const glm::vec4& v) const;
    void set(const std::string& uniform, const glm::mat4& v) const;
    void set(const std::string& uniform, const std::vector<glm::vec4>& v) const;
    void set(const std::string& uniform, const std::vector<glm::vec3>& v) const;
    void set(const std::string& uniform, const std::vector<float>& v) const;
    void set(const std::string& uniform, const std::vector<glm::vec2>& v) const;

private:
    std::string name_;
    std::vector<std::string> stage_paths_;
    std::vector<std::string> feedback_varyings_;
    std::vector<std::string> defines_;
    Program program_;
    std::string last_error_;
    std::vector<std::pair<std::string, std::filesystem::file_time_type>> watched_;
    mutable std::unordered_map<std::string, GLint> locations_;
};

// Builds (or finds) a compile-time variant of a program from repository-relative files: what
// a chapter's technique asks for its shaders. Steps pass App::program_factory() (hot reload,
// errors in the panel); tests build directly (tests/gpu/program_cache.hpp).
using ProgramFactory = std::function<ShaderProgram*(const std::string& name, const std::vector<std::string>& files,
                                                    const std::vector<std::string>& defines)>;

// Sets each binding in `program` (linked) from the host: what layout(binding = N) does in the
// shader in GLSL 4.2 and later (ShaderProgram::build calls it for the older profiles).
void apply_bindings(GLuint program, const std::vector<UniformBinding>& bindings);

// Compiles one stage from source; on failure returns the mapped log in *error.
Shader compile_shader_stage(GLenum stage, const ShaderSource& source, std::string* error);

// The first line of a (possibly long) compiler log, plus how many more there were: the one
// line a fatal error prints.
std::string first_line_summary(const std::string& log);

}  // namespace ocean
