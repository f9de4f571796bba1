// common/platform.hpp's calls, one #if per form. What has no form on a platform says so rather
// than pretending (resident_kilobytes gives nullopt).
#include "common/platform.hpp"

#include <cerrno>
#include <fcntl.h>
#include <algorithm>
#include <cstdint>
#include <fstream>

#if defined(_WIN32)
#define WIN32_LEAN_AND_MEAN
#ifndef NOMINMAX  // libstdc++ for mingw defines it already
#define NOMINMAX
#endif
#include <windows.h>
#include <psapi.h>  // GetProcessMemoryInfo (kernel32's K32 form: no extra library)
#include <io.h>
#include <process.h>
#include <sys/stat.h>
#else
#include <unistd.h>
#endif
#if defined(__APPLE__)
#include <mach-o/dyld.h>  // _NSGetExecutablePath
#include <mach/mach.h>    // task_info
#endif

namespace ocean::platform {

namespace fs = std::filesystem;

namespace {
std::error_code last_errno() { return {errno, std::generic_category()}; }
}  // namespace

#if defined(_WIN32)
const char* const kExecutableSuffix = ".exe";
#else
const char* const kExecutableSuffix = "";
#endif

fs::path executable_path() {
#if defined(_WIN32)
    std::wstring buffer(MAX_PATH, L'\0');
    for (;;) {
        const DWORD length = GetModuleFileNameW(nullptr, buffer.data(), DWORD(buffer.size()));
        if (length == 0) return {};
        if (length < buffer.size()) return fs::path(buffer.substr(0, length));
        buffer.resize(buffer.size() * 2);  // truncated: a longer path
    }
#elif defined(__APPLE__)
    std::uint32_t size = 0;
    _NSGetExecutablePath(nullptr, &size);  // asks for the size it needs
    std::string buffer(size, '\0');
    if (_NSGetExecutablePath(buffer.data(), &size) != 0) return {};
    std::error_code ignored;
    const fs::path resolved = fs::canonical(buffer.c_str(), ignored);  // it may name a link
    return resolved.empty() ? fs::path(buffer.c_str()) : resolved;
#else
    std::error_code error;
    fs::path self = fs::read_symlink("/proc/self/exe", error);
    return error ? fs::path() : self;
#endif
}

int process_id() {
#if defined(_WIN32)
    return _getpid();
#else
    return int(::getpid());
#endif
}

std::error_code replace_process(const std::vector<std::string>& command) {
    if (command.empty()) return std::make_error_code(std::errc::invalid_argument);
    std::vector<char*> argv;
    for (const auto& a : command) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
#if defined(_WIN32)
    _execv(argv[0], argv.data());  // starts the program, then ends this process
#else
    ::execv(argv[0], argv.data());
#endif
    return last_errno();
}

std::optional<long> resident_kilobytes() {
#if defined(_WIN32)
    PROCESS_MEMORY_COUNTERS counters{};
    if (!K32GetProcessMemoryInfo(GetCurrentProcess(), &counters, sizeof counters)) return std::nullopt;
    return long(counters.WorkingSetSize / 1024);
#elif defined(__APPLE__)
    mach_task_basic_info_data_t info{};
    mach_msg_type_number_t count = MACH_TASK_BASIC_INFO_COUNT;
    if (task_info(mach_task_self(), MACH_TASK_BASIC_INFO, reinterpret_cast<task_info_t>(&info), &count) != KERN_SUCCESS)
        return std::nullopt;
    return long(info.resident_size / 1024);
#else
    // /proc/self/statm: size, resident, ... in pages.
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    if (!(statm >> pages >> resident)) return std::nullopt;
    return resident * (::sysconf(_SC_PAGESIZE) / 1024);
#endif
}

OpenedFile open_existing_for_writing(const fs::path& path) {
#if defined(_WIN32)
    const int fd = ::_wopen(path.c_str(), _O_WRONLY | _O_BINARY | _O_NOINHERIT);
#else
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
#endif
    return fd < 0 ? OpenedFile{-1, last_errno()} : OpenedFile{fd, {}};
}

OpenedFile create_new_file(const fs::path& path) {
#if defined(_WIN32)
    const int fd = ::_wopen(path.c_str(), _O_WRONLY | _O_BINARY | _O_CREAT | _O_EXCL | _O_NOINHERIT, _S_IREAD | _S_IWRITE);
#else
    // Mode 0666: the umask applies as to any new file.
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
#endif
    return fd < 0 ? OpenedFile{-1, last_errno()} : OpenedFile{fd, {}};
}

std::error_code write_all(int descriptor, std::string_view bytes) {
    for (std::size_t written = 0; written < bytes.size();) {
        const std::size_t left = bytes.size() - written;
#if defined(_WIN32)
        const int n = ::_write(descriptor, bytes.data() + written, unsigned(std::min<std::size_t>(left, 1u << 30)));
#else
        const ssize_t n = ::write(descriptor, bytes.data() + written, left);
#endif
        if (n > 0) written += std::size_t(n);
        else if (n == 0) return std::make_error_code(std::errc::io_error);  // no progress and no reason: never spin
        else if (errno != EINTR) return last_errno();
    }
    return {};
}

std::error_code close_file(int descriptor) {
#if defined(_WIN32)
    return ::_close(descriptor) == 0 ? std::error_code() : last_errno();
#else
    return ::close(descriptor) == 0 ? std::error_code() : last_errno();
#endif
}

void set_environment(const std::string& name, const std::optional<std::string>& value) {
#if defined(_WIN32)
    ::_putenv_s(name.c_str(), value ? value->c_str() : "");  // "" removes it
#else
    if (value) ::setenv(name.c_str(), value->c_str(), 1);
    else ::unsetenv(name.c_str());
#endif
}

}  // namespace ocean::platform
