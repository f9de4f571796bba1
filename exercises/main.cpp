// exercise list | exercise prepare|check STEP N WORK_DIR | exercise hint|flags STEP N
// The exercises behind ./ocean exercise and ./ocean check (exercises/README.md).
//   list:    every exercise, one a line: STEP N  title (file), the title after "derived: " for
//            a variant no page answers.
//   prepare: copies the step's shaders into WORK_DIR and empties one function there (its body
//            becomes a TODO that compiles), so the step runs on the learner's copy
//            (--shader-dir, hot reload) with that piece missing; a derived exercise's function in
//            the same file is emptied too, so no copy shows its answer.
//   check:   holds the learner's function to the chapter's CPU reference; prints pass, or fail with
//            a hint. Exit 0 on pass, 1 on fail.
//   hint:    the formula the task leaves out (the second hint: try first, then read it).
//   flags:   the step's flags that run the code the exercise edits, one a line (./ocean passes them).
// Any other outcome is one line on stderr, "exercise: error: ...": exit 2 for the command line
// (and a check before its prepare), 1 for a failure of the tool itself (a file it cannot write).
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "common/context.hpp"
#include "exercises/arguments.hpp"
#include "exercises/exercise.hpp"
#include "exercises/limits.hpp"
#include "exercises/prepare.hpp"
#include "exercises/process.hpp"

namespace {

using namespace exercises;

int error_line(int status, std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' ');  // one line, whatever the message held
    std::fprintf(stderr, "exercise: error: %s\n", message.c_str());
    return status;
}

// A GLSL exercise's check runs in a child process with its own GL context, so that a learner's
// endless loop ends at the limit (a GPU runs it for ever; llvmpipe stops a shader's loops after
// 65535 turns, which can still take many minutes). Its verdict comes back as text: 'P' or 'F', 'H'
// when the hint applies, then the detail.
Verdict check_on_gpu(const Exercise& e, const fs::path& work) {
    const ChildResult result = run_in_child(
        [&] {
            const auto context = ocean::Context::create({true, 16, 16, "exercise check"});
            const Verdict verdict = e.check(work);
            return std::string(verdict.pass ? "P" : "F") + (verdict.formula_hint ? "H" : "-") +
                   verdict.detail;
        },
        gpu_check_seconds());
    const Ending& ending = result.ending;
    if (ending.kind == Ending::TimedOut)
        return {false, time_limit_verdict("the check of your shader", gpu_check_seconds()), false};
    if (ending.kind == Ending::Signalled)
        return {false, "the check of your shader crashed: " + signal_name(ending.code), false};
    if (ending.code != 0 || result.text.size() < 2)
        return {false, "the check stopped with status " + std::to_string(ending.code) + " before its verdict",
                false};
    return {result.text[0] == 'P', result.text.substr(2), result.text[1] == 'H'};
}

int check(const Exercise& e, const fs::path& work) {
    std::error_code error;
    if (!fs::is_regular_file(work / e.file, error))
        return error_line(2, (work / e.file).string() + " does not exist: start with ./ocean exercise " +
                                 e.step + " " + std::to_string(e.number));
    const Verdict verdict = is_cpp(e.file) ? e.check(work) : check_on_gpu(e, work);
    std::printf("%s: exercise %d of %s (%s): %s\n", verdict.pass ? "pass" : "fail", e.number, e.step.c_str(),
                e.title.c_str(), verdict.detail.c_str());
    if (!verdict.pass && verdict.formula_hint) std::printf("hint: %s\n", e.hint.c_str());
    return verdict.pass ? 0 : 1;
}

int run(const Command& command, const std::vector<Exercise>& every) {
    if (command.verb == Verb::List) {
        for (const Exercise& e : every)
            std::printf("%s %d  %s%s (%s)\n", e.step.c_str(), e.number, e.derived ? "derived: " : "", e.title.c_str(),
                        e.file.c_str());
        return 0;
    }
    const Exercise& e = *std::find_if(every.begin(), every.end(), [&](const Exercise& x) {
        return x.step == command.exercise.step && x.number == command.exercise.number;
    });  // parse_command took only an exercise of `every`
    const fs::path work = command.work;
    switch (command.verb) {
        case Verb::Hint:
            std::printf("exercise %d of %s: %s\n%s\n", e.number, e.step.c_str(), e.title.c_str(),
                        e.formula.c_str());
            return 0;
        case Verb::Flags:
            for (const std::string& flag : e.run_flags) std::printf("%s\n", flag.c_str());
            return 0;
        case Verb::Prepare:
            if (auto problem = prepare(e, work, OCEAN_SOURCE_DIR)) return error_line(1, *problem);
            std::printf(
                "exercise %d of %s: %s\n%s\nedit %s %s\nstuck? ./ocean exercise %s %d --hint prints the "
                "formula\n",
                e.number, e.step.c_str(), e.title.c_str(), e.task.c_str(), (work / e.file).string().c_str(),
                is_cpp(e.file) ? "(C++: ./ocean check holds it to the chapter's own)"
                               : "(the step reloads it when you save)",
                e.step.c_str(), e.number);
            return 0;
        case Verb::Check:
            return check(e, work);
        case Verb::List:
            break;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::vector<Exercise> every = all();
        std::vector<ExerciseId> known;
        for (const Exercise& e : every) known.push_back({e.step, e.number});
        const auto parsed = parse_command(std::vector<std::string>(argv + 1, argv + argc), known);
        if (const auto* problem = std::get_if<std::string>(&parsed)) return error_line(2, *problem);
        return run(std::get<Command>(parsed), every);
    } catch (const std::exception& error) {
        return error_line(1, error.what());
    }
}
