// The exercise tool's command line, read completely before anything runs: a verb, then STEP and N
// that must name an exercise that exists, then the work folder. Pure (no files, no GL), so that the
// unit tests and a fuzzer can drive it (tests/unit/test_exercise_input.cpp, tests/fuzz).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace exercises {

enum class Verb { List, Prepare, Check, Hint, Flags };

struct ExerciseId {
    std::string step;
    int number = 0;
};

struct Command {
    Verb verb = Verb::List;
    ExerciseId exercise;  // every verb but list
    std::string work;     // prepare and check: the folder of the learner's copy
};

extern const char* const kUsage;

// N as the tool takes it: 1 to 999 in digits alone, without a leading zero (./ocean names the work
// folder STEP-N after it, so one exercise has one spelling). A sign, a space, '2abc', '1e1' or
// '007' is no number.
std::optional<int> parse_exercise_number(std::string_view text);

// `args`: what follows the program's name; `known`: every exercise there is. Returns the command,
// or what is wrong with the arguments as one line (the caller prefixes "exercise: error: ").
std::variant<Command, std::string> parse_command(const std::vector<std::string>& args,
                                                 const std::vector<ExerciseId>& known);

}  // namespace exercises
