// Running what a learner wrote without trusting it: no shell (an argument vector, so no quote in a
// path is ever a command), a process group of its own killed whole at a time limit, a cap on the
// size of the files it writes, and nothing left running when the tool itself is stopped.
#pragma once

#include "common/text.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace exercises {

// How a child process ended.
struct Ending {
    enum Kind { Exited, Signalled, TimedOut } kind = Exited;
    int code = 0;  // the exit status (Exited) or the signal (Signalled)
};

// Runs the program argv[0] (a path: no PATH search) with `argv`, stdin from /dev/null, stdout and
// stderr into the two files (one file when they are the same path). Its process group is killed
// after `seconds`; a file it writes may not grow past `max_file_bytes` (past it, SIGXFSZ ends it).
// Throws ocean::Error when it cannot start.
Ending run_program(const std::vector<std::string>& argv, const std::filesystem::path& stdout_file,
                   const std::filesystem::path& stderr_file, double seconds, std::uint64_t max_file_bytes);

// Runs `task` in a forked child, killed after `seconds`, and returns the text it returned (sent
// back through a pipe) with how the child ended: the text is whole only when the ending is
// Exited with code 0. When the task throws, this throws ocean::Error with its message. Call it
// before this process makes a GL context: a context does not survive fork.
struct ChildResult {
    Ending ending;
    std::string text;
};
ChildResult run_in_child(const std::function<std::string()>& task, double seconds);

// "WHAT ran longer than 5 s and was stopped: an endless loop?"
inline std::string time_limit_verdict(const std::string& what, double seconds) {
    return what + " ran longer than " + ocean::format_number(seconds) + " s and was stopped: an endless loop?";
}
// "signal 6 (Aborted)"
std::string signal_name(int signal);

}  // namespace exercises
