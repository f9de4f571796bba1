// One exception type for fatal, user-facing errors. Its message is the single line printed on
// stderr (after "error: ") before the program exits non-zero; write it for the user.
#pragma once

#include <stdexcept>
#include <string>

namespace ocean {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace ocean
