// Every shader program a step uses, built on first request and kept: the one way a step (or a
// chapter's technique class, through a ProgramFactory) gets a program. A program is named, made
// of stage files, and optionally a compile-time variant (`defines` such as "VIEW 3"). The
// library also hot-reloads: a program whose files changed is rebuilt, and a failed rebuild keeps
// the last good one.
#pragma once

#include "common/shader.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ocean {

class ProgramLibrary {
public:
    // Where stage files are found: a bare name in `shader_dir` (the step's shaders/, or
    // --shader-dir), else in common/shaders; "dir/file" relative to the repository (a later
    // chapter using an earlier one's shader), except that a file of the step's own shaders folder
    // (`own_dir`, as a chapter's classes name it: "step05_fft/shaders/fft.comp") is read from
    // `shader_dir` too, so --shader-dir (and an exercise's copy) replaces every shader of the step.
    void set_shader_dir(std::string own_dir, std::string shader_dir) {
        own_dir_ = std::move(own_dir);
        shader_dir_ = std::move(shader_dir);
    }
    // A chapter that runs an earlier chapter's program (step07 draws step06's sea) also finds bare
    // names in that chapter's shaders folder (`dir`, from the repository root), after its own
    // shader_dir and before common/shaders.
    void inherit_shaders_of(std::string dir) { inherited_dirs_.push_back(std::move(dir)); }

    // The program `name` built from `stage_files` with `defines`. Until running() a program that
    // does not build throws ocean::Error (the step cannot start). Afterwards (the user switched
    // to a variant after breaking a shader) the error goes to message() and the last good program
    // of the same name is returned, so the step keeps drawing; message() names it, as it may be
    // another variant. nullptr only when no program of that name ever built.
    ShaderProgram* get(const std::string& name, const std::vector<std::string>& stage_files,
                       const std::vector<std::string>& defines = {});
    ProgramFactory factory() {
        return [this](const std::string& name, const std::vector<std::string>& files,
                      const std::vector<std::string>& defines) { return get(name, files, defines); };
    }

    // Rebuilds the programs whose files changed since they were built (or all of them: F5).
    void reload_changed() { reload(false); }
    void rebuild_all() { reload(true); }
    // From the first frame on, failures are reported, not fatal.
    void set_running() { running_ = true; }
    // The last build problem (for the panel), "" when none.
    const std::string& message() const { return message_; }
    void clear() { programs_.clear(); by_key_.clear(); last_good_.clear(); failed_.clear(); }

private:
    void reload(bool all);
    std::vector<std::string> stage_paths(const std::vector<std::string>& stage_files) const;

    std::string own_dir_, shader_dir_;
    std::vector<std::string> inherited_dirs_;
    std::vector<std::unique_ptr<ShaderProgram>> programs_;
    std::map<std::string, ShaderProgram*> by_key_;     // name + defines
    std::map<std::string, ShaderProgram*> last_good_;  // name -> the variant built last
    std::map<std::string, std::unique_ptr<ShaderProgram>> failed_;  // not built; retried on a change
    bool running_ = false;
    std::string message_;
};

}  // namespace ocean
