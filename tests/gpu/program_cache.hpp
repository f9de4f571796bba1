// A ProgramFactory for tests: builds each (file, defines) variant once from the repository and
// fails the test with the compiler's message if it does not build.
#pragma once

#include "common/shader.hpp"

#include <gtest/gtest.h>

#include <map>
#include <memory>

namespace ocean_test {

class ProgramCache {
public:
    ocean::ShaderProgram* operator()(const std::string& name, const std::vector<std::string>& files,
                                     const std::vector<std::string>& defines) {
        std::string key = name;
        for (const auto& d : defines) key += "|" + d;
        auto& slot = programs_[key];
        if (!slot) {
            std::vector<std::string> paths;
            for (const auto& f : files) paths.push_back(std::string(OCEAN_SOURCE_DIR) + "/" + f);
            slot = std::make_unique<ocean::ShaderProgram>(name, paths, std::vector<std::string>{}, defines);
            if (auto error = slot->build()) {
                ADD_FAILURE() << *error;
                return nullptr;
            }
        }
        return slot.get();
    }

    // This cache as a ProgramFactory (it must outlive what uses it).
    ocean::ProgramFactory factory() {
        return [this](const std::string& n, const std::vector<std::string>& f, const std::vector<std::string>& d) {
            return (*this)(n, f, d);
        };
    }

private:
    std::map<std::string, std::unique_ptr<ocean::ShaderProgram>> programs_;
};

}  // namespace ocean_test
