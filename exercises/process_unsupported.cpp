// exercises/process.hpp where there is no fork, process group or rlimit (Windows): every call says
// so in one line, and the tool (./ocean check) stops there. The shaders' exercises still run in the
// step itself (./ocean exercise); only the checks, which run a learner's code in a limited child
// process, need Linux or macOS.
#include "exercises/process.hpp"

#include "common/error.hpp"

namespace exercises {

namespace {
[[noreturn]] void not_on_this_platform() {
    throw ocean::Error("checking an exercise runs it in a limited child process, which this platform "
                       "does not offer here (./ocean check runs on Linux and macOS)");
}
}  // namespace

Ending run_program(const std::vector<std::string>&, const std::filesystem::path&, const std::filesystem::path&,
                   double, std::uint64_t) {
    not_on_this_platform();
}

ChildResult run_in_child(const std::function<std::string()>&, double) { not_on_this_platform(); }

std::string signal_name(int signal) { return "signal " + std::to_string(signal); }

}  // namespace exercises
