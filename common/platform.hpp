// The few calls whose form differs between Linux, macOS and Windows, in one place: everything
// else in the repository is standard C++ (std::filesystem, <thread>, <chrono>) and GLFW.
// docs/portability.md lists each call, its three forms, and what was checked where.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace ocean::platform {

// The running program's own file (Linux: /proc/self/exe; macOS: _NSGetExecutablePath; Windows:
// GetModuleFileNameW); empty where it cannot be found.
std::filesystem::path executable_path();
// What an executable's name ends with: ".exe" on Windows, nothing elsewhere.
extern const char* const kExecutableSuffix;

// This process's id (getpid; Windows: _getpid), for names no other process picks.
int process_id();

// Replaces this process with `command` (its first word, a path, is the program): execv, or on
// Windows _execv, which starts the program and ends this process. Returns only on failure, with
// its reason.
std::error_code replace_process(const std::vector<std::string>& command);

// The memory this process holds in RAM, in KiB (Linux: /proc/self/statm; macOS: task_info;
// Windows: GetProcessMemoryInfo); nullopt where it cannot be read.
std::optional<long> resident_kilobytes();

// Files written whole (common/file_output.cpp): a descriptor opened for writing, the bytes, the
// close. Each returns what failed (EFBIG past a size limit, ENOSPC on a full disk).
struct OpenedFile {
    int descriptor = -1;
    std::error_code error;
};
// An existing file (a device, a FIFO) opened to be written where it is.
OpenedFile open_existing_for_writing(const std::filesystem::path& path);
// A new file, failing with "file exists" where one is there (O_EXCL): never another process's.
OpenedFile create_new_file(const std::filesystem::path& path);
std::error_code write_all(int descriptor, std::string_view bytes);
std::error_code close_file(int descriptor);

// Sets (or, with nullopt, removes) an environment variable: setenv/unsetenv, or _putenv_s.
void set_environment(const std::string& name, const std::optional<std::string>& value);

}  // namespace ocean::platform
