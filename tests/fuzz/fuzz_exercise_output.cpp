// libFuzzer target: the reading of a learner's check program's output (exercises/program_output.hpp).
// The first two bytes choose how many cases (0-15) and values a case (0-7) are expected, the rest is
// the output. It must return the numbers or a one-line verdict, never crash or hang; numbers it
// returns are exactly the cases and values expected, every one finite.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "exercises/program_output.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const std::size_t cases = data[0] % 16, values = data[1] % 8;
    const std::string_view output(reinterpret_cast<const char*>(data + 2), size - 2);
    const auto parsed = exercises::parse_program_output(output, cases, values);
    if (const auto* verdict = std::get_if<std::string>(&parsed)) {
        if (verdict->empty() || verdict->find('\n') != std::string::npos || verdict->size() > 300)
            std::abort();
        return 0;
    }
    const exercises::CaseValues& table = std::get<exercises::CaseValues>(parsed);
    if (table.size() != cases) std::abort();
    for (const auto& row : table) {
        if (row.size() != values) std::abort();
        for (double v : row)
            if (!std::isfinite(v)) std::abort();
    }
    return 0;
}
