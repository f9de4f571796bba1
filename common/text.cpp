#include "common/text.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ocean {

std::string trim(const std::string& text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    const auto last = text.find_last_not_of(" \t\r\n");
    return text.substr(first, last - first + 1);
}

std::string lowercase(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream stream(text);
    while (std::getline(stream, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.emplace_back();
    return parts;
}

std::string join(const std::vector<std::string>& parts, const std::string& separator) {
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? separator : "") + parts[i];
    return out;
}

std::string pad_right(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

std::string ellipsize(const std::string& text, std::size_t max_chars) {
    std::string shown;
    for (char c : text) shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    return shown.size() <= max_chars ? shown : shown.substr(0, max_chars) + "...";
}

std::string format_number(double value) {
    char buffer[64];
    for (int digits = 6; digits <= 17; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
        if (static_cast<float>(std::strtod(buffer, nullptr)) == static_cast<float>(value)) break;
    }
    return buffer;
}

std::string format_double(double value) {
    char buffer[64];
    for (int digits = 6; digits <= 17; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    return buffer;
}

std::optional<std::string> read_text_file(const std::string& path, std::string* text, std::size_t max_bytes) {
    std::error_code missing;
    const auto status = std::filesystem::status(path, missing);
    if (missing) return "'" + path + "': " + missing.message();
    if (std::filesystem::is_directory(status)) return "'" + path + "': is a directory";
    if (!std::filesystem::is_regular_file(status))
        return "'" + path + "': not a regular file (a pipe or a device is not read)";
    if (std::filesystem::file_size(path, missing) > max_bytes)
        return "'" + path + "': larger than " + std::to_string(max_bytes / 1024) + " KiB";
    std::ifstream file(path, std::ios::binary);
    if (!file) return "'" + path + "': " + std::strerror(errno);
    // Read at most one byte past the limit: a file that grows while it is read is still bounded.
    std::string content(max_bytes + 1, '\0');
    file.read(content.data(), std::streamsize(content.size()));
    content.resize(std::size_t(file.gcount()));
    if (content.size() > max_bytes)
        return "'" + path + "': larger than " + std::to_string(max_bytes / 1024) + " KiB";
    *text = std::move(content);
    return std::nullopt;
}

}  // namespace ocean
