// image_panel OUT.png TILE_WxH COLUMNS "LABEL|IMAGE.png[|X0,Y0,X1,Y1]" ...
// A figure for a README: pictures in a grid, each under its label, each optionally cropped to
// the rectangle X0..X1, Y0..Y1 given as fractions of its own size (so a picture rendered at four
// times the resolution crops to the same view). A crop larger than its tile is box-averaged in
// linear light (a supersampled render becomes the reference it stands for); a smaller one is
// enlarged without smoothing, so its pixels stay visible.
#include "tools/canvas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

double to_linear(std::uint8_t v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
std::uint8_t to_srgb(double v) {
    const double c = v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return std::uint8_t(std::clamp(std::lround(c * 255.0), 0L, 255L));
}

// The crop [x0, x1) x [y0, y1) of `image` (pixels) as a w x h picture: each output pixel the
// linear-light mean of the source pixels it covers, or the one it falls in.
ocean::Image resample(const ocean::Image& image, int x0, int y0, int x1, int y1, int w, int h) {
    ocean::Image out{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4, 255)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int sx0 = x0 + (x1 - x0) * x / w, sx1 = std::max(sx0 + 1, x0 + (x1 - x0) * (x + 1) / w);
            const int sy0 = y0 + (y1 - y0) * y / h, sy1 = std::max(sy0 + 1, y0 + (y1 - y0) * (y + 1) / h);
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int sy = sy0; sy < sy1; ++sy)
                    for (int sx = sx0; sx < sx1; ++sx) sum += to_linear(image.rgba[(std::size_t(sy) * image.width + sx) * 4 + c]);
                out.rgba[(std::size_t(y) * w + x) * 4 + c] = to_srgb(sum / ((sx1 - sx0) * (sy1 - sy0)));
            }
        }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    int w = 0, h = 0, columns = 0;
    if (argc < 5 || std::sscanf(argv[2], "%dx%d", &w, &h) != 2 || w < 16 || h < 16 || w > 4096 || h > 4096 ||
        std::sscanf(argv[3], "%d", &columns) != 1 || columns < 1 || columns > 16) {
        std::fprintf(stderr, "usage: image_panel OUT.png TILE_WxH COLUMNS \"LABEL|IMAGE.png[|X0,Y0,X1,Y1]\" ...\n");
        return 2;
    }
    using namespace ocean_tools;
    const int count = argc - 4, rows = (count + columns - 1) / columns, margin = 12, label = 30;
    Canvas canvas(margin + columns * (w + margin), margin + rows * (h + label + margin), {24, 27, 32});
    for (int i = 0; i < count; ++i) {
        const std::string entry = argv[4 + i];
        const auto bar1 = entry.find('|'), bar2 = entry.find('|', bar1 == std::string::npos ? bar1 : bar1 + 1);
        if (bar1 == std::string::npos)
            return std::fprintf(stderr, "image_panel: expected LABEL|IMAGE[|X0,Y0,X1,Y1], got '%s'\n", entry.c_str()), 2;
        const std::string path = entry.substr(bar1 + 1, bar2 == std::string::npos ? std::string::npos : bar2 - bar1 - 1);
        double f[4] = {0, 0, 1, 1};
        if (bar2 != std::string::npos &&
            (std::sscanf(entry.c_str() + bar2 + 1, "%lf,%lf,%lf,%lf", &f[0], &f[1], &f[2], &f[3]) != 4 ||
             !(0 <= f[0] && f[0] < f[2] && f[2] <= 1 && 0 <= f[1] && f[1] < f[3] && f[3] <= 1)))
            return std::fprintf(stderr, "image_panel: bad crop in '%s' (fractions 0 <= X0 < X1 <= 1)\n", entry.c_str()), 2;
        std::string error;
        const auto image = ocean::load_image(path, &error);
        if (!image) return std::fprintf(stderr, "image_panel: %s\n", error.c_str()), 1;
        const int x = margin + (i % columns) * (w + margin), y = margin + (i / columns) * (h + label + margin);
        const int x0 = int(f[0] * image->width), x1 = std::max(x0 + 1, int(f[2] * image->width));
        const int y0 = int(f[1] * image->height), y1 = std::max(y0 + 1, int(f[3] * image->height));
        canvas.draw_image(resample(*image, x0, y0, x1, y1, w, h), x, y, w, h);
        canvas.text(x, y + h + 8, entry.substr(0, bar1), {235, 238, 242}, 2);
    }
    if (auto error = ocean::save_png(canvas.image(), argv[1])) return std::fprintf(stderr, "image_panel: %s\n", error->c_str()), 1;
    return 0;
}
