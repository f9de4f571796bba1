#include "common/shader.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#ifndef OCEAN_SOURCE_DIR
#error "OCEAN_SOURCE_DIR must name the repository root"
#endif

namespace ocean {

namespace fs = std::filesystem;

namespace {

// The first lines of a shader in each profile, in place of its `#version 450 core`. GLSL ES has
// no default precision for floats in fragment shaders nor for most sampler types: all highp.
// Before 4.5 there are no coarse derivatives by name: the plain ones (which an implementation may
// compute coarsely anyway) stand in, the one built-in the shaders use that 4.1 lacks.
std::string version_header(GlProfile profile) {
    const std::string portable = "#define OCEAN_GL_PORTABLE 1\n#define dFdxCoarse dFdx\n#define dFdyCoarse dFdy\n";
    switch (profile) {
        case GlProfile::Core45: return "#version 450 core\n";
        case GlProfile::Core41: return "#version 410 core\n" + portable;
        case GlProfile::Es30:
            return "#version 300 es\n"
                   "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
                   "precision highp sampler2DArray;\nprecision highp sampler3D;\nprecision highp samplerCube;\n"
                   "precision highp usampler2D;\nprecision highp isampler2D;\n" + portable;
    }
    return "";
}

struct Preprocessor {
    std::vector<std::string> include_dirs;
    std::vector<std::string> defines;
    GlProfile profile = GlProfile::Core45;
    std::vector<std::string> files;
    std::map<std::string, int> numbers;      // names #defined as a whole number (texture units)
    std::vector<UniformBinding> bindings;    // taken out of layout qualifiers (profiles before 4.2)
    std::set<std::string> expanding;  // the files whose expansion is under way (an include cycle stops there)
    std::ostringstream out;

    // A file's number for #line: the same each time it is included.
    int file_number(const std::string& path) {
        const auto found = std::find(files.begin(), files.end(), path);
        if (found != files.end()) return static_cast<int>(found - files.begin());
        files.push_back(path);
        return static_cast<int>(files.size()) - 1;
    }

    std::string resolve(const std::string& name, const std::string& from) const {
        std::vector<fs::path> candidates{fs::path(from).parent_path() / name};
        for (const auto& dir : include_dirs) candidates.push_back(fs::path(dir) / name);
        for (const auto& c : candidates)
            if (fs::is_regular_file(c)) return fs::weakly_canonical(c).string();
        return "";
    }

    // A whole number that fits an int, else nothing (a #define of 10^20 is not a texture unit, and
    // must not stop the shader).
    static std::optional<int> whole_number(const std::string& text) {
        int value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
        return value;
    }

    // `#define NAME 42`: remembered, so that `binding = NAME` can be read.
    void note_number(const std::string& line) {
        if (profile == GlProfile::Core45) return;  // 4.5 keeps its bindings: no regex on every line
        static const std::regex define_re(R"(^\s*#\s*define\s+(\w+)\s+(-?\d+)\s*(//.*)?$)");
        std::smatch m;
        if (!std::regex_match(line, m, define_re)) return;
        if (const std::optional<int> value = whole_number(m[2].str())) numbers[m[1].str()] = *value;
    }

    // In `layout(..., binding = N) uniform TYPE NAME;` or `layout(..., binding = N) uniform BLOCK {`
    // takes `binding = N` out (the whole layout when nothing else is in it) and records it.
    std::string take_binding(const std::string& line, const std::string& where) {
        static const std::regex layout_re(R"(layout\s*\(([^)]*)\)\s*uniform\s+(\w+)(\s*)(\w*))");
        static const std::regex binding_re(R"(^\s*binding\s*=\s*(\w+)\s*$)");
        std::smatch m;
        if (!std::regex_search(line, m, layout_re)) return line;
        std::vector<std::string> kept;
        std::optional<std::string> value;
        for (const std::string& item : split(m[1].str(), ',')) {
            std::smatch b;
            if (std::regex_match(item, b, binding_re)) value = b[1].str();
            else kept.push_back(trim(item));
        }
        if (!value) return line;
        std::optional<int> unit = whole_number(*value);
        if (auto found = numbers.find(*value); !unit && found != numbers.end()) unit = found->second;
        if (!unit || *unit < 0)
            throw Error(where + ": binding = " + *value + " is neither a number nor a name #defined as one");
        // A block: `uniform Name {` (nothing after its name on the line, or the brace); a sampler:
        // `uniform sampler2D u_name`.
        const bool block = m[4].str().empty();
        bindings.push_back({block ? m[2].str() : m[4].str(), *unit, block});
        std::string qualifiers;
        for (const std::string& k : kept) qualifiers += (qualifiers.empty() ? "" : ", ") + k;
        const std::string replaced = (qualifiers.empty() ? "" : "layout(" + qualifiers + ") ") + "uniform " +
                                     m[2].str() + m[3].str() + m[4].str();
        return m.prefix().str() + replaced + m.suffix().str();
    }

    void expand(const std::string& path, bool is_main) {
        std::string text;
        if (auto error = read_text_file(path, &text)) throw Error("cannot read shader " + *error);
        const int number = file_number(path);
        std::istringstream lines(text);
        std::string line;
        int line_number = 0;
        bool version_seen = false;
        // An included file is written out at every #include, inside a guard that GLSL's own
        // preprocessor reads: its first copy counts only where it is compiled in. (Written out
        // once, a file included first inside an #if that is compiled out was missing from every
        // later file that included it too.)
        const std::string guard = "OCEAN_INCLUDED_" + std::to_string(number);
        if (!is_main) out << "#ifndef " << guard << "\n#define " << guard << "\n#line 1 " << number << "\n";
        expanding.insert(path);
        static const std::regex include_re(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
        static const std::regex version_re(R"(^\s*#\s*version\b.*)");
        while (std::getline(lines, line)) {
            ++line_number;
            std::smatch match;
            if (std::regex_match(line, version_re)) {
                if (!is_main)
                    throw Error(path + ":" + std::to_string(line_number) +
                                ": an included file must not have #version");
                out << (profile == GlProfile::Core45 ? line + "\n" : version_header(profile));
                for (const auto& define : defines) {
                    out << "#define " << define << "\n";
                    note_number("#define " + define);
                }
                out << "#line " << line_number + 1 << " " << number << "\n";
                version_seen = true;
            } else if (std::regex_match(line, match, include_re)) {
                const std::string target = resolve(match[1].str(), path);
                if (target.empty())
                    throw Error(path + ":" + std::to_string(line_number) + ": cannot find include \"" +
                                match[1].str() + "\"");
                if (expanding.count(target) == 0) expand(target, false);
                out << "#line " << line_number + 1 << " " << number << "\n";
            } else {
                note_number(line);
                if (profile != GlProfile::Core45 && line.find("binding") != std::string::npos)
                    out << take_binding(line, path + ":" + std::to_string(line_number)) << "\n";
                else
                    out << line << "\n";
            }
        }
        expanding.erase(path);
        if (!is_main) out << "#endif\n";
        if (is_main && !version_seen)
            throw Error(path + ": a shader must start with #version (we use #version 450 core)");
    }
};

}  // namespace

std::vector<std::string> default_include_dirs() {
    return {OCEAN_SOURCE_DIR, std::string(OCEAN_SOURCE_DIR) + "/common/shaders"};
}

ShaderSource preprocess_shader(const std::string& path, const std::vector<std::string>& include_dirs,
                               const std::vector<std::string>& defines, GlProfile profile) {
    Preprocessor pre;
    pre.include_dirs = include_dirs;
    pre.defines = defines;
    pre.profile = profile;
    const std::string main_path = fs::exists(path) ? fs::weakly_canonical(path).string() : path;
    pre.expand(main_path, true);
    return {pre.out.str(), pre.files, pre.bindings};
}

std::string map_log_to_files(const std::string& log, const std::vector<std::string>& files) {
    static const std::regex mesa_re(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex nvidia_re(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::ostringstream out;
    std::istringstream lines(log);
    std::string line;
    auto file_name = [&](const std::string& number) {
        const std::size_t i = std::stoul(number);
        return i < files.size() ? files[i] : "<source " + number + ">";
    };
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_match(line, m, mesa_re))
            out << file_name(m[1]) << ":" << m[2] << ":" << m[3] << ": " << m[4] << "\n";
        else if (std::regex_match(line, m, nvidia_re))
            out << file_name(m[1]) << ":" << m[2] << ": " << m[3] << "\n";
        else if (!trim(line).empty())
            out << line << "\n";
    }
    return out.str();
}

GLenum shader_stage_for(const std::string& path) {
    const std::string ext = fs::path(path).extension().string();
    if (ext == ".vert") return GL_VERTEX_SHADER;
    if (ext == ".frag") return GL_FRAGMENT_SHADER;
#ifdef GL_COMPUTE_SHADER  // GL 4.3: not in the portable build's loader
    if (ext == ".comp") return GL_COMPUTE_SHADER;
#endif
#ifdef GL_TESS_CONTROL_SHADER  // GL 3.2 and 4.0: not in ES 3.0's loader
    if (ext == ".geom") return GL_GEOMETRY_SHADER;
    if (ext == ".tesc") return GL_TESS_CONTROL_SHADER;
    if (ext == ".tese") return GL_TESS_EVALUATION_SHADER;
#endif
    return 0;
}

std::string first_line_summary(const std::string& log) {
    std::vector<std::string> lines;
    for (const auto& l : split(log, '\n'))
        if (!trim(l).empty()) lines.push_back(trim(l));
    if (lines.empty()) return "(no message)";
    // Prefer the first line that says "error" over warnings printed before it.
    auto first = std::find_if(lines.begin(), lines.end(),
                              [](const std::string& l) { return l.find("error") != std::string::npos; });
    if (first == lines.end()) first = lines.begin();
    std::string summary = *first;
    if (lines.size() > 1)
        summary += " (and " + std::to_string(lines.size() - 1) + " more line" +
                   (lines.size() > 2 ? "s" : "") + " of log)";
    return summary;
}

Shader compile_shader_stage(GLenum stage, const ShaderSource& source, std::string* error) {
    Shader shader(glCreateShader(stage));
    const char* text = source.text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (ok == GL_TRUE) return shader;
    GLint length = 0;
    glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
    *error = map_log_to_files(log.c_str(), source.files);
    if (trim(*error).empty()) *error = source.files.front() + ": failed to compile (no log)";
    return Shader();
}

// What layout(binding = N) does in GLSL 4.2 and later, done by the host once the program is linked:
// each sampler reads its texture unit, each uniform block its binding point.
void apply_bindings(GLuint program, const std::vector<UniformBinding>& bindings) {
    detail::BindForEdit use(GL_CURRENT_PROGRAM, program);  // glUniform1i writes the program in use
    for (const UniformBinding& b : bindings) {
        if (b.block) {
            const GLuint index = glGetUniformBlockIndex(program, b.name.c_str());
            if (index != GL_INVALID_INDEX) glUniformBlockBinding(program, index, GLuint(b.unit));
        } else if (const GLint location = glGetUniformLocation(program, b.name.c_str()); location >= 0) {
            glUniform1i(location, b.unit);
        }
    }
}

ShaderProgram::ShaderProgram(std::string name, std::vector<std::string> stage_paths,
                             std::vector<std::string> feedback_varyings, std::vector<std::string> defines)
    : name_(std::move(name)), stage_paths_(std::move(stage_paths)),
      feedback_varyings_(std::move(feedback_varyings)), defines_(std::move(defines)) {}

std::optional<std::string> ShaderProgram::build() {
    std::vector<Shader> stages;
    std::vector<UniformBinding> bindings;  // the shaders' layout(binding = N), set here before 4.2
    std::vector<std::pair<std::string, fs::file_time_type>> watched;
    auto fail = [&](const std::string& message) {
        last_error_ = message;
        // Watch what we could read, so fixing the file triggers the next reload.
        if (!watched.empty()) watched_ = watched;
        return std::optional<std::string>(message);
    };
    for (const auto& path : stage_paths_) {
        const GLenum stage = shader_stage_for(path);
        if (stage == 0) {
            const std::string ext = fs::path(path).extension().string();
            const bool known = ext == ".comp" || ext == ".geom" || ext == ".tesc" || ext == ".tese";
            return fail(path + (known ? std::string(": OpenGL ") + profile_name(kBuildProfile) + " has no such shader stage"
                                      : std::string(": unknown shader stage (use .vert .frag .comp ...)")));
        }
        ShaderSource source;
        try {
            source = preprocess_shader(path, default_include_dirs(), defines_);
        } catch (const Error& e) {
            if (fs::exists(path)) watched.emplace_back(path, fs::last_write_time(path));
            return fail(e.what());
        }
        for (const auto& file : source.files) {
            std::error_code ec;
            watched.emplace_back(file, fs::last_write_time(file, ec));
        }
        std::string error;
        Shader shader = compile_shader_stage(stage, source, &error);
        if (!shader) return fail(error);
        stages.push_back(std::move(shader));
        for (const UniformBinding& b : source.bindings)
            if (std::find(bindings.begin(), bindings.end(), b) == bindings.end()) bindings.push_back(b);
    }
    Program program(glCreateProgram());
    for (const auto& s : stages) glAttachShader(program.id(), s.id());
    if (!feedback_varyings_.empty()) {
        std::vector<const char*> names;
        for (const auto& v : feedback_varyings_) names.push_back(v.c_str());
        glTransformFeedbackVaryings(program.id(), static_cast<GLsizei>(names.size()), names.data(),
                                    GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        return fail(name_ + ": link failed: " + trim(log.c_str()));
    }
    if (!bindings.empty()) apply_bindings(program.id(), bindings);
    program_ = std::move(program);
    watched_ = std::move(watched);
    locations_.clear();
    last_error_.clear();
    return std::nullopt;
}

bool ShaderProgram::sources_changed() const {
    for (const auto& [path, time] : watched_) {
        std::error_code ec;
        const auto now = fs::last_write_time(path, ec);
        if (!ec && now != time) return true;
    }
    return false;
}

GLint ShaderProgram::location(const std::string& uniform) const {
    auto it = locations_.find(uniform);
    if (it == locations_.end())
        it = locations_.emplace(uniform, glGetUniformLocation(program_.id(), uniform.c_str())).first;
    return it->second;
}

// Writes a uniform of this program without leaving it in use. GL 4.1 and 4.5 write a program's
// uniforms by its name (glProgramUniform*); ES 3.0 writes only the program in use (glUniform*), so
// there the program is put in use for the write and the one before put back. Location -1 (a
// uniform the compiler optimised away) is silently ignored by GL, which is what we want while
// editing.
#if defined(OCEAN_GL_ES)
// The program is usually in use already (set right after glUseProgram): then it is written
// straight away, without putting another program in use and back.
#define OCEAN_SET_UNIFORM(Form, ...)                                  \
    do {                                                              \
        if (detail::bound(GL_CURRENT_PROGRAM) == id()) {              \
            glUniform##Form(__VA_ARGS__);                             \
        } else {                                                      \
            detail::BindForEdit use(GL_CURRENT_PROGRAM, id());        \
            glUniform##Form(__VA_ARGS__);                             \
        }                                                             \
    } while (false)
#else
#define OCEAN_SET_UNIFORM(Form, ...) glProgramUniform##Form(id(), __VA_ARGS__)
#endif

void ShaderProgram::set(const std::string& u, float v) const { OCEAN_SET_UNIFORM(1f, location(u), v); }
void ShaderProgram::set(const std::string& u, int v) const { OCEAN_SET_UNIFORM(1i, location(u), v); }
void ShaderProgram::set(const std::string& u, const glm::vec2& v) const {
    OCEAN_SET_UNIFORM(2fv, location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::vec3& v) const {
    OCEAN_SET_UNIFORM(3fv, location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::vec4& v) const {
    OCEAN_SET_UNIFORM(4fv, location(u), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const glm::mat4& v) const {
    OCEAN_SET_UNIFORM(Matrix4fv, location(u), 1, GL_FALSE, glm::value_ptr(v));
}
void ShaderProgram::set(const std::string& u, const std::vector<glm::vec4>& v) const {
    if (!v.empty()) OCEAN_SET_UNIFORM(4fv, location(u), static_cast<GLsizei>(v.size()), glm::value_ptr(v[0]));
}
void ShaderProgram::set(const std::string& u, const std::vector<glm::vec3>& v) const {
    if (!v.empty()) OCEAN_SET_UNIFORM(3fv, location(u), static_cast<GLsizei>(v.size()), glm::value_ptr(v[0]));
}
void ShaderProgram::set(const std::string& u, const std::vector<float>& v) const {
    if (!v.empty()) OCEAN_SET_UNIFORM(1fv, location(u), static_cast<GLsizei>(v.size()), v.data());
}
void ShaderProgram::set(const std::string& u, const glm::ivec2& v) const { OCEAN_SET_UNIFORM(2i, location(u), v.x, v.y); }
void ShaderProgram::set(const std::string& u, const std::vector<glm::vec2>& v) const {
    if (!v.empty()) OCEAN_SET_UNIFORM(2fv, location(u), static_cast<GLsizei>(v.size()), glm::value_ptr(v[0]));
}

#undef OCEAN_SET_UNIFORM

}  // namespace ocean
