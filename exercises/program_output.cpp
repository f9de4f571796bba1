#include "exercises/program_output.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "common/text.hpp"

namespace exercises {

namespace {

std::vector<std::string_view> split_tokens(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t start = 0;
    while (start < line.size()) {
        const std::size_t end = std::min(line.find_first_of(" \t", start), line.size());
        if (end > start) tokens.push_back(line.substr(start, end - start));
        start = end + 1;
    }
    return tokens;
}

std::string shown(std::string_view text) { return "'" + ocean::ellipsize(std::string(text), 40) + "'"; }

// The token as a double, or why it is not one. strtod alone would skip leading white space (a
// vertical tab) and stop at the first character it cannot read ('2abc' is 2): both are refused.
std::variant<double, std::string> read_number(std::string_view token, const std::string& where) {
    const std::string text(token);  // strtod needs the terminating NUL
    char* end = nullptr;
    const double value =
        std::isspace(static_cast<unsigned char>(text[0])) ? 0 : std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) return where + ": " + shown(token) + " is not a number";
    if (std::isnan(value)) return where + " is not a number: " + ocean::ellipsize(text, 40);
    if (std::isinf(value)) return where + " is infinite: " + ocean::ellipsize(text, 40);
    return value;
}

}  // namespace

std::variant<CaseValues, std::string> parse_program_output(std::string_view output, std::size_t cases,
                                                           std::size_t values) {
    CaseValues table;
    std::size_t start = 0;
    while (start < output.size()) {
        const std::size_t newline = output.find('\n', start);
        const std::string_view line =
            output.substr(start, newline == std::string_view::npos ? newline : newline - start);
        start = newline == std::string_view::npos ? output.size() : newline + 1;
        if (table.size() == cases)
            return "the program printed a line after its " + std::to_string(cases) + " cases: " + shown(line);
        const std::string where = "case " + std::to_string(table.size());
        const std::vector<std::string_view> tokens = split_tokens(line);
        if (tokens.size() != values)
            return where + " has " + std::to_string(tokens.size()) + " values, not " + std::to_string(values);
        std::vector<double>& row = table.emplace_back();
        for (std::size_t v = 0; v < values; ++v) {
            const auto number = read_number(tokens[v], where + ", value " + std::to_string(v));
            if (const auto* problem = std::get_if<std::string>(&number)) return *problem;
            row.push_back(std::get<double>(number));
        }
    }
    if (table.size() < cases)
        return "the program printed " + std::to_string(table.size()) + " lines, not " +
               std::to_string(cases) + " (one a case)";
    return table;
}

}  // namespace exercises
