// wake_check WITHOUT WITH: the wake as a camera following the boat records it (the boat at the
// picture's centre: the camera looks at it), the water behind it below the centre, ahead of it
// above. WITHOUT and WITH are the same frame with the wake off and on (wake_behind.sh draws them);
// how much the wake changes the picture (RMSE of the luma, 0..255) in a band behind the boat and in
// one ahead of it. A boat leaves its wake behind: it must change the band behind at least three
// times as much as the band ahead, and by a visible amount (above 2). Like step06's picture checks
// it reads only the pictures (tests/picture_camera.hpp), no shader.
// Prints the figures; exit 0 when they hold, 1 otherwise (and 2 on bad input).
#include "tests/picture_camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

using ocean_test::display_luma;

int wake(const std::string& without_path, const std::string& with_path) {
    const ocean::Image without = ocean_test::load_picture(without_path), with = ocean_test::load_picture(with_path);
    if (without.width != with.width || without.height != with.height) throw std::runtime_error("wake: the pictures differ in size");
    const auto change = [&](double from, double to) {  // rows from..to of the height, the middle 80 % of the width
        double sum = 0;
        long count = 0;
        for (int y = int(from * with.height); y < int(to * with.height); ++y)
            for (int x = with.width / 10; x < with.width - with.width / 10; ++x, ++count) {
                const double d = display_luma(with, x, y) - display_luma(without, x, y);
                sum += d * d;
            }
        return std::sqrt(sum / double(std::max(count, 1L)));
    };
    // Behind: from just below the boat to the picture's bottom; ahead: between the horizon's
    // neighbourhood and just above the boat.
    const double behind = change(0.56, 1.0), ahead = change(0.2, 0.44);
    std::printf("wake: the picture changes by RMSE %.2f behind the boat, %.2f ahead of it\n", behind, ahead);
    const bool ok = behind > 2 && behind > 3 * ahead;
    if (!ok) std::printf("FAIL: the wake must change the water behind the boat (above 2) at least three times as much as ahead\n");
    return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) return std::fprintf(stderr, "usage: wake_check WITHOUT WITH\n"), 2;
    try {
        return wake(argv[1], argv[2]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "wake_check: %s\n", e.what());
        return 2;
    }
}
