#pragma once
// Decodes PNG files for image comparisons in tests.

#include <png.h>

#include <string>
#include <vector>

namespace test_support {

/// A decoded 8-bit grey image.
struct grey_image {
    unsigned width = 0;                ///< pixels per row
    unsigned height = 0;               ///< rows
    std::vector<unsigned char> pixels;  ///< row-major, 0 black to 255 white

    /// The pixel at column x, row y.
    unsigned char at(unsigned x, unsigned y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// Decodes PNG bytes to grey; an empty image if they are not a PNG.
inline grey_image decode(const std::string& png) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    grey_image out;
    if (!png_image_begin_read_from_memory(&image, png.data(), png.size())) return out;
    image.format = PNG_FORMAT_GRAY;
    out.pixels.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) return {};
    out.width = image.width;
    out.height = image.height;
    return out;
}

}  // namespace test_support
