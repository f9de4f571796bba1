#include "exercises/arguments.hpp"

#include <algorithm>

#include "common/text.hpp"

namespace exercises {

const char* const kUsage =
    "usage: exercise list | exercise prepare|check STEP N WORK_DIR | exercise hint|flags STEP N";

namespace {

// Text the user typed, as a message may show it: one line, printable, cut short.
std::string quoted(const std::string& text) { return "'" + ocean::ellipsize(text, 40) + "'"; }

struct VerbShape {
    const char* name;
    Verb verb;
    std::size_t arguments;
    const char* what;
};
constexpr VerbShape kVerbs[] = {
    {"list", Verb::List, 0, "no arguments"},      {"prepare", Verb::Prepare, 3, "STEP N WORK_DIR"},
    {"check", Verb::Check, 3, "STEP N WORK_DIR"}, {"hint", Verb::Hint, 2, "STEP N"},
    {"flags", Verb::Flags, 2, "STEP N"},
};

// The steps that have exercises, each once, in the order `known` lists them.
std::vector<std::string> steps_of(const std::vector<ExerciseId>& known) {
    std::vector<std::string> steps;
    for (const ExerciseId& id : known)
        if (std::find(steps.begin(), steps.end(), id.step) == steps.end()) steps.push_back(id.step);
    return steps;
}

}  // namespace

std::optional<int> parse_exercise_number(std::string_view text) {
    if (text.empty() || text.size() > 3 || text[0] == '0') return std::nullopt;
    int number = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        number = 10 * number + (c - '0');
    }
    return number;
}

std::variant<Command, std::string> parse_command(const std::vector<std::string>& args,
                                                 const std::vector<ExerciseId>& known) {
    if (args.empty()) return std::string("no verb: ") + kUsage;
    const auto shape = std::find_if(std::begin(kVerbs), std::end(kVerbs),
                                    [&](const VerbShape& v) { return args[0] == v.name; });
    if (shape == std::end(kVerbs)) return "unknown verb " + quoted(args[0]) + ": " + kUsage;
    const std::size_t given = args.size() - 1;
    if (given != shape->arguments)
        return std::string(shape->name) + " takes " + shape->what + "; given " + std::to_string(given) +
               " argument" + (given == 1 ? "" : "s") + ": " + kUsage;
    Command command;
    command.verb = shape->verb;
    if (command.verb == Verb::List) return command;

    const std::string& step = args[1];
    const std::vector<std::string> steps = steps_of(known);
    if (std::find(steps.begin(), steps.end(), step) == steps.end())
        return "no step " + quoted(step) + " has exercises; these do: " + ocean::join(steps, ", ");
    const std::optional<int> number = parse_exercise_number(args[2]);
    std::vector<std::string> numbers;
    for (const ExerciseId& id : known)
        if (id.step == step) numbers.push_back(std::to_string(id.number));
    if (!number)
        return "N must be a whole number from 1 to 999, in digits without a leading zero, not " +
               quoted(args[2]) + " (" + step + " has " + ocean::join(numbers, ", ") + ")";
    const bool exists = std::any_of(known.begin(), known.end(), [&](const ExerciseId& id) {
        return id.step == step && id.number == *number;
    });
    if (!exists)
        return step + " has no exercise " + std::to_string(*number) + "; it has " +
               ocean::join(numbers, ", ");
    command.exercise = {step, *number};

    if (shape->arguments == 3) {
        command.work = args[3];
        if (command.work.empty())
            return "WORK_DIR is empty: give the folder of the learner's copy (./ocean gives "
                   "exercises/work/STEP-N)";
    }
    return command;
}

}  // namespace exercises
