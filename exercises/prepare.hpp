// `exercise prepare`: the learner's copy of an exercise.
#pragma once

#include <optional>
#include <string>

#include "exercises/exercise.hpp"

namespace exercises {

// Copies the step's shaders (a C++ exercise: its one file) from `source_root`/STEP into `work`, with
// the exercise's function body replaced by its stub, so that the step runs on the learner's copy
// (--shader-dir, hot reload) with that piece missing. Every file goes through ocean::write_file.
// Returns what went wrong as one line; refuses a `work` that is the chapter's own folder.
std::optional<std::string> prepare(const Exercise& exercise, const fs::path& work,
                                   const fs::path& source_root);

// `source` with the body of the function whose first line is `signature` replaced by `stub` (the
// body ends at the first line that is "}" alone); nothing when no line is `signature`.
std::optional<std::string> replace_body(const std::string& source, const std::string& signature,
                                        const std::string& stub);

}  // namespace exercises
