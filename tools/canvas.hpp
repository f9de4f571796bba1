// A small CPU canvas for the repository's own pictures (the contact sheet, the bench chart):
// rectangles, text (DejaVu Sans through stb_truetype, anti-aliased; stb_easy_font's segment font
// if the font file is missing) and resized images, into an RGBA8 image.
#pragma once

#include "common/image.hpp"

#include <array>
#include <cstdint>
#include <string>

namespace ocean_tools {

using Colour = std::array<std::uint8_t, 3>;

class Canvas {
public:
    Canvas(int width, int height, Colour background);
    void fill_rect(int x, int y, int w, int h, Colour colour);
    // Text with its top-left corner at (x, y), UTF-8, 8 x scale pixels high.
    void text(int x, int y, const std::string& text, Colour colour, int scale = 2);
    static int text_width(const std::string& text, int scale = 2);
    // `image` resized (bilinear) into the rectangle.
    void draw_image(const ocean::Image& image, int x, int y, int w, int h);
    const ocean::Image& image() const { return image_; }

private:
    void blend(int x, int y, Colour colour, int coverage);
    void segment_text(int x, int y, const std::string& text, Colour colour, int scale);
    ocean::Image image_;
};

}  // namespace ocean_tools
