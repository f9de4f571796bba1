// libFuzzer target: the parameter registry's preset parser and --set, on arbitrary bytes.
// Whatever the input, they must return (an error or not), never crash, hang or leave a value
// outside its declared range.
#include "common/params.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ocean::ParamRegistry params;
    float amplitude = 1;
    int count = 3, mode = 0;
    bool flag = false;
    glm::vec3 colour{0.5f};
    std::string text;
    params.add_float("amplitude", &amplitude, 0, 10, "");
    params.add_int("wave_count", &count, 1, 64, "");
    params.add_choice("mode", &mode, {"orbit", "fly"}, "");
    params.add_bool("wireframe", &flag, "");
    params.add_color("colour", &colour, "");
    params.add_text("sky_image", &text, "");
    const std::string input(reinterpret_cast<const char*>(data), size);
    params.apply_preset_text(input, "fuzz");
    params.set_assignment(input);
    // The invariants every accepted value keeps.
    if (!(amplitude >= 0 && amplitude <= 10) || count < 1 || count > 64 || mode < 0 || mode > 1) std::abort();
    for (int c = 0; c < 3; ++c)
        if (!(colour[c] >= 0 && colour[c] <= 1)) std::abort();
    if (text.size() > 1024 || text.find('#') != std::string::npos) std::abort();
    // What a preset writes must read back.
    if (params.apply_preset_text(params.preset_text("round trip"), "round trip")) std::abort();
    return 0;
}
