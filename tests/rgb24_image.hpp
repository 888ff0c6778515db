// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An image for the plot layer's encoders (PNG, GIF) made of given pixels, for the tests that
// read the encoders' bytes back (tests/png_image.hpp decodes them; it stays free of plot).

#include "plot/frames.hpp"

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace test_support {

/// An RGB24 image of the given pixels (0xRRGGBB), one row a line of `width`.
inline plot::argb_image rgb24(const std::vector<std::uint32_t>& pixels, int width) {
    plot::argb_image im;
    im.width = width;
    im.height = static_cast<int>(pixels.size()) / width;
    im.stride = 4 * width;
    im.rgb24 = true;
    im.data.resize(pixels.size() * 4);
    std::memcpy(im.data.data(), pixels.data(), im.data.size());
    return im;
}

/// An RGB24 image of w x h pixels, pixel(x, y) each (0xUURRGGBB, UU the byte Cairo leaves as
/// it likes), each row followed by `row_gap` bytes of 0x5a (as a wider stride leaves them).
inline plot::argb_image rgb24_of(int w, int h, const std::function<std::uint32_t(int, int)>& pixel, int row_gap = 0) {
    plot::argb_image im;
    im.width = w;
    im.height = h;
    im.stride = 4 * w + row_gap;
    im.rgb24 = true;
    im.data.assign(static_cast<std::size_t>(im.stride) * h, 0x5a);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::uint32_t p = pixel(x, y);
            std::memcpy(im.data.data() + static_cast<std::size_t>(y) * im.stride + 4 * x, &p, 4);
        }
    }
    return im;
}

/// A PNG's colour type (IHDR's tenth byte): 0 grey, 2 RGB, 3 palette.
inline int color_type(const std::string& png) { return static_cast<unsigned char>(png.at(25)); }

/// The image's pixels as R, G, B bytes (Cairo's unused byte left out).
inline std::vector<unsigned char> rgb_of(const plot::argb_image& im) {
    std::vector<unsigned char> out;
    for (int y = 0; y < im.height; ++y) {
        for (int x = 0; x < im.width; ++x) {
            std::uint32_t p;
            std::memcpy(&p, im.data.data() + static_cast<std::size_t>(y) * im.stride + 4 * x, 4);
            out.insert(out.end(), {static_cast<unsigned char>(p >> 16), static_cast<unsigned char>(p >> 8),
                                   static_cast<unsigned char>(p)});
        }
    }
    return out;
}

}  // namespace test_support
