#include "common/program_library.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <filesystem>
#include <iostream>

namespace ocean {

namespace fs = std::filesystem;

std::vector<std::string> ProgramLibrary::stage_paths(const std::vector<std::string>& stage_files) const {
    std::vector<std::string> paths;
    for (const auto& file : stage_files) {
        if (file.find('/') != std::string::npos) {
            const fs::path in_repository = fs::path(OCEAN_SOURCE_DIR) / file;
            const bool own = !own_dir_.empty() && fs::path(own_dir_).lexically_normal() ==
                                                      in_repository.parent_path().lexically_normal();
            paths.push_back((own ? fs::path(shader_dir_) / in_repository.filename() : in_repository).string());
            continue;
        }
        const fs::path own = fs::path(shader_dir_) / file;
        fs::path found = own;
        if (!fs::exists(own)) {
            std::vector<fs::path> candidates;
            for (const auto& dir : inherited_dirs_) candidates.push_back(fs::path(OCEAN_SOURCE_DIR) / dir / file);
            candidates.push_back(fs::path(OCEAN_SOURCE_DIR) / "common" / "shaders" / file);
            for (const auto& candidate : candidates)
                if (fs::exists(candidate)) {
                    found = candidate;
                    break;
                }
        }
        paths.push_back(found.string());
    }
    return paths;
}

ShaderProgram* ProgramLibrary::get(const std::string& name, const std::vector<std::string>& stage_files,
                                   const std::vector<std::string>& defines) {
    const std::string key = name + "|" + join(defines, "|");
    if (auto it = by_key_.find(key); it != by_key_.end()) return last_good_[name] = it->second;
    const auto fallback = [&]() -> ShaderProgram* {
        const auto previous = last_good_.find(name);
        return previous == last_good_.end() ? nullptr : previous->second;
    };
    // A variant that failed is tried again only once one of its files has changed.
    auto failed = failed_.find(key);
    if (failed != failed_.end() && !failed->second->sources_changed()) return fallback();
    const std::string label = defines.empty() ? name : name + " [" + join(defines, ", ") + "]";
    auto program = failed != failed_.end()
                       ? std::move(failed->second)
                       : std::make_unique<ShaderProgram>(label, stage_paths(stage_files), std::vector<std::string>{},
                                                         defines);
    if (failed != failed_.end()) failed_.erase(failed);
    if (auto error = program->build()) {
        if (!running_) throw Error("shader program '" + label + "' does not build: " + first_line_summary(*error));
        std::cerr << "shader program '" << label << "' does not build:\n" << *error;
        // What is drawn instead is said, not left to be guessed: it may be another variant.
        ShaderProgram* instead = fallback();
        message_ = "'" + label + "' does not build; " +
                   (instead != nullptr ? "drawing '" + instead->name() + "' (the last that built) until it does"
                                       : "nothing to draw in its place") +
                   ":\n" + *error;
        failed_[key] = std::move(program);
        return instead;
    }
    programs_.push_back(std::move(program));
    return last_good_[name] = by_key_[key] = programs_.back().get();
}

void ProgramLibrary::reload(bool all) {
    for (auto& program : programs_) {
        if (!all && !program->sources_changed()) continue;
        if (auto error = program->build()) {
            std::cerr << "shader reload failed, keeping the last good '" << program->name() << "':\n" << *error;
            message_ = "reload failed (last good program kept):\n" + *error;
        } else {
            std::cerr << "shader '" << program->name() << "' reloaded\n";
            message_.clear();
        }
    }
}

}  // namespace ocean
