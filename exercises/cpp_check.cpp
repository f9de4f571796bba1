// How a C++ exercise is checked: the learner's file compiled with the check's small program by the
// compiler that built this tool, that program run under a time limit, and what it prints read
// strictly (program_output.hpp) and held to the chapter's own function. Neither runs through a
// shell: the paths are arguments, never parts of a command line.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <optional>
#include <sstream>

#include "common/error.hpp"
#include "common/file_output.hpp"
#include "common/text.hpp"
#include "exercises/exercise.hpp"
#include "exercises/limits.hpp"
#include "exercises/process.hpp"
#include "exercises/program_output.hpp"

namespace exercises {

namespace {

// The compiler's first error line, for the verdict (the whole log is in the work folder).
std::string first_error(const fs::path& log) {
    std::string text;
    if (ocean::read_text_file(log.string(), &text, kCompileOutputBytes)) return "";
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.find("error") != std::string::npos) return line;
    return "";
}

// Why the check's program did not finish, or nothing when it exited 0.
std::optional<std::string> did_not_finish(const Ending& ending, const std::string& file) {
    switch (ending.kind) {
        case Ending::TimedOut:
            return time_limit_verdict(file, kProgramSeconds);
        case Ending::Signalled:
            if (ending.code == SIGXFSZ)
                return file + " printed more than " + std::to_string(kProgramOutputBytes >> 10) +
                       " KiB and was stopped: does it print forever?";
            return file + " crashed: " + signal_name(ending.code);
        case Ending::Exited:
            if (ending.code == 0) return std::nullopt;
            return "the check's program exited with status " + std::to_string(ending.code) +
                   " (an exit() in " + file + "?)";
    }
    return std::nullopt;
}

}  // namespace

Verdict check_cpp(const fs::path& work, const std::string& file, const std::string& driver, int cases,
                  const CaseReference& reference, double tolerance) {
    const fs::path source = work / "check_driver.cpp", exe = work / "check_driver",
                   log = work / "check_compile.log", output = work / "check_output.txt",
                   errors = work / "check_errors.txt";
    if (auto error = ocean::write_file(source, driver)) throw ocean::Error(*error);
    const Ending compiled = run_program({OCEAN_CXX_COMPILER, "-std=c++17", "-O1", "-I", OCEAN_SOURCE_DIR,
                                         source.string(), (work / file).string(), "-o", exe.string()},
                                        log, log, kCompileSeconds, kCompileOutputBytes);
    if (compiled.kind == Ending::TimedOut)
        return {false, time_limit_verdict("the compiler", kCompileSeconds), false};
    if (compiled.kind != Ending::Exited || compiled.code != 0)
        return {false,
                file + " does not compile: " + first_error(log) + " (all of it: " + log.string() + ")"};

    const Ending ran = run_program({exe.string(), std::to_string(cases)}, output, errors, kProgramSeconds,
                                   kProgramOutputBytes);
    if (auto problem = did_not_finish(ran, file)) return {false, *problem, false};
    std::string printed;
    if (auto error = ocean::read_text_file(output.string(), &printed, kProgramOutputBytes))
        throw ocean::Error(*error);

    double scale = 0;
    std::vector<std::vector<double>> expected;
    for (int c = 0; c < cases; ++c) {
        expected.push_back(reference(c));
        for (double v : expected.back()) scale = std::max(scale, std::abs(v));
    }
    const auto parsed = parse_program_output(printed, std::size_t(cases), expected.front().size());
    if (const auto* problem = std::get_if<std::string>(&parsed)) return {false, *problem, false};
    const CaseValues& got = std::get<CaseValues>(parsed);
    double worst = -1;
    std::size_t worst_case = 0, worst_value = 0;
    for (std::size_t c = 0; c < got.size(); ++c)
        for (std::size_t i = 0; i < got[c].size(); ++i) {
            const double error = std::abs(got[c][i] - expected[c][i]);
            if (error > worst) worst = error, worst_case = c, worst_value = i;
        }
    std::ostringstream detail;
    detail << "worst difference " << worst << " (" << worst / std::max(scale, 1e-30)
           << " of the largest value) at case " << worst_case << ", value " << worst_value << ": got "
           << got[worst_case][worst_value] << ", expected " << expected[worst_case][worst_value]
           << "; tolerance " << tolerance << " of the largest, over " << cases << " cases";
    return {worst <= tolerance * scale, detail.str()};
}

}  // namespace exercises
