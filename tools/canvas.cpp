#include "tools/canvas.hpp"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ocean_tools {

Canvas::Canvas(int width, int height, Colour background)
    : image_{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4, 255)} {
    fill_rect(0, 0, width, height, background);
}

void Canvas::fill_rect(int x, int y, int w, int h, Colour colour) {
    for (int j = std::max(0, y); j < std::min(image_.height, y + h); ++j)
        for (int i = std::max(0, x); i < std::min(image_.width, x + w); ++i) {
            std::uint8_t* p = &image_.rgba[(std::size_t(j) * image_.width + i) * 4];
            p[0] = colour[0];
            p[1] = colour[1];
            p[2] = colour[2];
            p[3] = 255;
        }
}

void Canvas::text(int x, int y, const std::string& text, Colour colour, int scale) {
    // stb_easy_font writes 64 bytes a quad and needs up to ~12 quads for a digit ("0", "8"): at the
    // ~300 bytes a character its header calls typical, labels full of digits were cut short.
    std::vector<char> buffer(text.size() * 1024 + 64);
    std::string copy = text;
    const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size()));
    // 4 vertices a quad, each x, y, z (floats) and a colour (4 bytes): 16 bytes.
    for (int q = 0; q < quads; ++q) {
        const float* v0 = reinterpret_cast<const float*>(&buffer[std::size_t(q) * 64]);
        const float* v2 = reinterpret_cast<const float*>(&buffer[std::size_t(q) * 64 + 32]);
        const int x0 = x + int(std::lround(v0[0] * float(scale))), y0 = y + int(std::lround(v0[1] * float(scale)));
        const int x1 = x + int(std::lround(v2[0] * float(scale))), y1 = y + int(std::lround(v2[1] * float(scale)));
        fill_rect(std::min(x0, x1), std::min(y0, y1), std::abs(x1 - x0), std::abs(y1 - y0), colour);
    }
}

int Canvas::text_width(const std::string& text, int scale) {
    std::string copy = text;
    return stb_easy_font_width(copy.data()) * scale;
}

void Canvas::draw_image(const ocean::Image& src, int x, int y, int w, int h) {
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const float u = (float(i) + 0.5f) * float(src.width) / float(w) - 0.5f;
            const float v = (float(j) + 0.5f) * float(src.height) / float(h) - 0.5f;
            const int u0 = std::clamp(int(std::floor(u)), 0, src.width - 1), v0 = std::clamp(int(std::floor(v)), 0, src.height - 1);
            const int u1 = std::min(u0 + 1, src.width - 1), v1 = std::min(v0 + 1, src.height - 1);
            const float fu = std::clamp(u - float(u0), 0.0f, 1.0f), fv = std::clamp(v - float(v0), 0.0f, 1.0f);
            Colour c{};
            for (int k = 0; k < 3; ++k) {
                auto at = [&](int uu, int vv) { return float(src.rgba[(std::size_t(vv) * src.width + uu) * 4 + k]); };
                const float top = at(u0, v0) * (1 - fu) + at(u1, v0) * fu;
                const float bottom = at(u0, v1) * (1 - fu) + at(u1, v1) * fu;
                c[std::size_t(k)] = std::uint8_t(std::lround(top * (1 - fv) + bottom * fv));
            }
            fill_rect(x + i, y + j, 1, 1, c);
        }
}

}  // namespace ocean_tools
