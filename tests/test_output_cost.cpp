// SPDX-License-Identifier: GPL-3.0-or-later
// The PNG writer's passes: what they promise while they are made cheaper (a grey image is
// told from a coloured one at every pixel of every row, whatever Cairo leaves in the unused
// byte, and every kind decodes to the pixels it was given).

#include "plot/frames.hpp"
#include "plot/output.hpp"
#include "png_image.hpp"
#include "rgb24_image.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace test_support;

namespace {

/// An RGB24 image of w x h pixels, pixel(x, y) each, rows with a gap after them.
plot::argb_image image_of(int w, int h, const std::function<std::uint32_t(int, int)>& pixel) {
    return rgb24_of(w, h, pixel, 8);
}

/// The PNG of the image, after checking that it decodes to the image's pixels.
std::string encoded(const plot::argb_image& im) {
    std::vector<unsigned char> scratch;
    const std::string png = plot::png_of_pixels(im, 300, scratch);
    const rgb_image decoded = decode_rgb(png);
    EXPECT_EQ(decoded.width, static_cast<unsigned>(im.width));
    EXPECT_EQ(decoded.height, static_cast<unsigned>(im.height));
    EXPECT_TRUE(decoded.pixels == rgb_of(im)) << im.width << " x " << im.height;
    return png;
}

/// A grey level that changes along the row and down the rows, and an unused byte that does too.
std::uint32_t grey_at(int x, int y) {
    const auto level = static_cast<std::uint32_t>((37 * x + 11 * y) % 256);
    const auto unused = static_cast<std::uint32_t>((x * 89 + y * 7) % 256);
    return (unused << 24) | (level * 0x010101u);
}

}  // namespace

TEST(OutputCost, GreyIsToldFromColourAtEveryPixelOfARow) {
    // Widths around the vector lanes (4, 8, 16 pixels) and their tails; one channel of one
    // pixel off by one (red, green or blue; the last row and elsewhere) makes the image
    // coloured (a palette: these have few colours), and the pixels hold either way.
    for (const int w : {1, 2, 3, 4, 5, 7, 8, 9, 15, 16, 17, 31, 32, 33, 67}) {
        const int h = 3;
        EXPECT_EQ(color_type(encoded(image_of(w, h, grey_at))), 0) << w;
        for (const std::uint32_t channel : {0x010000u, 0x000100u, 0x000001u}) {
            for (const int at_x : {0, w / 2, w - 1}) {
                for (const int at_y : {0, h - 1}) {
                    const auto off = [&](int x, int y) {
                        const std::uint32_t p = grey_at(x, y);
                        if (x != at_x || y != at_y) return p;
                        return (p & 0xff000000u) | ((p & 0xffffffu) ^ channel);
                    };
                    EXPECT_EQ(color_type(encoded(image_of(w, h, off))), 3)
                        << "width " << w << ", pixel (" << at_x << ", " << at_y << "), channel " << channel;
                }
            }
        }
    }
}

TEST(OutputCost, TheUnusedByteNeverMakesAGreyImageColoured) {
    // Every value of the byte Cairo does not define, on grey pixels of every level.
    const auto grey = [](int x, int y) {
        return (static_cast<std::uint32_t>(x) << 24) | (static_cast<std::uint32_t>((x + y) % 256) * 0x010101u);
    };
    EXPECT_EQ(color_type(encoded(image_of(256, 2, grey))), 0);
}

TEST(OutputCost, MoreThan256ColoursAreRgbAndHoldTheirPixels) {
    const auto colours = [](int n) {
        return [n](int x, int y) { return static_cast<std::uint32_t>(((x + 7 * y) % n) * 0x010203u + 0x100000u); };
    };
    EXPECT_EQ(color_type(encoded(image_of(300, 5, colours(256)))), 3);
    EXPECT_EQ(color_type(encoded(image_of(300, 5, colours(257)))), 2);
}

TEST(OutputCost, RgbRowsEndWhereTheyShouldAtEveryWidth) {
    // A pixel's three bytes are written as four: the fourth lands on the next pixel, the next
    // row's filter byte, or past the last row. Every width from 1, and a tall and a wide
    // image, with more than 256 colours (RGB), decode to their pixels.
    const auto distinct = [](int w) {
        return [w](int x, int y) {
            const auto i = static_cast<std::uint32_t>(y * w + x);
            return 0xa5000000u | ((i * 2654435761u) & 0xffffffu);
        };
    };
    for (int w = 1; w <= 33; ++w) {
        const int h = 257 / w + 2;
        EXPECT_EQ(color_type(encoded(image_of(w, h, distinct(w)))), 2) << w;
    }
    EXPECT_EQ(color_type(encoded(image_of(1, 1000, distinct(1)))), 2);
    EXPECT_EQ(color_type(encoded(image_of(3001, 2, distinct(3001)))), 2);
}

TEST(OutputCost, ReusedRowsGiveTheBytesOfFreshOnes) {
    // The rows are written over whatever the scratch holds: frames of an animation reuse it,
    // an RGB frame leaving three bytes a pixel behind before a grey or a palette frame, and
    // a larger frame growing it. Each PNG is the same as from a fresh scratch.
    const int w = 301;
    const int h = 7;
    const auto rgb = [](int x, int y) { return static_cast<std::uint32_t>((x * 977 + y * 131071) & 0xffffff); };
    const auto few = [](int x, int y) { return (x + y) % 3 == 0 ? 0x0072b2u : 0xffffffu; };
    std::vector<unsigned char> reused;
    for (const auto& [pixels, width] : std::vector<std::pair<std::function<std::uint32_t(int, int)>, int>>{
             {rgb, w}, {grey_at, w}, {few, w}, {rgb, 2 * w}, {grey_at, 3}, {rgb, 3}}) {
        const plot::argb_image im = image_of(width, h, pixels);
        std::vector<unsigned char> fresh;
        const std::string png = plot::png_of_pixels(im, 150, reused);
        EXPECT_EQ(png, plot::png_of_pixels(im, 150, fresh)) << width;
        EXPECT_TRUE(decode_rgb(png).pixels == rgb_of(im)) << width;
    }
}
