// contact_sheet OUT.png WIDTHxHEIGHT "LABEL|RENDERED.png|OWN.png" ...
// One row per step: the picture just rendered (with the shared camera and time) and the step's
// own screenshot beside it, the step's name and notes sections under them. ./ocean compare calls it.
#include "tools/canvas.hpp"
#include "tools/contact_sheet_layout.hpp"

#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: contact_sheet OUT.png WIDTHxHEIGHT \"LABEL|RENDERED.png|OWN.png\" ...\n");
        return 2;
    }
    int w = 0, h = 0;
    if (std::sscanf(argv[2], "%dx%d", &w, &h) != 2 || w < 16 || h < 16 || w > 4096 || h > 4096)
        return std::fprintf(stderr, "contact_sheet: bad tile size '%s'\n", argv[2]), 2;
    using namespace ocean_tools;
    const int margin = kSheetMargin, rows = argc - 3;
    Canvas canvas(sheet_width(w), sheet_height(rows, h), {24, 27, 32});
    // Each header over its own column, at the size that fits the tile (they used to run into each
    // other). The columns differ in camera for the steps whose screenshot has its own view
    // (step05 and step06 look from a deck): the headers say so.
    const char* headers[] = {"rendered now: one camera and time for all", "the step's own screenshot: its own view"};
    for (int column = 0; column < 2; ++column) {
        const int scale = Canvas::text_width(headers[column], 2) <= w ? 2 : 1;
        canvas.text(sheet_tile_x(column, w), 10, headers[column], {200, 205, 215}, scale);
    }
    for (int r = 0; r < rows; ++r) {
        const std::string entry = argv[3 + r];
        const auto bar1 = entry.find('|'), bar2 = entry.find('|', bar1 + 1);
        if (bar1 == std::string::npos || bar2 == std::string::npos)
            return std::fprintf(stderr, "contact_sheet: expected LABEL|RENDERED|OWN, got '%s'\n", entry.c_str()), 2;
        const std::string text = entry.substr(0, bar1);
        const int y = sheet_tile_y(r, h);
        for (int column = 0; column < 2; ++column) {
            const std::string path = column == 0 ? entry.substr(bar1 + 1, bar2 - bar1 - 1) : entry.substr(bar2 + 1);
            std::string error;
            const auto image = ocean::load_image(path, &error);
            const int x = sheet_tile_x(column, w);
            if (image) {
                canvas.draw_image(*image, x, y, w, h);
            } else {
                canvas.fill_rect(x, y, w, h, {60, 30, 30});
                canvas.text(x + 8, y + 8, "missing: " + path.substr(path.rfind('/') + 1), {255, 160, 150}, 2);
            }
        }
        canvas.text(margin, y + h + 10, text, {235, 238, 242}, 2);
    }
    if (auto error = ocean::save_png(canvas.image(), argv[1])) return std::fprintf(stderr, "contact_sheet: %s\n", error->c_str()), 1;
    return 0;
}
