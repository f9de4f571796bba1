// What a C++ exercise's check program printed, read strictly: one line a case, each exactly the
// expected count of numbers. Anything else is a one-line verdict that says what the program printed
// wrong, rather than a loose parse that turns '2abc' into 2 or a missing value into the next line's.
// Pure (no files), so that the unit tests and a fuzzer can drive it.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace exercises {

using CaseValues = std::vector<std::vector<double>>;

// `output` must be `cases` lines (the last one's newline may be missing), each of `values` numbers
// separated by spaces or tabs; a number is a whole token that strtod reads to its end, and finite.
// Returns the numbers, case by case, or the first thing wrong (cases and values counted from 0).
std::variant<CaseValues, std::string> parse_program_output(std::string_view output, std::size_t cases,
                                                           std::size_t values);

}  // namespace exercises
