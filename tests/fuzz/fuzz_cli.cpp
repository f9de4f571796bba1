// libFuzzer target: the command line parser, on arbitrary argument lists (the input is split at
// NUL bytes into arguments). It must return a result or a one-line error, never crash or hang,
// and every accepted value must be inside its stated limits.
#include "common/cli.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args(1);
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) args.emplace_back();
        else args.back() += char(data[i]);
    }
    const ocean::ParseResult r = ocean::parse_command_line(args);
    if (r.error) {
        if (r.error->find('\n') != std::string::npos || r.error->size() > 400) std::abort();
        return 0;
    }
    const ocean::Options& o = r.options;
    if (o.width < 1 || o.height < 1 || o.width > ocean::kMaxImageSide || o.height > ocean::kMaxImageSide) std::abort();
    if (o.frames < 0 || (o.start_time && !std::isfinite(*o.start_time)) || (o.fixed_dt && !(*o.fixed_dt >= 0)))
        std::abort();
    return 0;
}
