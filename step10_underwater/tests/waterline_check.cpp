// waterline_check: the waterline measured from the sides view (--set waterline_view=sides), which
// paints each pixel red where the frame draws it from above the water, blue where from below, and
// leaves green a pixel the frame would draw from neither side.
//
//   waterline_check sweep FRAME.png...
//       The frames of a camera going down through the surface of a moving sea: in every frame,
//       every pixel is red or blue (no gap), and each column is red above blue at most once (the
//       picture split along one line: across a lens centimetres wide the surface is a plane);
//       the first frame is all above, the last all below, and some frame between shows both.
//   waterline_check flat PICTURE.png EYE_HEIGHT [NEAR_METRES VERTICAL_FOV_DEGREES]
//       A level camera (pitch 0) at EYE_HEIGHT metres over a flat sea: the lens's rows lie at
//       y = EYE_HEIGHT + NEAR tan(fov / 2) ndc_y, so the line is where that is 0: the rows below
//       it blue, those above red, within one row (NEAR 0.1, fov 50: the camera's own).
// Prints the figures; exit 0 when they hold, 1 otherwise, 2 on bad input.
#include "common/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

enum class Side { above, below, neither };

struct Frame {
    ocean::Image image;
    Side at(int x, int y) const {
        const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
        if (p[0] == 255 && p[1] == 0 && p[2] == 0) return Side::above;
        if (p[0] == 0 && p[1] == 0 && p[2] == 255) return Side::below;
        return Side::neither;
    }
};

std::optional<Frame> load(const char* path) {
    std::string error;
    auto image = ocean::load_image(path, &error);
    if (!image) {
        std::fprintf(stderr, "waterline_check: %s\n", error.c_str());
        return std::nullopt;
    }
    return Frame{*image};
}

struct Count {
    long above = 0, below = 0, neither = 0;
    int broken_columns = 0;  // columns whose sides change more than once, or blue above red
    int first_row_below(const Frame& f, int x) const {
        for (int y = 0; y < f.image.height; ++y)
            if (f.at(x, y) == Side::below) return y;
        return f.image.height;
    }
};

Count count(const Frame& f) {
    Count c;
    for (int x = 0; x < f.image.width; ++x) {
        int changes = 0;
        Side previous = f.at(x, 0);
        for (int y = 0; y < f.image.height; ++y) {
            const Side s = f.at(x, y);
            (s == Side::above ? c.above : s == Side::below ? c.below : c.neither) += 1;
            if (s != previous) {
                ++changes;
                if (previous != Side::above || s != Side::below) changes += 2;  // not red over blue
            }
            previous = s;
        }
        if (changes > 1) ++c.broken_columns;
    }
    return c;
}

int sweep(int count_of_frames, char** paths) {
    bool ok = true, both_seen = false;
    for (int i = 0; i < count_of_frames; ++i) {
        const auto frame = load(paths[i]);
        if (!frame) return 2;
        const Count c = count(*frame);
        const long pixels = c.above + c.below + c.neither;
        if (c.neither > 0 || c.broken_columns > 0) {
            std::printf("FAIL: %s: %ld pixels on neither side, %d columns not split once\n", paths[i], c.neither,
                        c.broken_columns);
            ok = false;
        }
        if (c.above > 0 && c.below > 0) both_seen = true;
        if (i == 0 && c.above != pixels) {
            std::printf("FAIL: the first frame is not all above the water (%ld of %ld)\n", c.above, pixels);
            ok = false;
        }
        if (i + 1 == count_of_frames && c.below != pixels) {
            std::printf("FAIL: the last frame is not all below the water (%ld of %ld)\n", c.below, pixels);
            ok = false;
        }
        std::printf("%s: %5.1f %% below\n", paths[i], 100.0 * double(c.below) / double(pixels));
    }
    if (!both_seen) {
        std::printf("FAIL: no frame shows the waterline (the sweep must cross the surface slowly enough)\n");
        ok = false;
    }
    std::printf("waterline_check: %d frames, %s\n", count_of_frames, ok ? "no gap, one line" : "failed");
    return ok ? 0 : 1;
}

int flat(const char* path, double eye_height, double near, double fov_degrees) {
    const auto frame = load(path);
    if (!frame) return 2;
    const Count c = count(*frame);
    const int height = frame->image.height;
    // Row y's centre is at ndc_y = 1 - 2 (y + 0.5) / height; below the water where
    // eye + near tan(fov / 2) ndc_y < 0, i.e. from row (1 + eye / (near tan)) height / 2 - 0.5 on.
    const double spread = near * std::tan(fov_degrees * kPi / 360);
    const double line = (1 + eye_height / spread) * height / 2 - 0.5;
    double worst = 0;
    for (int x = 0; x < frame->image.width; ++x) {
        const int measured = c.first_row_below(*frame, x);
        const double expected = std::clamp(std::ceil(line), 0.0, double(height));
        worst = std::max(worst, std::abs(measured - expected));
    }
    std::printf("waterline_check: eye %.4f m: the line at row %.2f of %d; worst column %.0f rows off (limit 1); "
                "%ld pixels on neither side\n", eye_height, line, height, worst, c.neither);
    const bool ok = worst <= 1 && c.neither == 0 && c.broken_columns == 0;
    if (!ok) std::printf("FAIL: the waterline is not where the lens meets the level sea\n");
    return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 3 && std::strcmp(argv[1], "sweep") == 0) return sweep(argc - 2, argv + 2);
    if ((argc == 4 || argc == 6) && std::strcmp(argv[1], "flat") == 0)
        return flat(argv[2], std::atof(argv[3]), argc == 6 ? std::atof(argv[4]) : 0.1, argc == 6 ? std::atof(argv[5]) : 50);
    std::fprintf(stderr, "usage: waterline_check sweep FRAME.png... | flat PICTURE.png EYE_HEIGHT [NEAR FOV]\n");
    return 2;
}
