#include "common/file_output.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ocean {

namespace fs = std::filesystem;

namespace {

// Every byte to the open file `fd`: 0, or the errno of the write that failed (EFBIG past a file
// size limit, ENOSPC on a full disk, EDQUOT over a quota).
int write_all(int fd, std::string_view bytes) {
    for (std::size_t written = 0; written < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n > 0) written += std::size_t(n);
        else if (n == 0) return EIO;  // no progress and no reason: never spin on it
        else if (errno != EINTR) return errno;
    }
    return 0;
}

// Writes, then closes `fd` whatever happened; the first error wins. close() reports what a file
// system could only say late (a full disk over NFS, a quota).
int write_and_close(int fd, std::string_view bytes) {
    int error = write_all(fd, bytes);
    if (::close(fd) != 0 && error == 0) error = errno;
    return error;
}

// A device or a FIFO (/dev/null, /dev/full): written where it is, since renaming a regular file
// over it would replace the device itself.
int write_in_place(const fs::path& target, std::string_view bytes) {
    const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return errno;
    return write_and_close(fd, bytes);
}

// A new file beside `target`, so that the rename cannot cross file systems: .NAME.partial-PID-N.
// O_EXCL: never another process's file. Mode 0666: the umask applies as to any new file.
// Returns the descriptor, or -1 with errno set.
int create_temporary(const fs::path& target, std::string* name) {
    static std::atomic<unsigned> counter{0};
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    // A name near the 255-byte limit would not fit with the suffix.
    const std::string stem = "." + target.filename().string().substr(0, 160) + ".partial-" + std::to_string(::getpid());
    for (int attempt = 0;; ++attempt) {  // a crashed run may have left the same name behind
        *name = (folder / (stem + "-" + std::to_string(counter++))).string();
        const int fd = ::open(name->c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST || attempt == 100) return fd;
    }
}

// The bytes into a temporary file, renamed over `target` only once every byte is written and the
// file closed. `keep_mode`: the mode of the file it replaces.
int replace_by_rename(const fs::path& target, std::string_view bytes, const struct stat* keep_mode) {
    std::string temporary;
    const int fd = create_temporary(target, &temporary);
    if (fd < 0) return errno;
    if (keep_mode != nullptr) ::fchmod(fd, keep_mode->st_mode & 07777);  // best effort, as cp does
    int error = write_and_close(fd, bytes);
    if (error == 0 && ::rename(temporary.c_str(), target.c_str()) != 0) error = errno;
    if (error != 0) ::unlink(temporary.c_str());
    return error;
}

}  // namespace

std::optional<std::string> write_file(const fs::path& path, std::string_view bytes, std::string_view what) {
    struct stat existing {};
    const bool exists = ::stat(path.c_str(), &existing) == 0;  // follows symbolic links
    fs::path target = path;
    std::error_code ignored;
    if (exists && fs::is_symlink(fs::symlink_status(path, ignored))) {
        // Replace the file the link names and keep the link (a preset linked from elsewhere).
        const fs::path resolved = fs::canonical(path, ignored);
        if (!resolved.empty()) target = resolved;
    }
    const bool special = exists && !S_ISREG(existing.st_mode) && !S_ISDIR(existing.st_mode);
    const int error = special ? write_in_place(target, bytes)
                              : replace_by_rename(target, bytes, exists && S_ISREG(existing.st_mode) ? &existing : nullptr);
    if (error == 0) return std::nullopt;
    std::string message = "cannot write ";
    if (!what.empty()) message.append(what).append(" ");
    return message + "'" + path.string() + "': " + std::strerror(error);
}

}  // namespace ocean
