// libFuzzer target: the exercise tool's command line (exercises/arguments.hpp), on arbitrary argument
// lists (the input is split at NUL bytes into arguments). It must return a command or a one-line
// error, never crash or hang; a command it accepts names an exercise that exists, with N spelt as
// the number it read (./ocean names the work folder after that text).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "exercises/arguments.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::vector<exercises::ExerciseId> known{
        {"step01_sine2d", 1}, {"step01_sine2d", 2}, {"step05_fft", 9}, {"step07_buoyancy", 2}};
    std::vector<std::string> args(1);
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0)
            args.emplace_back();
        else
            args.back() += char(data[i]);
    }
    const auto parsed = exercises::parse_command(args, known);
    if (const auto* error = std::get_if<std::string>(&parsed)) {
        if (error->empty() || error->find('\n') != std::string::npos || error->size() > 400) std::abort();
        return 0;
    }
    const exercises::Command& c = std::get<exercises::Command>(parsed);
    if (c.verb == exercises::Verb::List) {
        if (args.size() != 1) std::abort();
        return 0;
    }
    const bool exists = std::any_of(known.begin(), known.end(), [&](const exercises::ExerciseId& id) {
        return id.step == c.exercise.step && id.number == c.exercise.number;
    });
    if (!exists || args[1] != c.exercise.step || args[2] != std::to_string(c.exercise.number)) std::abort();
    const bool takes_work = c.verb == exercises::Verb::Prepare || c.verb == exercises::Verb::Check;
    if (takes_work && (c.work.empty() || c.work != args[3])) std::abort();
    return 0;
}
