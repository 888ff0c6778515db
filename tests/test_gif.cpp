// SPDX-License-Identifier: GPL-3.0-or-later
// The GIF encoder: frames, delays, looping, palette mapping and reproducible bytes,
// checked by decoding the file with giflib.
#include "plot/gif.hpp"
#include "plot/handles.hpp"

#include <cairo.h>
#include <gif_lib.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <utility>
#include <string>

namespace {

using namespace plot;

/// A white frame with a black bar at x and a blue disc.
surface_ptr frame(int x) {
    surface_ptr s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 64, 48));
    context_ptr cr(cairo_create(s.get()));
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    cairo_set_source_rgb(cr.get(), 0, 0, 0);
    cairo_rectangle(cr.get(), x, 10, 4, 20);
    cairo_fill(cr.get());
    cairo_set_source_rgb(cr.get(), 0.0, 0.447, 0.698);
    cairo_arc(cr.get(), 40, 30, 6.3, 0, 6.3);
    cairo_fill(cr.get());
    cairo_surface_flush(s.get());
    return s;
}

std::string encode(const std::vector<int>& xs, double fps) {
    gif_encoder gif(64, 48, gif_palette({{0, 0, 0}, {0.0, 0.447, 0.698}}, {1, 1, 1}, 8), fps);
    for (int x : xs) {
        auto s = frame(x);
        gif.add_frame(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
    }
    EXPECT_EQ(gif.frames(), static_cast<int>(xs.size()));
    return gif.finish();
}

/// A decoded GIF, freed on scope exit.
struct decoded {
    explicit decoded(const std::string& bytes) : data(bytes) {
        int error = 0;
        gif = DGifOpen(this, &decoded::read, &error);
        if (!gif || DGifSlurp(gif) == GIF_ERROR) throw std::runtime_error("not a GIF");
    }
    ~decoded() {
        int error = 0;
        if (gif) DGifCloseFile(gif, &error);
    }
    static int read(GifFileType* g, GifByteType* buf, int n) {
        auto* self = static_cast<decoded*>(g->UserData);
        const int left = static_cast<int>(self->data.size() - self->pos);
        n = std::min(n, left);
        std::memcpy(buf, self->data.data() + self->pos, static_cast<std::size_t>(n));
        self->pos += static_cast<std::size_t>(n);
        return n;
    }
    int delay(int i) const {
        GraphicsControlBlock gcb;
        DGifSavedExtensionToGCB(gif, i, &gcb);
        return gcb.DelayTime;
    }
    GifColorType pixel(int i, int x, int y) const {
        const SavedImage& im = gif->SavedImages[i];
        const auto& d = im.ImageDesc;
        const int index = im.RasterBits[(y - d.Top) * d.Width + (x - d.Left)];
        return gif->SColorMap->Colors[index];
    }
    std::string data;
    std::size_t pos = 0;
    GifFileType* gif = nullptr;
};

TEST(Gif, FramesDelaysAndLoop) {
    const std::string bytes = encode({5, 9, 9, 13}, 30);
    EXPECT_EQ(bytes.substr(0, 6), "GIF89a");
    const decoded g(bytes);
    ASSERT_EQ(g.gif->ImageCount, 4);
    EXPECT_EQ(g.gif->SWidth, 64);
    EXPECT_EQ(g.gif->SHeight, 48);
    // 30 frames per second in hundredths: 3, 4, 3, 3 add up to the true 13.33.
    EXPECT_EQ(g.delay(0) + g.delay(1) + g.delay(2), 10);
    EXPECT_EQ(g.delay(0) + g.delay(1) + g.delay(2) + g.delay(3), 13);
    // The loop extension, before the first frame.
    EXPECT_NE(bytes.find("NETSCAPE2.0"), std::string::npos);
    EXPECT_LT(bytes.find("NETSCAPE2.0"), bytes.find(','));
    // The first frame is whole; later ones only what changed (the bar), an unchanged one a pixel.
    EXPECT_EQ(g.gif->SavedImages[0].ImageDesc.Width, 64);
    EXPECT_EQ(g.gif->SavedImages[1].ImageDesc.Left, 5);
    EXPECT_EQ(g.gif->SavedImages[1].ImageDesc.Width, 8);
    EXPECT_EQ(g.gif->SavedImages[2].ImageDesc.Width * g.gif->SavedImages[2].ImageDesc.Height, 1);
}

TEST(Gif, PixelsMapToThePalette) {
    const decoded g(encode({5, 9}, 25));
    const auto white = g.pixel(0, 1, 1);
    EXPECT_EQ(white.Red + white.Green + white.Blue, 3 * 255);
    const auto black = g.pixel(0, 6, 20);
    EXPECT_EQ(black.Red + black.Green + black.Blue, 0);
    const auto blue = g.pixel(0, 40, 30);
    EXPECT_EQ(blue.Red, 0);
    EXPECT_EQ(blue.Green, 114);
    EXPECT_EQ(blue.Blue, 178);
    // The second frame's bar.
    const auto bar = g.pixel(1, 10, 20);
    EXPECT_EQ(bar.Red + bar.Green + bar.Blue, 0);
    EXPECT_EQ(g.delay(0), 4);
}

TEST(Gif, SameFramesSameBytes) { EXPECT_EQ(encode({1, 2, 3}, 30), encode({1, 2, 3}, 30)); }

TEST(Gif, PreviousFrameKeptAgainstTheStillPart) {
    // The still part: the frame without the bar (white, the disc). Kept against it, the
    // previous frame is the bar's pixels only, and the bytes are those of a whole copy,
    // also for a part primed with the frame before it.
    surface_ptr still(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 64, 48));
    {
        context_ptr cr(cairo_create(still.get()));
        cairo_set_source_surface(cr.get(), frame(0).get(), 0, 0);
        cairo_paint(cr.get());
        cairo_set_source_rgb(cr.get(), 1, 1, 1);
        cairo_rectangle(cr.get(), 0, 10, 4, 20);
        cairo_fill(cr.get());
    }
    cairo_surface_flush(still.get());
    const std::vector<int> xs = {5, 9, 9, 13, 34, 38, 20, 61};
    const auto palette = gif_palette({{0, 0, 0}, {0.0, 0.447, 0.698}}, {1, 1, 1}, 8);
    for (const bool primed : {false, true}) {
        const auto run = [&](bool against) {
            gif_encoder gif(64, 48, palette, 30);
            if (against) gif.keep_against(cairo_image_surface_get_data(still.get()), cairo_image_surface_get_stride(still.get()));
            if (primed) {
                auto s = frame(50);
                gif.prime(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
            }
            std::size_t most_kept = 0;
            for (int x : xs) {
                auto s = frame(x);
                gif.add_frame(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
                most_kept = std::max(most_kept, gif.kept_pixels());
            }
            return std::pair{gif.finish(), most_kept};
        };
        const auto [whole, whole_kept] = run(false);
        const auto [against, kept] = run(true);
        EXPECT_EQ(against, whole) << (primed ? "primed" : "");
        EXPECT_EQ(whole_kept, 64u * 48u);
        // The bar, 4 x 20 pixels, and where it crosses the disc; not the frame.
        EXPECT_GE(kept, 4u * 20u);
        EXPECT_LE(kept, 4u * 20u + 8u * 20u);
    }
    gif_encoder late(64, 48, palette, 30);
    auto s = frame(1);
    late.add_frame(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
    EXPECT_THROW(late.keep_against(cairo_image_surface_get_data(still.get()), cairo_image_surface_get_stride(still.get())),
                 std::logic_error);
}

/// A white frame with a grey bar and an anti-aliased disc at x, whose edges take many shades.
surface_ptr soft_frame(double x) {
    surface_ptr s(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 64, 48));
    context_ptr cr(cairo_create(s.get()));
    cairo_set_source_rgb(cr.get(), 1, 1, 1);
    cairo_paint(cr.get());
    cairo_set_source_rgb(cr.get(), 0.5, 0.5, 0.5);
    cairo_rectangle(cr.get(), 2, 2, 60, 3);
    cairo_fill(cr.get());
    cairo_set_source_rgb(cr.get(), 0.0, 0.447, 0.698);
    cairo_arc(cr.get(), x, 24 + 0.37 * x, 9.3, 0, 6.3);
    cairo_fill(cr.get());
    cairo_set_source_rgb(cr.get(), 0, 0, 0);
    cairo_set_line_width(cr.get(), 1.3);
    cairo_move_to(cr.get(), 4, 40);
    cairo_line_to(cr.get(), x, 10 + 0.2 * x);
    cairo_stroke(cr.get());
    cairo_surface_flush(s.get());
    return s;
}

/// Frame i of a decoded GIF as shown: the frames before it drawn under it, its transparent
/// pixels keeping theirs.
std::vector<std::uint32_t> shown(const decoded& g, int frame) {
    std::vector<std::uint32_t> screen(static_cast<std::size_t>(g.gif->SWidth * g.gif->SHeight));
    for (int i = 0; i <= frame; ++i) {
        const SavedImage& im = g.gif->SavedImages[i];
        GraphicsControlBlock gcb;
        DGifSavedExtensionToGCB(g.gif, i, &gcb);
        const auto& d = im.ImageDesc;
        for (int y = 0; y < d.Height; ++y) {
            for (int x = 0; x < d.Width; ++x) {
                const int index = im.RasterBits[y * d.Width + x];
                if (index == gcb.TransparentColor) continue;
                const GifColorType c = g.gif->SColorMap->Colors[index];
                screen[static_cast<std::size_t>((d.Top + y) * g.gif->SWidth + d.Left + x)] =
                    static_cast<std::uint32_t>(c.Red) << 16 | static_cast<std::uint32_t>(c.Green) << 8 | c.Blue;
            }
        }
    }
    return screen;
}

TEST(Gif, EveryFrameShowsWhatItShowsAlone) {
    // Pixels whose colour changed but whose palette colour did not are left transparent: each
    // frame of the animation still shows what the frame encoded alone shows, no more than
    // the changed pixels are stored, and fewer than the pixels whose colour changed.
    const auto palette = gif_palette({{0, 0, 0}, {0.0, 0.447, 0.698}, {0.5, 0.5, 0.5}}, {1, 1, 1}, 8);
    std::vector<double> xs;
    for (int i = 0; i < 24; ++i) xs.push_back(14 + 1.37 * i);
    gif_encoder gif(64, 48, palette, 30);
    std::size_t changed = 0;  // pixels whose colour differs from the previous frame's
    std::vector<std::uint32_t> before;
    for (double x : xs) {
        auto s = soft_frame(x);
        const auto* data = cairo_image_surface_get_data(s.get());
        const int stride = cairo_image_surface_get_stride(s.get());
        std::vector<std::uint32_t> now;
        for (int y = 0; y < 48; ++y) {
            const auto* row = reinterpret_cast<const std::uint32_t*>(data + y * stride);
            now.insert(now.end(), row, row + 64);
        }
        if (!before.empty()) {
            for (std::size_t k = 0; k < now.size(); ++k) changed += now[k] != before[k];
        }
        before = now;
        gif.add_frame(data, stride);
    }
    const decoded g(gif.finish());
    ASSERT_EQ(g.gif->ImageCount, static_cast<int>(xs.size()));
    std::size_t stored = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        gif_encoder alone(64, 48, palette, 30);
        auto s = soft_frame(xs[i]);
        alone.add_frame(cairo_image_surface_get_data(s.get()), cairo_image_surface_get_stride(s.get()));
        const decoded one(alone.finish());
        EXPECT_TRUE(shown(g, static_cast<int>(i)) == shown(one, 0)) << "frame " << i;
        if (i == 0) continue;
        const SavedImage& im = g.gif->SavedImages[i];
        GraphicsControlBlock gcb;
        DGifSavedExtensionToGCB(g.gif, static_cast<int>(i), &gcb);
        for (int k = 0; k < im.ImageDesc.Width * im.ImageDesc.Height; ++k) stored += im.RasterBits[k] != gcb.TransparentColor;
    }
    EXPECT_GT(stored, 0u);
    EXPECT_LT(stored, changed);
}

TEST(Gif, PaletteHasShadesAndStaysSmall) {
    const auto p = gif_palette({{0, 0, 0}, {0.0, 0.447, 0.698}, {0.835, 0.369, 0.0}}, {1, 1, 1}, 16);
    EXPECT_EQ(p[0].r, 255);
    EXPECT_EQ(p[1].r + p[1].g + p[1].b, 0);
    EXPECT_LE(p.size(), 256u);
    EXPECT_GE(p.size(), 3u * 15);
    const auto many = gif_palette(std::vector<rgb>(40, rgb{0.5, 0.2, 0.1}), {1, 1, 1}, 64);
    EXPECT_LE(many.size(), 256u);
}

TEST(Gif, BadArguments) {
    EXPECT_THROW(gif_encoder(0, 10, {{0, 0, 0}}, 30), std::invalid_argument);
    EXPECT_THROW(gif_encoder(10, 10, {}, 30), std::invalid_argument);
    EXPECT_THROW(gif_encoder(10, 10, {{0, 0, 0}}, 0), std::invalid_argument);
    gif_encoder g(4, 4, {{0, 0, 0}}, 30);
    g.finish();
    EXPECT_THROW(g.finish(), std::logic_error);
}

}  // namespace
