// Small string helpers shared by the command line, the parameter registry and the shader loader.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ocean {

std::string trim(const std::string& text);
std::string lowercase(std::string text);
std::vector<std::string> split(const std::string& text, char separator);
std::string join(const std::vector<std::string>& parts, const std::string& separator);
std::string pad_right(const std::string& text, std::size_t width);
// Cuts long text (a user can pass a megabyte to --set) so messages stay one readable line.
std::string ellipsize(const std::string& text, std::size_t max_chars);
// Shortest decimal form (at least 6 digits) that reads back as the same float: parameters are
// floats, so 0.1f prints as "0.1", not "0.100000001".
std::string format_number(double value);
// The shortest text that reads back as the same double (format_number's reads back as the same float).
std::string format_double(double value);
// Reads a whole file; on failure returns "'path': reason".
// Reads a whole regular file of at most max_bytes. Anything else is refused with a message, not
// read: a FIFO or a device (/dev/urandom) would block or never end.
constexpr std::size_t kMaxTextFileBytes = 1 << 20;
std::optional<std::string> read_text_file(const std::string& path, std::string* text,
                                          std::size_t max_bytes = kMaxTextFileBytes);

}  // namespace ocean
