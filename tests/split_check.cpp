// split_check SPLIT.png LEFT.png RIGHT.png: the split view's left half must be LEFT's left half and
// its right half RIGHT's right half (within RMSE 1/255, the 2-pixel divider aside), and LEFT and
// RIGHT must differ there (so the halves really show two variants). Exit 0 when all hold.
#include "common/image.hpp"

#include <cmath>
#include <cstdio>

namespace {

// RMSE (0..255) between two images over columns [x0, x1).
double rmse(const ocean::Image& a, const ocean::Image& b, int x0, int x1) {
    double sum = 0;
    long count = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) {
                const std::size_t i = (std::size_t(y) * a.width + x) * 4 + c;
                const double d = double(a.rgba[i]) - double(b.rgba[i]);
                sum += d * d;
                ++count;
            }
    return std::sqrt(sum / double(count));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) return std::fprintf(stderr, "usage: split_check SPLIT.png LEFT.png RIGHT.png\n"), 2;
    std::string error;
    const auto split = ocean::load_image(argv[1], &error);
    const auto left = ocean::load_image(argv[2], &error);
    const auto right = ocean::load_image(argv[3], &error);
    if (!split || !left || !right) return std::fprintf(stderr, "split_check: %s\n", error.c_str()), 1;
    const int w = split->width, middle = w / 2;
    const double left_match = rmse(*split, *left, 0, middle - 1);
    const double right_match = rmse(*split, *right, middle + 1, w);
    const double left_differs = rmse(*left, *right, 0, middle - 1);
    const double right_differs = rmse(*left, *right, middle + 1, w);
    std::printf("left half vs LEFT: rmse %.3f; right half vs RIGHT: rmse %.3f; LEFT vs RIGHT: %.3f | %.3f\n",
                left_match, right_match, left_differs, right_differs);
    const bool ok = left_match <= 1.0 && right_match <= 1.0 && left_differs > 2.0 && right_differs > 2.0;
    std::printf("split_check: %s\n", ok ? "the halves are the two variants" : "FAIL");
    return ok ? 0 : 1;
}
