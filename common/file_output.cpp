#include "common/file_output.hpp"

#include "common/platform.hpp"

#include <atomic>
#include <string>

namespace ocean {

namespace fs = std::filesystem;

namespace {

// Writes, then closes the file whatever happened; the first error wins. The close reports what a
// file system could only say late (a full disk over NFS, a quota).
std::error_code write_and_close(int fd, std::string_view bytes) {
    std::error_code error = platform::write_all(fd, bytes);
    const std::error_code closed = platform::close_file(fd);
    return error ? error : closed;
}

// A device or a FIFO (/dev/null, /dev/full): written where it is, since renaming a regular file
// over it would replace the device itself.
std::error_code write_in_place(const fs::path& target, std::string_view bytes) {
    const platform::OpenedFile file = platform::open_existing_for_writing(target);
    return file.error ? file.error : write_and_close(file.descriptor, bytes);
}

// A new file beside `target`, so that the rename cannot cross file systems: .NAME.partial-PID-N,
// made only if no file has that name (never another process's).
platform::OpenedFile create_temporary(const fs::path& target, fs::path* name) {
    static std::atomic<unsigned> counter{0};
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    // A name near the 255-byte limit would not fit with the suffix.
    const std::string stem = "." + target.filename().string().substr(0, 160) + ".partial-" +
                             std::to_string(platform::process_id());
    for (int attempt = 0;; ++attempt) {  // a crashed run may have left the same name behind
        *name = folder / (stem + "-" + std::to_string(counter++));
        platform::OpenedFile file = platform::create_new_file(*name);
        if (!file.error || file.error != std::errc::file_exists || attempt == 100) return file;
    }
}

// The bytes into a temporary file, renamed over `target` only once every byte is written and the
// file closed. `keep`: the permissions of the file it replaces (perms::unknown for a new file).
std::error_code replace_by_rename(const fs::path& target, std::string_view bytes, fs::perms keep) {
    fs::path temporary;
    const platform::OpenedFile file = create_temporary(target, &temporary);
    if (file.error) return file.error;
    std::error_code error = write_and_close(file.descriptor, bytes);
    std::error_code ignored;
    if (!error && keep != fs::perms::unknown) fs::permissions(temporary, keep, ignored);  // best effort, as cp does
    if (!error) fs::rename(temporary, target, error);  // over an older file, on Windows too
    if (error) fs::remove(temporary, ignored);
    return error;
}

}  // namespace

std::optional<std::string> write_file(const fs::path& path, std::string_view bytes, std::string_view what) {
    std::error_code ignored;
    const fs::file_status existing = fs::status(path, ignored);  // follows symbolic links
    const bool exists = fs::exists(existing);
    fs::path target = path;
    if (exists && fs::is_symlink(fs::symlink_status(path, ignored))) {
        // Replace the file the link names and keep the link (a preset linked from elsewhere).
        const fs::path resolved = fs::canonical(path, ignored);
        if (!resolved.empty()) target = resolved;
    }
    const bool special = exists && !fs::is_regular_file(existing) && !fs::is_directory(existing);
    const fs::perms keep = fs::is_regular_file(existing) ? existing.permissions() : fs::perms::unknown;
    const std::error_code error = special ? write_in_place(target, bytes) : replace_by_rename(target, bytes, keep);
    if (!error) return std::nullopt;
    std::string message = "cannot write ";
    if (!what.empty()) message.append(what).append(" ");
    return message + "'" + path.string() + "': " + error.message();
}

}  // namespace ocean
