// image_compare ACTUAL.png GOLDEN.png [--rmse R] [--threshold T] [--bad-fraction F] [--diff OUT.png]
// Exit 0 when ACTUAL matches GOLDEN within the tolerances and is not blank; 1 otherwise, with
// one line saying which limit failed. The defaults are the smoke tests' stated tolerance:
// RMSE <= 2.5 (0..255 units) and at most 0.5% of pixels off by more than 24 in a channel.
// image_compare A.png B.png --box [--threshold T]: a measurement, not a check: prints
// "box X0 Y0 X1 Y1", the smallest rectangle (inclusive) holding every pixel with a channel off by
// more than T, or "box none"; exit 0 when the sizes match (tests/smoke/panel_fits.sh: a panel).
#include "common/image.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// The --box measurement: which pixels differ by more than `threshold`, as one rectangle.
int print_box(const ocean::Image& a, const ocean::Image& b, int threshold) {
    if (a.width != b.width || a.height != b.height) {
        std::fprintf(stderr, "image_compare: sizes differ: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
        return 1;
    }
    int x0 = a.width, y0 = a.height, x1 = -1, y1 = -1;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const std::size_t i = 4 * (std::size_t(y) * std::size_t(a.width) + std::size_t(x));
            int most = 0;
            for (std::size_t c = 0; c < 3; ++c) most = std::max(most, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
            if (most <= threshold) continue;
            x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
    if (x1 < 0) std::printf("box none\n");
    else std::printf("box %d %d %d %d\n", x0, y0, x1, y1);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: image_compare ACTUAL.png GOLDEN.png [--rmse R] [--threshold T] "
                             "[--bad-fraction F] [--diff OUT.png]\n");
        return 2;
    }
    double max_rmse = 2.5, max_bad_fraction = 0.005;
    int threshold = 24;
    std::string diff_path;
    bool box = false;
    for (int i = 3; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--box") {
            box = true;
            continue;
        }
        if (i + 1 >= argc) {
            std::fprintf(stderr, "image_compare: %s needs a value\n", flag.c_str());
            return 2;
        }
        const char* value = argv[++i];
        if (flag == "--rmse") max_rmse = std::atof(value);
        else if (flag == "--threshold") threshold = std::atoi(value);
        else if (flag == "--bad-fraction") max_bad_fraction = std::atof(value);
        else if (flag == "--diff") diff_path = value;
        else {
            std::fprintf(stderr, "image_compare: unknown flag %s\n", flag.c_str());
            return 2;
        }
    }
    std::string error;
    const auto actual = ocean::load_image(argv[1], &error);
    if (!actual) return std::fprintf(stderr, "image_compare: %s\n", error.c_str()), 1;
    const auto golden = ocean::load_image(argv[2], &error);
    if (!golden) return std::fprintf(stderr, "image_compare: golden %s\n", error.c_str()), 1;
    if (box) return print_box(*actual, *golden, threshold);
    if (ocean::is_blank(*actual)) {
        const auto s = ocean::image_statistics(*actual);
        std::fprintf(stderr, "image_compare: %s is blank (luminance stddev %.2f, %d colours)\n", argv[1],
                     s.luminance_stddev, s.distinct_colours);
        return 1;
    }
    const auto d = ocean::compare_images(*actual, *golden, threshold);
    if (!d.same_size) {
        std::fprintf(stderr, "image_compare: sizes differ: %dx%d vs golden %dx%d\n", actual->width,
                     actual->height, golden->width, golden->height);
        return 1;
    }
    std::printf("image_compare: rmse %.3f (limit %.3f), %.4f%% pixels off by > %d (limit %.4f%%), max %g\n",
                d.rmse, max_rmse, 100 * d.bad_fraction, threshold, 100 * max_bad_fraction, d.max_difference);
    if (d.rmse <= max_rmse && d.bad_fraction <= max_bad_fraction) return 0;
    if (!diff_path.empty() && !ocean::save_png(ocean::difference_image(*actual, *golden), diff_path))
        std::fprintf(stderr, "image_compare: differences (x4) written to %s\n", diff_path.c_str());
    std::fprintf(stderr, "image_compare: %s differs from %s beyond the tolerance\n", argv[1], argv[2]);
    return 1;
}
