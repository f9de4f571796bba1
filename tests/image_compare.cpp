// image_compare ACTUAL.png GOLDEN.png [--rmse R] [--threshold T] [--bad-fraction F] [--diff OUT.png]
// Exit 0 when ACTUAL matches GOLDEN within the tolerances and is not blank; 1 otherwise, with
// one line saying which limit failed. The defaults are the smoke tests' stated tolerance:
// RMSE <= 2.5 (0..255 units) and at most 0.5% of pixels off by more than 24 in a channel.
#include "common/image.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: image_compare ACTUAL.png GOLDEN.png [--rmse R] [--threshold T] "
                             "[--bad-fraction F] [--diff OUT.png]\n");
        return 2;
    }
    double max_rmse = 2.5, max_bad_fraction = 0.005;
    int threshold = 24;
    std::string diff_path;
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--rmse") max_rmse = std::atof(argv[i + 1]);
        else if (flag == "--threshold") threshold = std::atoi(argv[i + 1]);
        else if (flag == "--bad-fraction") max_bad_fraction = std::atof(argv[i + 1]);
        else if (flag == "--diff") diff_path = argv[i + 1];
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
