#include "common/hand_over.hpp"

#include "common/camera.hpp"
#include "common/cli.hpp"
#include "common/platform.hpp"
#include "common/text.hpp"

#if defined(__EMSCRIPTEN__)
#include <emscripten.h>
#endif

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace ocean {

namespace fs = std::filesystem;

std::string step_executable(const std::string& step) {
#if defined(__EMSCRIPTEN__)
    return step;  // a page: its name is the chapter's, and run_next_step opens STEP.html
#endif
    const fs::path self = platform::executable_path();
    if (self.empty()) return "";
    const fs::path candidate = self.parent_path().parent_path() / step / (step + platform::kExecutableSuffix);
    return fs::exists(candidate) ? candidate.string() : "";
}

std::vector<std::string> hand_over_command(const std::string& executable, double time, glm::ivec2 size,
                                         const ParamRegistry& params, bool split, bool paused) {
    std::vector<std::string> command = {executable, "--start-at", std::to_string(time), "--size",
                                        std::to_string(size.x) + "x" + std::to_string(size.y)};
    for (const auto& p : params.all())
        if (p->group() == kCameraGroup) {
            command.push_back("--carry");
            command.push_back(p->name() + "=" + p->value_text());
        }
    if (split) command.push_back("--split");
    if (paused) command.push_back("--paused");  // a paused moment stays paused in the next chapter
    return command;
}

#if defined(__EMSCRIPTEN__)
namespace {
// `text` with every byte but letters, digits and - _ . ~ written %XX, as an address's query needs.
std::string url_encoded(const std::string& text) {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (unsigned char c : text) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
            out += char(c);
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}
}  // namespace
#endif

int run_next_step(int status, const std::vector<std::string>& command) {
    if (command.empty()) return status;
    // The next step replaces the process without running its exit: what is still buffered (stdout to a
    // file or a pipe is fully buffered) would vanish. Flush the C++ streams, then C's.
    std::cout.flush();
    std::cerr.flush();
    std::clog.flush();
    std::fflush(nullptr);
#if defined(__EMSCRIPTEN__)
    // A page hands over by opening the next chapter's page; its address carries the arguments,
    // each as an `arg`, which the page passes to main in order (web/chapter.html.in).
    std::string address = command[0] + ".html";
    for (std::size_t i = 1; i < command.size(); ++i) address += (i == 1 ? "?arg=" : "&arg=") + url_encoded(command[i]);
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wdollar-in-identifier-extension"  // EM_ASM names its arguments $0, $1 ...
    EM_ASM({ window.location.href = UTF8ToString($0); }, address.c_str());
#pragma clang diagnostic pop
    return status;
#endif
    const std::error_code error = platform::replace_process(command);
    std::cerr << "error: cannot start " << command[0] << ": " << error.message() << std::endl;
    return kExitRuntimeError;
}

std::vector<std::string> repository_steps() { return split(OCEAN_STEP_LIST, ','); }

}  // namespace ocean
