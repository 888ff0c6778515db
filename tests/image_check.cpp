// SPDX-License-Identifier: GPL-3.0-or-later
// Image checks for the shell tests, on PNG files (poppler's, librsvg's, ghostscript's, ours):
//
//   image_check frames PAGE.png DPI [MIN_MM]
//     The frames of the plots on a rasterised page, one line each: "left top right bottom"
//     in millimetres from the page's top left corner, ordered from the top. A frame is four
//     straight dark lines at least MIN_MM long (default 15) that meet at their ends; each
//     side is measured at its outer edge, so that frames drawn with the same stroke compare
//     exactly whatever touches them from inside.
//   image_check rms REFERENCE.png OTHER.png [BLOCK [DIFF.png]]
//     The RMS of the RGB differences (0..255), as the baseline tests compute it. OTHER may
//     be k times larger (k whole, a PNG at k times the dpi): it is averaged over k x k
//     blocks first. With BLOCK, both are then averaged over BLOCK x BLOCK blocks, so that
//     readers' different anti-aliasing of edges averages out and layout remains. Sizes that differ by a pixel (readers round the page differently) are
//     compared on the part both have. DIFF.png gets the differences, ten times amplified.
//   image_check alpha IMAGE.png
//     The opacity (0..255) of the top left pixel.
#include "png_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

struct run {
    int x0, x1;  // columns, inclusive
    int y0, y1;  // rows, inclusive
};

std::string slurp(const char* path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

[[noreturn]] void not_png(const char* path) {
    std::fprintf(stderr, "image_check: %s is not a PNG\n", path);
    std::exit(2);
}

/// The image averaged over k x k blocks (a partial block at the end is left out).
test_support::rgb_image average(const test_support::rgb_image& b, unsigned k) {
    if (k <= 1) return b;
    test_support::rgb_image small;
    small.width = b.width / k;
    small.height = b.height / k;
    small.pixels.assign(static_cast<std::size_t>(small.width) * small.height * 3, 0);
    for (unsigned y = 0; y < small.height; ++y) {
        for (unsigned x = 0; x < small.width; ++x) {
            for (unsigned c = 0; c < 3; ++c) {
                unsigned sum = 0;
                for (unsigned j = 0; j < k; ++j) {
                    for (unsigned i = 0; i < k; ++i) {
                        sum += b.pixels[(static_cast<std::size_t>(y * k + j) * b.width + x * k + i) * 3 + c];
                    }
                }
                small.pixels[(static_cast<std::size_t>(y) * small.width + x) * 3 + c] =
                    static_cast<unsigned char>((sum + k * k / 2) / (k * k));
            }
        }
    }
    return small;
}

int rms(const char* reference, const char* other, unsigned block, const char* diff_path) {
    auto a = test_support::decode_rgb(slurp(reference));
    if (a.width == 0) not_png(reference);
    auto b = test_support::decode_rgb(slurp(other));
    if (b.width == 0) not_png(other);
    b = average(b, (b.width + a.width / 2) / a.width);
    a = average(a, block);
    b = average(b, block);
    if (std::max(a.width, b.width) - std::min(a.width, b.width) > 1 ||
        std::max(a.height, b.height) - std::min(a.height, b.height) > 1) {
        std::fprintf(stderr, "image_check: %s is %ux%u, %s %ux%u\n", reference, a.width, a.height, other, b.width,
                     b.height);
        return 2;
    }
    const unsigned w = std::min(a.width, b.width);
    const unsigned h = std::min(a.height, b.height);
    double sum = 0;
    test_support::rgb_image diff;
    diff.width = w;
    diff.height = h;
    diff.pixels.resize(static_cast<std::size_t>(w) * h * 3);
    for (unsigned y = 0; y < h; ++y) {
        for (unsigned x = 0; x < w * 3; ++x) {
            const double d = double(a.pixels[static_cast<std::size_t>(y) * a.width * 3 + x]) -
                             double(b.pixels[static_cast<std::size_t>(y) * b.width * 3 + x]);
            sum += d * d;
            diff.pixels[static_cast<std::size_t>(y) * w * 3 + x] =
                static_cast<unsigned char>(std::min(255.0, 10 * std::fabs(d)));
        }
    }
    if (diff_path) test_support::write_png(diff_path, diff);
    std::printf("%.3f\n", std::sqrt(sum / (3.0 * w * h)));
    return 0;
}

int alpha(const char* path) {
    const std::string bytes = slurp(path);
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) not_png(path);
    image.format = PNG_FORMAT_RGBA;
    std::vector<unsigned char> pixels(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) not_png(path);
    std::printf("%d\n", pixels.at(3));
    return 0;
}

/// Straight dark lines at least min_len long, across (vertical: columns) or along (rows).
/// Neighbouring columns (rows) whose runs overlap by half are one line: x0..x1 across it,
/// y0..y1 along it (for rows the roles swap).
std::vector<run> lines_of(const test_support::grey_image& image, int min_len, bool vertical) {
    const int across = static_cast<int>(vertical ? image.width : image.height);
    const int along = static_cast<int>(vertical ? image.height : image.width);
    const auto dark = [&](int a, int b) {
        const unsigned x = static_cast<unsigned>(vertical ? a : b);
        const unsigned y = static_cast<unsigned>(vertical ? b : a);
        return image.at(x, y) < 128;
    };
    std::vector<run> done;
    std::vector<run> open;
    for (int a = 0; a < across; ++a) {
        std::vector<run> next;
        for (int b = 0; b < along;) {
            if (!dark(a, b)) {
                ++b;
                continue;
            }
            int end = b;
            while (end + 1 < along && dark(a, end + 1)) ++end;
            if (end - b + 1 >= min_len) {
                run r{a, a, b, end};
                auto it = std::find_if(open.begin(), open.end(), [&](const run& o) {
                    const int common = std::min(o.y1, r.y1) - std::max(o.y0, r.y0);
                    return common >= std::min(o.y1 - o.y0, r.y1 - r.y0) / 2;
                });
                if (it != open.end()) {
                    r.x0 = it->x0;
                    r.y0 = std::min(r.y0, it->y0);
                    r.y1 = std::max(r.y1, it->y1);
                    open.erase(it);
                }
                next.push_back(r);
            }
            b = end + 1;
        }
        for (const auto& o : open) done.push_back(o);
        open = std::move(next);
    }
    for (const auto& o : open) done.push_back(o);
    return done;
}

int frames(const char* path, double dpi, double min_mm) {
    const auto image = test_support::decode(slurp(path));
    if (image.width == 0) not_png(path);
    const double mm = dpi / 25.4;  // pixels per millimetre
    const int min_len = static_cast<int>(min_mm * mm);
    const auto columns = lines_of(image, min_len, true);
    const auto rows = lines_of(image, min_len, false);
    // A frame: a left and a right line, and a top and a bottom line between their ends.
    // Each side is taken at its outer edge: curves and markers that touch the frame from
    // inside, or sit on its corners, do not move it there.
    const int slack = static_cast<int>(std::ceil(0.5 * mm));
    struct box {
        double left, top, right, bottom;
    };
    std::vector<box> boxes;
    std::vector<bool> used(columns.size(), false);
    const auto near = [&](int a, int b) { return std::abs(a - b) <= slack; };
    for (std::size_t i = 0; i < columns.size(); ++i) {
        const run& l = columns[i];
        for (std::size_t j = 0; j < columns.size() && !used[i]; ++j) {
            const run& r = columns[j];
            if (used[j] || r.x0 <= l.x1 + 1) continue;
            const run* top = nullptr;
            const run* bottom = nullptr;
            for (const auto& h : rows) {
                // Rows: x0..x1 are rows, y0..y1 columns.
                if (!near(h.y0, l.x0) || !near(h.y1, r.x1)) continue;
                if (near(h.x0, std::max(l.y0, r.y0)) || near(h.x0, std::min(l.y0, r.y0))) top = &h;
                if (near(h.x1, std::min(l.y1, r.y1)) || near(h.x1, std::max(l.y1, r.y1))) bottom = &h;
            }
            if (!top || !bottom) continue;
            used[i] = used[j] = true;
            boxes.push_back({l.x0 / mm, top->x0 / mm, (r.x1 + 1) / mm, (bottom->x1 + 1) / mm});
        }
    }
    std::sort(boxes.begin(), boxes.end(), [](const box& a, const box& b) { return a.top < b.top; });
    for (const auto& b : boxes) std::printf("%.3f %.3f %.3f %.3f\n", b.left, b.top, b.right, b.bottom);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "frames" && argc >= 4) return frames(argv[2], std::atof(argv[3]), argc > 4 ? std::atof(argv[4]) : 15.0);
    if (mode == "rms" && argc >= 4 && argc <= 6) {
        const int block = argc > 4 ? std::atoi(argv[4]) : 1;
        return rms(argv[2], argv[3], static_cast<unsigned>(std::max(block, 1)), argc > 5 ? argv[5] : nullptr);
    }
    if (mode == "alpha" && argc == 3) return alpha(argv[2]);
    std::fprintf(stderr, "usage: image_check frames PAGE.png DPI [MIN_MM] | rms REFERENCE.png OTHER.png [BLOCK [DIFF.png]] | alpha IMAGE.png\n");
    return 2;
}
