// SPDX-License-Identifier: GPL-3.0-or-later
// The PNG encoder's passes, read back with libpng: grey while every pixel is grey, a palette
// from the first pixel that is not (even in the last row), and one scratch buffer reused
// from a larger image to a smaller one. (Palette sizes 256 and 257, a first pixel of pure
// black, the GIF's loop and delays: tests/test_boundaries.cpp and tests/test_gif.cpp.)
#include "plot/frames.hpp"
#include "plot/output.hpp"

#include "png_image.hpp"
#include "rgb24_image.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace {

using test_support::rgb24;

/// The PNG's colour type (IHDR's byte 25).
int colour_type(const std::string& png) { return png.size() > 25 ? static_cast<unsigned char>(png[25]) : -1; }

std::vector<std::uint32_t> decoded(const std::string& png) {
    const auto im = test_support::decode_rgb(png);
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i + 2 < im.pixels.size(); i += 3) {
        out.push_back((std::uint32_t{im.pixels[i]} << 16) | (std::uint32_t{im.pixels[i + 1]} << 8) | im.pixels[i + 2]);
    }
    return out;
}

}  // namespace

TEST(PngPasses, GreyUntilTheLastPixelThenAPalette) {
    std::vector<unsigned char> scratch;
    std::vector<std::uint32_t> pixels = {0x000000, 0x404040, 0xffffff, 0x808080, 0x101010, 0xfefefe,
                                         0x000000, 0x404040, 0xffffff, 0x808080, 0x101010, 0xfefefe};
    std::string png = plot::png_of_pixels(rgb24(pixels, 4), 72, scratch);
    EXPECT_EQ(colour_type(png), 0) << "grey";
    EXPECT_EQ(decoded(png), pixels);
    pixels.back() = 0xfefeff;  // one pixel of the last row is not grey
    png = plot::png_of_pixels(rgb24(pixels, 4), 72, scratch);
    EXPECT_EQ(colour_type(png), 3) << "a palette";
    EXPECT_EQ(decoded(png), pixels);
}

TEST(PngPasses, ScratchReusedFromAnRgbImageToASmallerOne) {
    std::vector<unsigned char> scratch;
    std::vector<std::uint32_t> many;
    for (std::uint32_t i = 0; i < 300; ++i) many.push_back((0x010203u * i + 0x100000u * (i % 7)) & 0xffffffu);
    std::string png = plot::png_of_pixels(rgb24(many, 20), 72, scratch);
    EXPECT_EQ(colour_type(png), 2) << "RGB";
    EXPECT_EQ(decoded(png), many);
    const std::vector<std::uint32_t> few = {0x0072b2, 0xd55e00, 0x0072b2, 0xffffff};
    png = plot::png_of_pixels(rgb24(few, 2), 72, scratch);
    EXPECT_EQ(colour_type(png), 3);
    EXPECT_EQ(decoded(png), few);
}
