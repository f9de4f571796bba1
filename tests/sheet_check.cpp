// sheet_check SHEET.png ROWS WxH: the contact sheet has ROWS rows and every tile (the rendered
// picture and the step's own screenshot) is a real picture, not blank.
#include "common/image.hpp"
#include "tools/contact_sheet_layout.hpp"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 4) return std::fprintf(stderr, "usage: sheet_check SHEET.png ROWS WxH\n"), 2;
    int rows = std::atoi(argv[2]), w = 0, h = 0;
    if (std::sscanf(argv[3], "%dx%d", &w, &h) != 2) return 2;
    std::string error;
    const auto sheet = ocean::load_image(argv[1], &error);
    if (!sheet) return std::fprintf(stderr, "sheet_check: %s\n", error.c_str()), 1;
    using namespace ocean_tools;
    if (sheet->width != sheet_width(w) || sheet->height != sheet_height(rows, h)) {
        std::printf("FAIL: the sheet is %dx%d, expected %dx%d for %d rows\n", sheet->width, sheet->height,
                    sheet_width(w), sheet_height(rows, h), rows);
        return 1;
    }
    int failures = 0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < 2; ++c) {
            ocean::Image tile{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4)};
            const int x0 = sheet_tile_x(c, w), y0 = sheet_tile_y(r, h);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w * 4; ++x)
                    tile.rgba[std::size_t(y) * w * 4 + x] = sheet->rgba[(std::size_t(y0 + y) * sheet->width + x0) * 4 + x];
            const auto stats = ocean::image_statistics(tile);
            const bool blank = ocean::is_blank(tile);
            std::printf("%s row %d %s: luminance stddev %.1f, %d colours\n", blank ? "FAIL" : "ok  ", r,
                        c == 0 ? "rendered" : "screenshot", stats.luminance_stddev, stats.distinct_colours);
            failures += blank;
        }
    std::printf("sheet_check: %d blank tile(s) of %d\n", failures, 2 * rows);
    return failures == 0 ? 0 : 1;
}
