// Writing a file so that a failed write is never taken for a good one. The bytes go to a temporary
// file beside the target; every write, and the close, is checked; only then is the temporary file
// renamed over the target. A full disk, a missing folder or a read-only one gives an error message
// and leaves no half-written file behind (and an older file of that name as it was).
// Every file the programs write goes through write_file: encode into memory first (a PNG, a PFM,
// text in an ostringstream), then write it whole.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace ocean {

// Writes `bytes` to `path`; on failure returns "cannot write 'PATH': REASON" ("cannot write WHAT
// 'PATH': REASON" when `what` names the kind of file, e.g. "preset") and removes what it wrote.
// A new file gets the usual permissions (0666 less the umask), a replaced one keeps its own, and a
// symbolic link is followed (the file it points to is replaced, the link stays). A target that
// exists and is not a regular file (/dev/null, /dev/full, a FIFO) is written in place: a device
// cannot be replaced by renaming.
std::optional<std::string> write_file(const std::filesystem::path& path, std::string_view bytes,
                                      std::string_view what = {});

}  // namespace ocean
