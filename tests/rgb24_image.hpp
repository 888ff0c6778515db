// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An image for the plot layer's encoders (PNG, GIF) made of given pixels, for the tests that
// read the encoders' bytes back (tests/png_image.hpp decodes them; it stays free of plot).

#include "plot/frames.hpp"

#include <cstdint>
#include <cstring>
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

}  // namespace test_support
