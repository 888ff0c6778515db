// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Decodes PNG files for image comparisons in tests: grey and RGB pixels, the frame box of
// a plot, and an RMS comparison after matplotlib's compare_images.

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
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

/// A decoded 8-bit RGB image.
struct rgb_image {
    unsigned width = 0;                 ///< pixels per row
    unsigned height = 0;                ///< rows
    std::vector<unsigned char> pixels;  ///< row-major, three bytes (R, G, B) a pixel
};

namespace detail {

inline bool decode_as(const std::string& png, png_uint_32 format, unsigned& width, unsigned& height,
                      std::vector<unsigned char>& pixels) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, png.data(), png.size())) return false;
    image.format = format;
    pixels.resize(PNG_IMAGE_SIZE(image));
    // Transparent pixels (there are none in our figures) would be composed on white.
    png_color white{255, 255, 255};
    if (!png_image_finish_read(&image, &white, pixels.data(), 0, nullptr)) return false;
    width = image.width;
    height = image.height;
    return true;
}

}  // namespace detail

/// Decodes PNG bytes to grey; an empty image if they are not a PNG.
inline grey_image decode(const std::string& png) {
    grey_image out;
    if (!detail::decode_as(png, PNG_FORMAT_GRAY, out.width, out.height, out.pixels)) return {};
    return out;
}

/// Decodes PNG bytes to RGB; an empty image if they are not a PNG.
inline rgb_image decode_rgb(const std::string& png) {
    rgb_image out;
    if (!detail::decode_as(png, PNG_FORMAT_RGB, out.width, out.height, out.pixels)) return {};
    return out;
}

/// A plot's frame in pixels: the outermost rows and columns of its longest dark lines.
struct frame_box {
    int left = 0;    ///< first column of the left edge
    int top = 0;     ///< first row of the top edge
    int right = 0;   ///< last column of the right edge
    int bottom = 0;  ///< last row of the bottom edge
};

/// The frame of a one-panel figure: rows and columns whose longest run of dark pixels is
/// at least 90 % of the longest anywhere are the frame's edges (curves, ticks and text
/// never run that far).
inline frame_box find_frame(const grey_image& im) {
    auto longest = [&](bool rows, unsigned i) {
        const unsigned n = rows ? im.width : im.height;
        unsigned best = 0, run = 0;
        for (unsigned k = 0; k < n; ++k) {
            const bool dark = (rows ? im.at(k, i) : im.at(i, k)) < 128;
            run = dark ? run + 1 : 0;
            best = std::max(best, run);
        }
        return best;
    };
    auto edges = [&](bool rows, int& first, int& last) {
        const unsigned n = rows ? im.height : im.width;
        std::vector<unsigned> runs(n);
        for (unsigned i = 0; i < n; ++i) runs[i] = longest(rows, i);
        const unsigned most = n ? *std::max_element(runs.begin(), runs.end()) : 0;
        first = -1;
        last = -1;
        for (unsigned i = 0; i < n; ++i) {
            if (most > 0 && runs[i] * 10 >= most * 9) {
                if (first < 0) first = static_cast<int>(i);
                last = static_cast<int>(i);
            }
        }
    };
    frame_box b;
    edges(true, b.top, b.bottom);
    edges(false, b.left, b.right);
    return b;
}

/// Writes RGB pixels as a PNG file; false on failure.
inline bool write_png(const std::string& path, const rgb_image& im) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = im.width;
    image.height = im.height;
    image.format = PNG_FORMAT_RGB;
    return png_image_write_to_file(&image, path.c_str(), 0, im.pixels.data(), 0, nullptr) != 0;
}

/// The result of comparing two images.
struct comparison {
    bool same_size = false;  ///< the images have the same width and height
    double rms = 0;          ///< root mean square of the differences of all R, G and B values (0..255)
};

/// Compares like matplotlib's compare_images: the RMS of the per-channel differences of
/// RGB pixels. If the images differ by more than `tolerance` (or in size) and `diff_path`
/// is not empty, writes there an image of the differences, ten times amplified, as
/// matplotlib's save_diff_image does.
inline comparison compare_rgb(const rgb_image& expected, const rgb_image& actual, double tolerance,
                              const std::string& diff_path = {}) {
    comparison c;
    c.same_size = expected.width == actual.width && expected.height == actual.height &&
                  expected.pixels.size() == actual.pixels.size() && !expected.pixels.empty();
    if (!c.same_size) return c;
    double sum = 0;
    for (std::size_t i = 0; i < expected.pixels.size(); ++i) {
        const double d = double(expected.pixels[i]) - double(actual.pixels[i]);
        sum += d * d;
    }
    c.rms = std::sqrt(sum / double(expected.pixels.size()));
    if (c.rms > tolerance && !diff_path.empty()) {
        rgb_image diff = expected;
        for (std::size_t i = 0; i < diff.pixels.size(); ++i) {
            const int d = std::abs(int(expected.pixels[i]) - int(actual.pixels[i]));
            diff.pixels[i] = static_cast<unsigned char>(std::min(255, 10 * d));
        }
        write_png(diff_path, diff);
    }
    return c;
}

}  // namespace test_support
