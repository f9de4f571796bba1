#include "common/image.hpp"

#include "common/file_output.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unordered_set>

namespace ocean {

std::optional<Image> load_image(const std::string& path, std::string* error) {
    std::error_code missing;
    const auto status = std::filesystem::status(path, missing);
    if (missing) {
        *error = "'" + path + "': " + missing.message();
        return std::nullopt;
    }
    if (std::filesystem::is_directory(status)) {
        *error = "'" + path + "': is a directory";
        return std::nullopt;
    }
    int w = 0, h = 0, channels = 0;
    stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (pixels == nullptr) {
        *error = "'" + path + "': not a readable image (" + stbi_failure_reason() + ")";
        return std::nullopt;
    }
    Image image{w, h, std::vector<std::uint8_t>(pixels, pixels + std::size_t(w) * h * 4)};
    stbi_image_free(pixels);
    return image;
}

std::string encode_png(const Image& image) {
    std::string png;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() < std::size_t(image.width) * image.height * 4 ||
        stbi_write_png_to_func(append, &png, image.width, image.height, 4, image.rgba.data(), image.width * 4) == 0)
        return {};
    return png;
}

std::optional<std::string> save_png(const Image& image, const std::string& path) {
    const std::string png = encode_png(image);
    if (png.empty())
        return "cannot write '" + path + "': cannot encode a " + std::to_string(image.width) + "x" +
               std::to_string(image.height) + " image as PNG";
    return write_file(path, png);
}

Image read_framebuffer(GLuint framebuffer, int width, int height) {
    Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    if (framebuffer == 0) glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    // GL's first row is the bottom one; PNG's is the top one.
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(image.rgba.begin() + std::ptrdiff_t(y * row),
                         image.rgba.begin() + std::ptrdiff_t((y + 1) * row),
                         image.rgba.begin() + std::ptrdiff_t((height - 1 - y) * row));
    // Screenshots are opaque whatever alpha the passes left behind.
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
    return image;
}

std::string encode_pfm(const FloatImage& image) {
    // A negative scale: little-endian floats (the machines we run on).
    std::string pfm = "Pf\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    pfm.append(reinterpret_cast<const char*>(image.values.data()), image.values.size() * sizeof(float));
    return pfm;
}

std::optional<std::string> save_pfm(const FloatImage& image, const std::string& path) {
    return write_file(path, encode_pfm(image));
}

std::optional<FloatImage> load_pfm(const std::string& path, std::string* error) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        *error = "'" + path + "': " + std::strerror(errno);
        return std::nullopt;
    }
    FloatImage image;
    char magic[3] = {};
    double scale = 0;
    const bool header = std::fscanf(file, "%2s %d %d %lf", magic, &image.width, &image.height, &scale) == 4 &&
                        std::string(magic) == "Pf" && scale < 0 && image.width > 0 && image.height > 0 &&
                        image.width <= 65536 && image.height <= 65536 && std::fgetc(file) != EOF;
    if (header) {
        image.values.resize(std::size_t(image.width) * std::size_t(image.height));
        if (std::fread(image.values.data(), sizeof(float), image.values.size(), file) != image.values.size())
            image.values.clear();
    }
    std::fclose(file);
    if (!header || image.values.empty()) {
        *error = "'" + path + "': not a little-endian greyscale PFM";
        return std::nullopt;
    }
    return image;
}

ImageDifference compare_images(const Image& a, const Image& b, int threshold) {
    ImageDifference d;
    d.same_size = a.width == b.width && a.height == b.height;
    if (!d.same_size || a.rgba.empty()) return d;
    double sum_squares = 0;
    std::size_t bad_pixels = 0;
    for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
        int worst = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const int diff = std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c]));
            sum_squares += double(diff) * diff;
            worst = std::max(worst, diff);
        }
        d.max_difference = std::max(d.max_difference, double(worst));
        if (worst > threshold) ++bad_pixels;
    }
    const double pixels = double(a.rgba.size() / 4);
    d.rmse = std::sqrt(sum_squares / (pixels * 3));
    d.bad_fraction = double(bad_pixels) / pixels;
    return d;
}

Image difference_image(const Image& a, const Image& b) {
    Image out{a.width, a.height, std::vector<std::uint8_t>(a.rgba.size(), 255)};
    if (a.width != b.width || a.height != b.height) return out;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        if (i % 4 != 3)
            out.rgba[i] = std::uint8_t(std::min(255, 4 * std::abs(int(a.rgba[i]) - int(b.rgba[i]))));
    return out;
}

ImageStatistics image_statistics(const Image& image) {
    ImageStatistics s;
    double sum = 0, sum_squares = 0;
    std::unordered_set<std::uint32_t> colours;
    for (std::size_t p = 0; p + 3 < image.rgba.size(); p += 4) {
        const double y = 0.2126 * image.rgba[p] + 0.7152 * image.rgba[p + 1] + 0.0722 * image.rgba[p + 2];
        sum += y;
        sum_squares += y * y;
        if (colours.size() < 4096)
            colours.insert(std::uint32_t(image.rgba[p]) << 16 | std::uint32_t(image.rgba[p + 1]) << 8 |
                           image.rgba[p + 2]);
    }
    const double n = std::max<double>(1, double(image.rgba.size() / 4));
    const double mean = sum / n;
    s.luminance_stddev = std::sqrt(std::max(0.0, sum_squares / n - mean * mean));
    s.distinct_colours = int(colours.size());
    return s;
}

bool is_blank(const Image& image) {
    const ImageStatistics s = image_statistics(image);
    return s.luminance_stddev < 2.0 || s.distinct_colours < 16;
}

}  // namespace ocean
