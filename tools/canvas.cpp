#include "tools/canvas.hpp"

#include <stb_easy_font.h>
#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
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

namespace {

// The labels' font: DejaVu Sans from Debian's fonts-dejavu-core (./ocean installs it), rasterised
// by stb_truetype with anti-aliasing. Without the file the labels fall back to stb_easy_font's
// segment font, with one warning.
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct Font {
    std::vector<unsigned char> data;
    stbtt_fontinfo info{};
    bool loaded = false;
};

const Font& font() {
    static const Font f = [] {
        Font loaded;
        std::ifstream file(kFontPath, std::ios::binary);
        loaded.data.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
        loaded.loaded = !loaded.data.empty() &&
                        stbtt_InitFont(&loaded.info, loaded.data.data(), stbtt_GetFontOffsetForIndex(loaded.data.data(), 0)) != 0;
        if (!loaded.loaded)
            std::fprintf(stderr, "warning: cannot read the font %s (install fonts-dejavu-core): labels in the "
                                 "segment font\n", kFontPath);
        return loaded;
    }();
    return f;
}

// The code points of UTF-8 text (labels hold "x", "×", "—" ...); a malformed byte becomes '?'.
std::vector<int> code_points(const std::string& text) {
    std::vector<int> out;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        const int length = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (length == 0 || i + std::size_t(length) > text.size()) {
            out.push_back('?');
            ++i;
            continue;
        }
        int point = length == 1 ? c : c & (0x7F >> length);
        for (int k = 1; k < length; ++k) point = (point << 6) | (static_cast<unsigned char>(text[i + std::size_t(k)]) & 0x3F);
        out.push_back(point);
        i += std::size_t(length);
    }
    return out;
}

// How far the pen moves after character i of `points`, in pixels at font scale s: its advance,
// and the kerning with the next one.
float pen_advance(const Font& f, const std::vector<int>& points, std::size_t i, float s) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&f.info, points[i], &advance, &bearing);
    const int kern = i + 1 < points.size() ? stbtt_GetCodepointKernAdvance(&f.info, points[i], points[i + 1]) : 0;
    return float(advance + kern) * s;
}

// The font's pixel height for a `scale` of the old segment font (7 pixels a scale, plus leading).
float pixel_height(int scale) { return 8.0f * float(scale); }

int segment_text_width(const std::string& text, int scale) {
    std::string copy = text;
    return stb_easy_font_width(copy.data()) * scale;
}

}  // namespace

void Canvas::text(int x, int y, const std::string& text, Colour colour, int scale) {
    const Font& f = font();
    if (!f.loaded) {
        segment_text(x, y, text, colour, scale);
        return;
    }
    const float s = stbtt_ScaleForPixelHeight(&f.info, pixel_height(scale));
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(&f.info, &ascent, &descent, &gap);
    const int baseline = y + int(std::lround(float(ascent) * s));
    float pen = float(x);
    const std::vector<int> points = code_points(text);
    for (std::size_t i = 0; i < points.size(); ++i) {
        int w = 0, h = 0, x0 = 0, y0 = 0;
        const float shift = pen - std::floor(pen);
        unsigned char* bitmap = stbtt_GetCodepointBitmapSubpixel(&f.info, s, s, shift, 0.0f, points[i], &w, &h, &x0, &y0);
        for (int j = 0; j < h; ++j)
            for (int k = 0; k < w; ++k)
                blend(int(std::floor(pen)) + x0 + k, baseline + y0 + j, colour, bitmap[j * w + k]);
        stbtt_FreeBitmap(bitmap, nullptr);
        pen += pen_advance(f, points, i, s);
    }
}

int Canvas::text_width(const std::string& text, int scale) {
    const Font& f = font();
    if (!f.loaded) return segment_text_width(text, scale);
    const float s = stbtt_ScaleForPixelHeight(&f.info, pixel_height(scale));
    float width = 0;
    const std::vector<int> points = code_points(text);
    for (std::size_t i = 0; i < points.size(); ++i) width += pen_advance(f, points, i, s);
    return int(std::ceil(width));
}

// Coverage 0..255 of `colour` over the pixel (x, y).
void Canvas::blend(int x, int y, Colour colour, int coverage) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || coverage <= 0) return;
    std::uint8_t* p = &image_.rgba[(std::size_t(y) * image_.width + x) * 4];
    for (int k = 0; k < 3; ++k)
        p[k] = std::uint8_t((p[k] * (255 - coverage) + colour[std::size_t(k)] * coverage + 127) / 255);
}

void Canvas::segment_text(int x, int y, const std::string& text, Colour colour, int scale) {
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
