// Previous/Next replaces the process (platform::replace_process: execv, or _execv on Windows): what the step printed before
// must reach a file or a pipe, where stdout is fully buffered and exec would drop the buffer.
#include "common/hand_over.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {

TEST(HandOver, OutputReachesAFileBeforeTheNextStepStarts) {
    const std::string path = testing::TempDir() + "hand_over_output.txt";
    std::remove(path.c_str());
    // A child (gtest forks it) writes through every stream, stdout into a file, then hands over to
    // /bin/true, as a step hands over to the next.
    EXPECT_EXIT(
        {
            if (std::freopen(path.c_str(), "w", stdout) == nullptr) std::exit(4);
            std::cout << "a line through std::cout\n";
            std::printf("a line through printf\n");
            std::clog << "a line through std::clog\n";
            ocean::run_next_step(0, {"/bin/true"});
            std::exit(3);  // the exec failed
        },
        testing::ExitedWithCode(0), "");
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("a line through std::cout"), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("a line through printf"), std::string::npos) << text.str();
    std::remove(path.c_str());
}

}  // namespace
