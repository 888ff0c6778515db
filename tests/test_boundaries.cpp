// SPDX-License-Identifier: GPL-3.0-or-later
// Boundaries: each test sits where a threshold, a limit, a rule's order or an encoder field
// decides, on both sides of it, so that moving the boundary by one fails a test. The numeric
// ones compare with independent mpmath references (tests/data/make_*.py beside their CSV).
#include "pendulum/bessel_series.hpp"
#include "pendulum/exact.hpp"
#include "plot/frames.hpp"
#include "plot/gif.hpp"
#include "plot/handles.hpp"
#include "plot/layout.hpp"
#include "plot/legend.hpp"
#include "plot/output.hpp"
#include "plot/ticks.hpp"
#include "png_image.hpp"
#include "rgb24_image.hpp"
#include "process.hpp"
#include "reference.hpp"

#include <cairo.h>
#include <gif_lib.h>
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::temp_dir;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// ---------------------------------------------------------------------------------------
// Numbers: the Jacobi functions' Maclaurin branch and the Bessel power series' stop.

TEST(Boundaries, ExactThetaAtTheZeroCrossing) {
    // theta(s) just before s = 1/4, where sn is taken at u = K (1 - 4 s) from 3e-9 to 3e-4:
    // either side of the Maclaurin threshold |u| = 1e-8 and of 1e-4. The library's argument
    // K (1 - 4 s) carries the rounding of K and of k (an ulp each), so a few ulps of theta.
    const auto rows = test_support::read_reference("zero_crossing.csv");
    ASSERT_EQ(rows.size(), 40u);
    double worst = 0;
    for (const auto& row : rows) {
        const pendulum::exact_solution exact(row[0]);
        const double theta = exact.theta_at_fraction(row[1]);
        const double relative = std::fabs(theta - row[2]) / std::fabs(row[2]);
        worst = std::max(worst, relative);
        EXPECT_LE(relative, 8 * std::numeric_limits<double>::epsilon())
            << "theta0 = " << row[0] << ", s = " << row[1] << ": " << theta << " against " << row[2];
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty("worst_relative_error", text);
}

namespace {

/// A row of bessel_series.csv: n, x, J_n(x) and J_n(x)/x as long doubles.
struct bessel_row {
    int n = 0;
    long double x = 0;
    long double j = 0;
    long double j_over_x = 0;
};

std::vector<bessel_row> bessel_rows() {
    const auto text = test_support::read_reference_text("bessel_series.csv");
    std::vector<bessel_row> rows;
    for (std::size_t i = 1; i < text.size(); ++i) {
        const auto& t = text[i];
        rows.push_back({std::stoi(t[0]), std::stod(t[1]), std::strtold(t[2].c_str(), nullptr),
                        std::strtold(t[3].c_str(), nullptr)});
    }
    return rows;
}

}  // namespace

TEST(Boundaries, BesselSeriesToExtendedPrecision) {
    // The series is summed in extended precision until a term is below a thousandth of its
    // epsilon: the sums hold to a few extended-precision ulps (the alternating terms of
    // J_0(4) reach 6.8 against a sum of 0.4, 17 times larger: the tolerance allows it).
    const auto rows = bessel_rows();
    ASSERT_EQ(rows.size(), 90u);
    const long double eps = std::numeric_limits<long double>::epsilon();
    for (const auto& r : rows) {
        const long double j = pendulum::bessel_j_series(r.n, r.x);
        EXPECT_LE(std::fabs(j - r.j), 64 * eps * std::fabs(r.j))
            << "J_" << r.n << "(" << static_cast<double>(r.x) << ") = " << static_cast<double>(j);
        if (r.n == 0) continue;
        const long double q = pendulum::bessel_j_over_x_series(r.n, r.x);
        EXPECT_LE(std::fabs(q - r.j_over_x), 64 * eps * std::fabs(r.j_over_x))
            << "J_" << r.n << "(x)/x at " << static_cast<double>(r.x);
    }
}

// ---------------------------------------------------------------------------------------
// Plot rules: tick labels, the legend's spot and what it must keep clear of.

TEST(Boundaries, ScientificTickLabelsFrom1e5AndBelow1e2) {
    // Plain below 1e5, m×10^e from 1e5 on; plain down to 0.01, m×10^e below it.
    const auto plain = plot::format_linear_labels({0, 50000}, 50000);
    EXPECT_EQ(plain.back(), "50000");
    const auto large = plot::format_linear_labels({0, 100000}, 100000);
    EXPECT_TRUE(has(large.back(), "10<sup>5</sup>")) << large.back();
    const auto hundredth = plot::format_linear_labels({0, 0.01}, 0.01);
    EXPECT_EQ(hundredth.back(), "0.01");
    const auto small = plot::format_linear_labels({0, 0.005}, 0.005);
    EXPECT_TRUE(has(small.back(), "10<sup>\u22123</sup>")) << small.back();
}

namespace {

/// The eight spots legend_inside tries, by their place in the axes.
enum class spot { top_right, top_left, bottom_right, bottom_left, top_middle, bottom_middle, centre_right, centre_left };

/// Where a legend box stands in the axes area: left, middle or right; top, centre or bottom.
spot spot_of(const plot::rect& box, const plot::rect& area) {
    const double cx = box.x + 0.5 * box.w - (area.x + 0.5 * area.w);
    const double cy = box.y + 0.5 * box.h - (area.y + 0.5 * area.h);
    const int col = std::fabs(cx) < 1e-9 ? 1 : (cx < 0 ? 0 : 2);
    const int row = std::fabs(cy) < 1e-9 ? 1 : (cy < 0 ? 0 : 2);
    static constexpr spot table[3][3] = {{spot::top_left, spot::top_middle, spot::top_right},
                                         {spot::centre_left, spot::top_middle, spot::centre_right},
                                         {spot::bottom_left, spot::bottom_middle, spot::bottom_right}};
    if (row == 1 && col == 1) throw std::runtime_error("a legend in the middle of the axes");
    return table[row][col];
}

/// The centre of a spot's box for a legend of w x h in area, its inset as legend_inside's.
std::pair<double, double> centre_of(spot s, const plot::rect& area, double w, double h, const plot::theme& th) {
    const double inset = th.tick_length_pt + 72.0 / 25.4 - 0.5 * th.padding_pt;
    const double left = area.x + inset + 0.5 * w;
    const double right = area.x + area.w - inset - 0.5 * w;
    const double middle = area.x + 0.5 * area.w;
    const double top = area.y + inset + 0.5 * h;
    const double bottom = area.y + area.h - inset - 0.5 * h;
    const double centre = area.y + 0.5 * area.h;
    switch (s) {
        case spot::top_right: return {right, top};
        case spot::top_left: return {left, top};
        case spot::bottom_right: return {right, bottom};
        case spot::bottom_left: return {left, bottom};
        case spot::top_middle: return {middle, top};
        case spot::bottom_middle: return {middle, bottom};
        case spot::centre_right: return {right, centre};
        case spot::centre_left: return {left, centre};
    }
    return {0, 0};
}

}  // namespace

TEST(Boundaries, LegendTakesTheFirstFreeSpotInItsOrder) {
    // Top right first, then top left, the bottom corners, the middles of the top and bottom,
    // the middles of the sides: each spot taken once the spots before it hold a data point.
    const std::vector<spot> order = {spot::top_right,  spot::top_left,      spot::bottom_right, spot::bottom_left,
                                     spot::top_middle, spot::bottom_middle, spot::centre_right, spot::centre_left};
    const plot::theme th;
    plot::legend_layout lg;
    lg.entries = {0};
    lg.w = 40;
    lg.h = 20;
    plot::panel_geometry g;
    g.area = {10, 20, 200, 150};
    for (std::size_t blocked = 0; blocked <= order.size(); ++blocked) {
        plot::panel p;
        p.data.push_back(plot::series{.label = "a", .line = plot::line_style::none,
                                      .marker = plot::marker_style::open_circle});
        g.dev.assign(1, plot::device_series{});
        for (std::size_t i = 0; i < blocked; ++i) {
            const auto [x, y] = centre_of(order[i], g.area, lg.w, lg.h, th);
            g.dev[0].x.push_back(x);
            g.dev[0].y.push_back(y);
        }
        const auto box = plot::legend_inside(p, lg, g, th);
        if (blocked == order.size()) {
            EXPECT_FALSE(box.has_value()) << "every spot holds data";
            break;
        }
        ASSERT_TRUE(box.has_value()) << blocked;
        EXPECT_EQ(static_cast<int>(spot_of(*box, g.area)), static_cast<int>(order[blocked])) << "with " << blocked
                                                                                               << " spots blocked";
    }
}

TEST(Boundaries, WhatMovesBetweenFramesDoesNotMoveTheLegend) {
    // A line across the legend's box counts; the same line marked as an animation's overlay
    // (it moves from frame to frame) does not, so the legend stays put in every frame.
    const plot::rect box{50, 50, 40, 20};
    std::vector<plot::series> data(1);
    std::vector<plot::device_series> dev(1);
    dev[0].x = {0, 200};
    dev[0].y = {60, 60};
    EXPECT_EQ(plot::overlap(box, data, dev, 1.6), 1);
    data[0].overlay = true;
    EXPECT_EQ(plot::overlap(box, data, dev, 1.6), 0);
    // Markers too: counted where they are still, not where they move.
    data[0] = plot::series{.line = plot::line_style::none, .marker = plot::marker_style::filled_circle};
    EXPECT_EQ(plot::overlap(box, data, dev, 1.6), 0) << "both points lie outside the box";
    dev[0].x = {70};
    dev[0].y = {60};
    EXPECT_EQ(plot::overlap(box, data, dev, 1.6), 1);
    data[0].overlay = true;
    EXPECT_EQ(plot::overlap(box, data, dev, 1.6), 0);
}

TEST(Boundaries, AMarkerCountsAsFarAsItsRadius) {
    // A marker's centre outside the box but within its radius of it covers the box's edge.
    const plot::rect box{50, 50, 40, 20};
    const std::vector<plot::series> data = {
        plot::series{.line = plot::line_style::none, .marker = plot::marker_style::open_circle}};
    std::vector<plot::device_series> dev(1);
    dev[0].x = {48.5, 91.5, 70, 70};
    dev[0].y = {60, 60, 48.5, 71.5};
    EXPECT_EQ(plot::overlap(box, data, dev, 1.6), 4);
    EXPECT_EQ(plot::overlap(box, data, dev, 1.4), 0);
}

// ---------------------------------------------------------------------------------------
// Encoders, read back with their own libraries: a PNG's colour type and palette, a GIF's loop.

namespace {

using test_support::rgb24;

/// What libpng reads from a PNG's header: its format flags and the entries of its palette.
struct png_header {
    png_uint_32 format = 0;
    png_uint_32 colormap_entries = 0;
};

png_header read_header(const std::string& png) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, png.data(), png.size())) throw std::runtime_error("not a PNG");
    const png_header h{image.format, image.colormap_entries};
    png_image_free(&image);
    return h;
}

/// n distinct colours, none of them grey.
std::vector<std::uint32_t> colours(int n) {
    std::vector<std::uint32_t> out;
    for (int i = 0; i < n; ++i) out.push_back(0x200000u * static_cast<std::uint32_t>(i % 8) + 0x000100u * static_cast<std::uint32_t>(i / 8) + 0x40u);
    return out;
}

void expect_same_pixels(const std::string& png, const std::vector<std::uint32_t>& pixels) {
    const auto decoded = test_support::decode_rgb(png);
    ASSERT_EQ(decoded.pixels.size(), pixels.size() * 3);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const std::uint32_t got = (std::uint32_t{decoded.pixels[3 * i]} << 16) |
                                  (std::uint32_t{decoded.pixels[3 * i + 1]} << 8) | decoded.pixels[3 * i + 2];
        ASSERT_EQ(got, pixels[i]) << "pixel " << i;
    }
}

}  // namespace

TEST(Boundaries, PngPaletteHoldsUpTo256Colours) {
    std::vector<unsigned char> scratch;
    // 256 colours: a palette of 256 entries.
    auto pixels = colours(256);
    auto png = plot::png_of_pixels(rgb24(pixels, 16), 72, scratch);
    auto h = read_header(png);
    EXPECT_TRUE(h.format & PNG_FORMAT_FLAG_COLORMAP) << "256 colours fit a palette";
    EXPECT_EQ(h.colormap_entries, 256u);
    expect_same_pixels(png, pixels);
    // 257: RGB.
    pixels = colours(257);
    pixels.resize(272, pixels.front());
    png = plot::png_of_pixels(rgb24(pixels, 16), 72, scratch);
    h = read_header(png);
    EXPECT_FALSE(h.format & PNG_FORMAT_FLAG_COLORMAP) << "257 colours do not fit a palette";
    EXPECT_TRUE(h.format & PNG_FORMAT_FLAG_COLOR);
    expect_same_pixels(png, pixels);
}

TEST(Boundaries, PngPaletteOfAnImageStartingWithBlackOrWhite) {
    // The palette pass remembers the last pixel: no pixel value may stand for "none yet".
    std::vector<unsigned char> scratch;
    for (const std::uint32_t first : {0x000000u, 0xffffffu, 0x0072b2u}) {
        const std::vector<std::uint32_t> pixels = {first, 0xd55e00u, first, 0x0072b2u, 0xd55e00u, first, 0xffffffu, 0x000000u};
        const auto png = plot::png_of_pixels(rgb24(pixels, 4), 72, scratch);
        const auto h = read_header(png);
        EXPECT_TRUE(h.format & PNG_FORMAT_FLAG_COLORMAP);
        EXPECT_EQ(h.colormap_entries, 4u) << "first pixel " << std::hex << first;
        expect_same_pixels(png, pixels);
    }
}

namespace {

/// The pHYs chunk of a PNG as libpng reads it: pixels per metre on x and y, and the unit.
struct png_physical {
    png_uint_32 x = 0;
    png_uint_32 y = 0;
    int unit = -1;
};

struct png_memory {
    const std::string* bytes;
    std::size_t pos = 0;
};

void read_memory(png_structp png, png_bytep out, png_size_t n) {
    auto* in = static_cast<png_memory*>(png_get_io_ptr(png));
    if (in->pos + n > in->bytes->size()) png_error(png, "truncated");
    std::memcpy(out, in->bytes->data() + in->pos, n);
    in->pos += n;
}

/// Kept free of objects with destructors: libpng reports errors by longjmp.
bool read_physical(png_memory* in, png_physical* out) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_set_read_fn(png, in, read_memory);
    png_read_info(png, info);
    const bool found = png_get_pHYs(png, info, &out->x, &out->y, &out->unit) != 0;
    png_destroy_read_struct(&png, &info, nullptr);
    return found;
}

}  // namespace

TEST(Boundaries, PngResolutionRoundsToTheNearestPixelPerMetre) {
    // dpi / 0.0254 to the nearest whole number: 72 dpi is 2834.6 (2835), 300 dpi 11811.02 (11811).
    std::vector<unsigned char> scratch;
    const std::vector<std::uint32_t> pixels(4, 0x0072b2u);
    for (const auto& [dpi, ppm] : std::vector<std::pair<double, png_uint_32>>{{72, 2835}, {300, 11811}, {96, 3780}, {10, 394}}) {
        const std::string png = plot::png_of_pixels(rgb24(pixels, 2), dpi, scratch);
        png_memory in{&png};
        png_physical phys;
        ASSERT_TRUE(read_physical(&in, &phys)) << dpi;
        EXPECT_EQ(phys.x, ppm) << dpi << " dpi";
        EXPECT_EQ(phys.y, ppm) << dpi << " dpi";
        EXPECT_EQ(phys.unit, PNG_RESOLUTION_METER);
    }
}

namespace {

/// The application extensions of a GIF before its first frame, read with giflib: each as its
/// identifier block followed by its data sub-blocks.
std::vector<std::vector<std::string>> application_extensions(const std::string& bytes) {
    struct reader {
        const std::string* data;
        std::size_t pos = 0;
        static int read(GifFileType* g, GifByteType* buf, int n) {
            auto* self = static_cast<reader*>(g->UserData);
            n = std::min(n, static_cast<int>(self->data->size() - self->pos));
            std::memcpy(buf, self->data->data() + self->pos, static_cast<std::size_t>(n));
            self->pos += static_cast<std::size_t>(n);
            return n;
        }
    } in{&bytes};
    int error = 0;
    GifFileType* gif = DGifOpen(&in, &reader::read, &error);
    if (!gif) throw std::runtime_error("not a GIF");
    std::vector<std::vector<std::string>> out;
    if (DGifSlurp(gif) != GIF_ERROR && gif->ImageCount > 0) {
        const SavedImage& first = gif->SavedImages[0];
        for (int i = 0; i < first.ExtensionBlockCount; ++i) {
            const ExtensionBlock& b = first.ExtensionBlocks[i];
            const std::string block(reinterpret_cast<const char*>(b.Bytes), static_cast<std::size_t>(b.ByteCount));
            if (b.Function == APPLICATION_EXT_FUNC_CODE) out.push_back({block});
            if (b.Function == CONTINUE_EXT_FUNC_CODE && !out.empty()) out.back().push_back(block);
        }
    }
    DGifCloseFile(gif, &error);
    return out;
}

}  // namespace

TEST(Boundaries, GifLoopsForever) {
    plot::surface_ptr s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 8, 8));
    plot::context_ptr cr(cairo_create(s.get()));
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    cairo_surface_flush(s.get());
    plot::gif_encoder gif(8, 8, plot::gif_palette({{0, 0, 0}}, {1, 1, 1}, 4), 10);
    gif.add_frame(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
    gif.add_frame(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
    const auto apps = application_extensions(gif.finish());
    ASSERT_EQ(apps.size(), 1u);
    ASSERT_EQ(apps[0].size(), 2u) << "NETSCAPE2.0 and one data sub-block";
    EXPECT_EQ(apps[0][0], "NETSCAPE2.0");
    // Sub-block 1 (looping), then the loop count, little-endian: 0 is forever.
    EXPECT_EQ(apps[0][1], std::string("\x01\x00\x00", 3));
}

TEST(Boundaries, GifColourTableHoldsThePaletteAndTheTransparentIndex) {
    // The table has a power of two entries, at least the palette's and one more (the index
    // of unchanged pixels): 3 colours take 4 entries, 4 take 8, 127 take 128, 128 take 256.
    plot::surface_ptr s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 8, 8));
    plot::context_ptr cr(cairo_create(s.get()));
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    cairo_surface_flush(s.get());
    for (const auto& [colours, entries] : std::vector<std::pair<int, int>>{{1, 2}, {3, 4}, {4, 8}, {127, 128}, {128, 256}, {255, 256}}) {
        std::vector<plot::rgb8> palette(static_cast<std::size_t>(colours));
        for (int i = 0; i < colours; ++i) palette[static_cast<std::size_t>(i)] = {static_cast<std::uint8_t>(255 - i), 255, 255};
        plot::gif_encoder gif(8, 8, palette, 10);
        gif.add_frame(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
        gif.add_frame(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
        const std::string bytes = gif.finish();
        // The logical screen descriptor's packed byte: global table of 2^(n + 1) entries.
        ASSERT_GT(bytes.size(), 13u);
        const auto packed = static_cast<unsigned char>(bytes[10]);
        EXPECT_TRUE(packed & 0x80) << "a global colour table";
        EXPECT_EQ(2 << (packed & 7), entries) << colours << " colours";
        EXPECT_EQ(application_extensions(bytes).size(), 1u) << "giflib reads it";
    }
}

// ---------------------------------------------------------------------------------------
// The command line: every limit of a spec, N accepted and N + 1 refused naming the key and
// the limit, and nothing written; the messages' mechanics (exit codes, escapes, the list of
// commands, CLI11's messages in our case).

namespace {

std::string repeated(const std::string& item, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += (i ? ", " : "") + item;
    return out;
}

std::string panels(int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";
    return out;
}

std::string trajectory(const std::string& range) {
    return "[[panel]]\nplot = \"trajectory\"\ntheta0 = 1\nmethods = [\"exact\"]\nrange = " + range + "\n";
}

/// An animation of `frames` frames: one frame a second for `frames` seconds (the last frame
/// a second before the end, where the first follows), cut there without frames added.
std::string animation(int frames, const std::string& fps = "1") {
    return "[pendulum]\nlength_m = 1\n[animation]\nfps = " + fps + "\nduration_s = " + std::to_string(frames) +
           "\nloop = \"periods\"\n[[panel]]\nplot = \"pendulum\"\ntheta0 = 1\nmethods = [\"exact\"]\n";
}

/// One limit: the spec (and its file's stem) at the limit and just beyond it, the command
/// (SPEC and OUT replaced), and what the refusal names: the key and the limit.
struct boundary {
    std::string name;
    std::string inside;
    std::string beyond;
    std::vector<std::string> says;
    std::string args = "data SPEC -o OUT/data.csv";
    std::string inside_stem = "spec";
    std::string beyond_stem = "spec";
};

const std::string still_args = "render SPEC -f svg --dpi 10 -o OUT";
const std::string frame_args = "render SPEC -f png --dpi 10 --at 0 -o OUT";

std::vector<boundary> boundaries() {
    const std::string period = "[[panel]]\nplot = \"period\"\nmethods = [";
    const std::string orders = "[[panel]]\nplot = \"period\"\nrange = [0.1, 0.2]\nmethods = [";
    const std::string phase = "[[panel]]\nplot = \"phase\"\nmethods = [\"exact\"]\n";
    const std::string spectrum = "[[panel]]\nplot = \"spectrum\"\ntheta0 = 1\nmethods = [\"exact\"]\nharmonics = ";
    return {
        {"panels", panels(26), panels(27), {"26", "panel"}},
        {"amplitudes", phase + "theta0 = [" + repeated("1", 32) + "]\n", phase + "theta0 = [" + repeated("1", 33) + "]\n",
         {"'theta0'", "33", "32"}},
        {"starts", phase + "energy = [" + repeated("0.5", 32) + "]\n", phase + "energy = [" + repeated("0.5", 33) + "]\n",
         {"32", "start"}},
        {"methods", period + repeated("\"lowest\"", 12) + "]\n", period + repeated("\"lowest\"", 13) + "]\n",
         {"'methods'", "13", "12"}},
        // Orders of 40 on a narrow amplitude range: the iteration's cost grows fast with N.
        {"orders", orders + repeated("\"order:40\"", 10) + "]\n",
         orders + repeated("\"order:40\"", 9) + ", \"order:41\"]\n", {"401", "400"}},
        {"periods", trajectory("[0, 100]"), trajectory("[0, 100.5]"), {"'range'", "100"}},
        {"range", trajectory("[1, 1.000000000000001]"), trajectory("[1, 1]"), {"'range'"}},
        {"harmonics", spectrum + "100\n", spectrum + "101\n", {"'harmonics'", "100"}},
        {"title", "[figure]\ntitle = \"" + std::string(1000, 'x') + "\"\n" + panels(1),
         "[figure]\ntitle = \"" + std::string(1001, 'x') + "\"\n" + panels(1), {"'title'", "1001", "1000"}},
        {"name", panels(1), panels(1), {"101", "100"}, "data SPEC -o OUT/data.csv", std::string(100, 'n'),
         std::string(101, 'n')},
        {"paper-file", panels(1) + "paper_file = \"" + std::string(100, 'p') + "\"\n",
         panels(1) + "paper_file = \"" + std::string(101, 'p') + "\"\n", {"'paper_file'", "101", "100"}},
        {"frames", animation(10000), animation(10001), {"10001", "10000"}, frame_args},
        {"fps", animation(2, "120"), animation(2, "120.5"), {"'fps'", "120"}, frame_args},
    };
}

/// Runs args with SPEC a file `stem`.toml holding spec in work and OUT a new directory.
test_support::run_result run_boundary(const fs::path& work, const std::string& tag, const std::string& stem,
                                      const std::string& spec, std::string args, bool& wrote) {
    const auto dir = work / tag;
    fs::create_directories(dir / "out");
    const auto file = dir / (stem + ".toml");
    std::ofstream(file) << spec;
    const auto replace = [&](const std::string& from, const std::string& to) {
        for (std::size_t at = 0; (at = args.find(from, at)) != std::string::npos; at += to.size()) args.replace(at, from.size(), to);
    };
    replace("SPEC", "'" + file.string() + "'");
    replace("OUT", "'" + (dir / "out").string() + "'");
    const auto r = run_cli(args);
    wrote = !files_in(dir / "out").empty();
    return r;
}

}  // namespace

TEST(Boundaries, EveryLimitAcceptsNAndRefusesNPlusOne) {
    const auto work = temp_dir("boundaries-limits");
    for (const auto& b : boundaries()) {
        bool wrote = false;
        const auto in = run_boundary(work, b.name + "-inside", b.inside_stem, b.inside, b.args, wrote);
        EXPECT_EQ(in.status, 0) << b.name << " at the limit: " << in.err;
        EXPECT_TRUE(wrote) << b.name << " at the limit wrote nothing";
        const auto out = run_boundary(work, b.name + "-beyond", b.beyond_stem, b.beyond, b.args, wrote);
        EXPECT_EQ(out.status, 2) << b.name << " beyond the limit: " << out.err;
        for (const auto& s : b.says) EXPECT_TRUE(has(out.err, s)) << b.name << ": no '" << s << "' in " << out.err;
        EXPECT_FALSE(wrote) << b.name << " beyond the limit wrote something";
    }
    fs::remove_all(work);
}

namespace {

/// The text of each line of a message after the program's prefix "...error: ".
std::vector<std::string> message_lines(const std::string& err) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < err.size()) {
        const std::size_t end = std::min(err.find('\n', start), err.size());
        const std::string line = err.substr(start, end - start);
        const std::size_t at = line.find("error: ");
        lines.push_back(at == std::string::npos ? line : line.substr(at + 7));
        start = end + 1;
    }
    return lines;
}

}  // namespace

TEST(Boundaries, ControlBytesAndDelAreEscapedInMessages) {
    // Every byte below 0x20 but the line break, and DEL (0x7f), shown as \xNN; 0x20 and 0x7e as they are.
    for (const int byte : {0x01, 0x1b, 0x1f, 0x7f}) {
        const std::string word = std::string("bad") + static_cast<char>(byte) + "word";
        const auto r = run_cli(std::string("'") + word + "'");
        EXPECT_EQ(r.status, 2) << r.err;
        char shown[8];
        std::snprintf(shown, sizeof shown, "\\x%02x", byte);
        EXPECT_TRUE(has(r.err, std::string("bad") + shown + "word")) << r.err;
        EXPECT_FALSE(has(r.err, word)) << "byte " << byte << " printed raw";
    }
    const auto r = run_cli("'a ~b'");
    EXPECT_TRUE(has(r.err, "'a ~b'")) << r.err;
}

TEST(Boundaries, UnknownCommandListsEveryCommand) {
    // Every command (complete too, which --help leaves out), each named in the message for a
    // word that is none of them, and for no word at all.
    const std::vector<std::string> commands = {"eval", "trajectory", "render", "list",     "claims",
                                               "show", "plot",       "data",   "describe", "complete"};
    for (const std::string word : {"rendre", "x"}) {
        const auto r = run_cli(word);
        EXPECT_EQ(r.status, 2);
        EXPECT_TRUE(has(r.err, "'" + word + "'")) << r.err;
        for (const auto& c : commands) EXPECT_TRUE(has(r.err, c)) << c << " missing from: " << r.err;
    }
    const auto none = run_cli("");
    EXPECT_EQ(none.status, 2);
    for (const auto& c : commands) EXPECT_TRUE(has(none.err, c)) << c << " missing from: " << none.err;
}

TEST(Boundaries, ParserMessagesStartInLowerCase) {
    // CLI11's messages begin with a capital; ours do not, and its are lowercased to match
    // (an acronym such as "TOML" would stay as it is).
    for (const std::string args : {"eval --no-such-option", "eval --theta0", "trajectory --theta0 1 --samples abc",
                                   "eval --theta0 1 --theta0", "list extra words"}) {
        const auto r = run_cli(args);
        EXPECT_EQ(r.status, 2) << args;
        for (const auto& line : message_lines(r.err)) {
            if (line.empty()) continue;
            const bool capital = line[0] >= 'A' && line[0] <= 'Z' && !(line.size() > 1 && line[1] >= 'A' && line[1] <= 'Z');
            EXPECT_FALSE(capital) << args << ": " << r.err;
        }
    }
}
