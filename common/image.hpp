// Images: load through stb_image, write PNG, read back a framebuffer, and compare two images
// (the smoke tests hold every step's screenshot to a golden image with this comparison).
#pragma once

#include "common/gl.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ocean {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // 4 bytes a pixel, top row first
};

// Any format stb_image reads, converted to RGBA8. Errors: "'path': reason".
std::optional<Image> load_image(const std::string& path, std::string* error);
// The PNG file's bytes (empty if stb cannot encode the image).
std::string encode_png(const Image& image);
// Writes the PNG whole through write_file (common/file_output.hpp): on failure, "cannot write
// 'path': reason" and no file, or the older one as it was.
std::optional<std::string> save_png(const Image& image, const std::string& path);
// The colour attachment of `framebuffer` (0: the window's back buffer), flipped top-down.
Image read_framebuffer(GLuint framebuffer, int width, int height);

// Single-channel float images in PFM ("Pf", little-endian, rows bottom to top as the format
// says; we write row 0 first, so row 0 of `values` is the bottom row of the picture).
struct FloatImage {
    int width = 0, height = 0;
    std::vector<float> values;  // width * height, row 0 first
};
std::string encode_pfm(const FloatImage& image);
// As save_png: written whole or not at all.
std::optional<std::string> save_pfm(const FloatImage& image, const std::string& path);
std::optional<FloatImage> load_pfm(const std::string& path, std::string* error);

struct ImageDifference {
    bool same_size = false;
    double rmse = 0;              // root mean square channel difference, in 0..255 units
    double max_difference = 0;    // largest channel difference, 0..255
    double bad_fraction = 0;      // fraction of pixels with a channel off by more than `threshold`
};
ImageDifference compare_images(const Image& a, const Image& b, int threshold);
// Differences magnified (x4) for a human to look at when a comparison fails.
Image difference_image(const Image& a, const Image& b);

struct ImageStatistics {
    double luminance_stddev = 0;  // 0..255
    int distinct_colours = 0;     // counted up to 4096
};
ImageStatistics image_statistics(const Image& image);
// Blank: one flat colour, or nearly (a clear colour with no geometry drawn).
bool is_blank(const Image& image);

}  // namespace ocean
