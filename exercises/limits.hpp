// The limits the checker puts on what a learner wrote, so that an endless loop or a program that
// prints for ever ends in a verdict instead of a hung ./ocean check or a full disk. Each is many
// times what the chapters' own solutions need, measured on llvmpipe with 2 cores.
#pragma once

#include <cstdint>
#include <cstdlib>

namespace exercises {

// A GLSL exercise's whole check, in a child process: GL context, shader build, dispatches, read
// back. The slowest real one (step05 5 and 6: the chapter's whole FFT at N = 64 to 512) takes 0.7 s.
constexpr double kGpuCheckSeconds = 30;
// The limit a check runs under: kGpuCheckSeconds, or shorter where OCEAN_EXERCISE_GPU_SECONDS asks
// (1 to 30 s; anything else is ignored): the endless loop's test waits the limit out, and 5 s
// prove the same as 30.
inline double gpu_check_seconds() {
    const char* asked = std::getenv("OCEAN_EXERCISE_GPU_SECONDS");
    if (asked == nullptr) return kGpuCheckSeconds;
    char* end = nullptr;
    const double seconds = std::strtod(asked, &end);
    return end != asked && *end == '\0' && seconds >= 1 && seconds <= kGpuCheckSeconds ? seconds : kGpuCheckSeconds;
}

// A C++ exercise: the compile of the learner's file with the check's program (3 s at most), then
// that program (0.06 s at most: step05 8, the variance of 200 seas).
constexpr double kCompileSeconds = 120;
constexpr double kProgramSeconds = 5;

// What the check's program may write (41 KiB at most: step06 7's 200 lines of 13 numbers), and
// what the compiler may (the program, 50 KiB, and its messages).
constexpr std::uint64_t kProgramOutputBytes = 1 << 20;
constexpr std::uint64_t kCompileOutputBytes = std::uint64_t(256) << 20;

}  // namespace exercises
