// Image I/O and the comparison the smoke tests rely on.
#include "common/image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

ocean::Image gradient(int w, int h) {
    ocean::Image image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            auto* p = &image.rgba[(std::size_t(y) * w + x) * 4];
            p[0] = std::uint8_t(x * 255 / (w - 1));
            p[1] = std::uint8_t(y * 255 / (h - 1));
            p[2] = std::uint8_t((x + y) % 256);
            p[3] = 255;
        }
    return image;
}

std::string temp(const std::string& name) {
    return (std::filesystem::temp_directory_path() / (std::to_string(::getpid()) + name)).string();
}

TEST(ImageCompare, IdenticalImagesDifferByNothing) {
    const auto a = gradient(64, 32);
    const auto d = ocean::compare_images(a, a, 0);
    EXPECT_TRUE(d.same_size);
    EXPECT_EQ(d.rmse, 0);
    EXPECT_EQ(d.bad_fraction, 0);
}

TEST(ImageCompare, MeasuresRmseAndBadPixels) {
    const auto a = gradient(10, 10);
    auto b = a;
    b.rgba[0] = std::uint8_t(a.rgba[0] + 60);  // one channel of one pixel, +60
    const auto d = ocean::compare_images(a, b, 24);
    EXPECT_NEAR(d.rmse, std::sqrt(60.0 * 60.0 / 300.0), 1e-12);  // 100 pixels x 3 channels
    EXPECT_DOUBLE_EQ(d.bad_fraction, 0.01);
    EXPECT_EQ(d.max_difference, 60);
    EXPECT_EQ(ocean::compare_images(a, b, 60).bad_fraction, 0) << "threshold is exclusive";
}

TEST(ImageCompare, DifferentSizesNeverMatch) {
    EXPECT_FALSE(ocean::compare_images(gradient(10, 10), gradient(10, 11), 255).same_size);
}

TEST(ImageCompare, BlankDetection) {
    ocean::Image flat{32, 32, std::vector<std::uint8_t>(32 * 32 * 4, 40)};
    EXPECT_TRUE(ocean::is_blank(flat));
    EXPECT_FALSE(ocean::is_blank(gradient(32, 32)));
}

TEST(ImageIo, PngRoundTripIsLossless) {
    const auto a = gradient(33, 17);
    const std::string path = temp("roundtrip.png");
    ASSERT_FALSE(ocean::save_png(a, path));
    std::string error;
    const auto b = ocean::load_image(path, &error);
    ASSERT_TRUE(b) << error;
    EXPECT_EQ(b->width, 33);
    EXPECT_EQ(b->height, 17);
    EXPECT_EQ(b->rgba, a.rgba);
    std::filesystem::remove(path);
}

TEST(ImageIo, MissingCorruptAndDirectoryFilesAreErrors) {
    std::string error;
    EXPECT_FALSE(ocean::load_image("/nonexistent.png", &error));
    EXPECT_NE(error.find("/nonexistent.png"), std::string::npos);
    const std::string corrupt = temp("corrupt.png");
    std::ofstream(corrupt) << "\x89PNG not really";
    EXPECT_FALSE(ocean::load_image(corrupt, &error));
    EXPECT_NE(error.find("not a readable image"), std::string::npos);
    std::filesystem::remove(corrupt);
    EXPECT_FALSE(ocean::load_image(std::filesystem::temp_directory_path().string(), &error));
    EXPECT_NE(error.find("directory"), std::string::npos);
}

}  // namespace
