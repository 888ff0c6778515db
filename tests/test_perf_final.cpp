// SPDX-License-Identifier: GPL-3.0-or-later
// Performance without changing a pixel: Pango sorts the faces of the families a theme
// names, not every installed font, and lays out a text they do not cover over all fonts.
#include "plot/gif.hpp"
#include "plot/text.hpp"

#include "process.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using test_support::run_cli;
using test_support::slurp;
using test_support::temp_dir;

namespace {

/// The themes' font families.
const std::vector<std::string> theme_families = {"CMU Serif, DejaVu Math TeX Gyre", "CMU Sans Serif, DejaVu Sans"};

/// A context shaping as the program does (points, no hinting) over `map`.
plot::gobject_ptr<PangoContext> shaping(PangoFontMap* map) {
    plot::gobject_ptr<PangoContext> context(pango_font_map_create_context(map));
    pango_context_set_matrix(context.get(), nullptr);
    pango_context_set_round_glyph_positions(context.get(), FALSE);
    pango_cairo_context_set_resolution(context.get(), 72.0);
    plot::font_options_ptr options(cairo_font_options_create());
    cairo_font_options_set_hint_style(options.get(), CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
    pango_cairo_context_set_font_options(context.get(), options.get());
    return context;
}

/// What a layout of markup in `family` at `size` points is made of: per run its font file
/// and size, and per glyph its id, advance and offsets.
std::string laid_out(PangoContext* context, const std::string& family, const std::string& markup, double size) {
    plot::gobject_ptr<PangoLayout> layout(pango_layout_new(context));
    plot::font_description_ptr font(pango_font_description_new());
    pango_font_description_set_family(font.get(), family.c_str());
    pango_font_description_set_size(font.get(), static_cast<int>(size * PANGO_SCALE));
    pango_layout_set_font_description(layout.get(), font.get());
    pango_layout_set_markup(layout.get(), markup.c_str(), -1);
    std::string out;
    PangoLayoutIter* it = pango_layout_get_iter(layout.get());
    do {
        PangoLayoutRun* run = pango_layout_iter_get_run_readonly(it);
        if (!run) continue;
        plot::font_description_ptr d(pango_font_describe_with_absolute_size(run->item->analysis.font));
        char* name = pango_font_description_to_string(d.get());
        out += std::string("[") + name + "]";
        g_free(name);
        for (int g = 0; g < run->glyphs->num_glyphs; ++g) {
            const PangoGlyphInfo& info = run->glyphs->glyphs[g];
            out += " " + std::to_string(info.glyph) + "/" + std::to_string(info.geometry.width) + "/" +
                   std::to_string(info.geometry.x_offset) + "/" + std::to_string(info.geometry.y_offset);
        }
    } while (pango_layout_iter_next_run(it));
    pango_layout_iter_free(it);
    int w = 0, h = 0;
    pango_layout_get_size(layout.get(), &w, &h);
    return out + " size " + std::to_string(w) + "x" + std::to_string(h) + " baseline " +
           std::to_string(pango_layout_get_baseline(layout.get()));
}

/// Texts of the figures' kinds: Latin, Greek, italic and bold, scripts, accents, the
/// mathematical italic forms, digits and signs.
const std::vector<std::string> covered_texts = {
    "Period T/T<sub>0</sub> against the amplitude",
    "<i>\u03b8</i><sub>0</sub> = 3\u03c0/4, <i>\u03c9</i>, <i>\u03d1</i>",
    "<b>(a)</b> relative error \u2212 20 %",
    "<i>e\u0307</i> <span style=\"normal\">\U0001d703</span> \u00a0\u0302",
    "exact, lowest, first, second: 1.5 \u00d7 10<sup>\u22123</sup>",
};

}  // namespace

// The named faces cover the figures' texts; a character only another font has, or markup
// naming a family of its own, is not theirs.
TEST(PerfFonts, NamedFacesCoverTheirTextsOnly) {
    for (const std::string& family : theme_families) {
        EXPECT_TRUE(plot::named_fonts_cover(family, "Period T/T0, \u03b8 = 3\u03c0/4", nullptr)) << family;
        // One character beyond them is enough: U+4E2D is in no named face.
        EXPECT_FALSE(plot::named_fonts_cover(family, "Period \u4e2d", nullptr)) << family;
        EXPECT_FALSE(plot::named_fonts_cover(family, "\u4e2d", nullptr)) << family;
        PangoAttrList* attrs = nullptr;
        char* text = nullptr;
        ASSERT_TRUE(pango_parse_markup("<span font_family=\"DejaVu Serif\">Period</span>", -1, 0, &attrs, &text,
                                       nullptr, nullptr));
        EXPECT_FALSE(plot::named_fonts_cover(family, text, attrs)) << family;
        pango_attr_list_unref(attrs);
        g_free(text);
        ASSERT_TRUE(pango_parse_markup("<span font=\"12\"><i>Period</i></span>", -1, 0, &attrs, &text, nullptr, nullptr));
        EXPECT_TRUE(plot::named_fonts_cover(family, text, attrs)) << family;  // a size alone names no family
        pango_attr_list_unref(attrs);
        g_free(text);
    }
    // U+2605 BLACK STAR: the slides' DejaVu Sans has it, the paper's faces do not.
    EXPECT_TRUE(plot::named_fonts_cover(theme_families[1], "\u2605", nullptr));
    EXPECT_FALSE(plot::named_fonts_cover(theme_families[0], "\u2605", nullptr));
    // A family installed nowhere, or one whose name fontconfig alone compares: all fonts serve.
    EXPECT_FALSE(plot::named_fonts_cover("No Such Family Anywhere", "Period", nullptr));
    EXPECT_FALSE(plot::named_fonts_cover("CMU Serif, Caf\u00e9 Sans", "Period", nullptr));
    EXPECT_EQ(plot::named_font_map("No Such Family Anywhere"), plot::thread_font_map());
}

// Over the named faces a covered text is laid out glyph for glyph as over all fonts, at
// every size and style the figures use.
TEST(PerfFonts, CoveredTextsLayOutAsOverAllFonts) {
    const auto all = shaping(plot::thread_font_map());
    for (const std::string& family : theme_families) {
        const auto named = shaping(plot::named_font_map(family));
        ASSERT_NE(plot::named_font_map(family), plot::thread_font_map()) << family;
        for (const std::string& markup : covered_texts) {
            PangoAttrList* attrs = nullptr;
            char* text = nullptr;
            ASSERT_TRUE(pango_parse_markup(markup.c_str(), -1, 0, &attrs, &text, nullptr, nullptr)) << markup;
            const bool covered = plot::named_fonts_cover(family, text, attrs);
            pango_attr_list_unref(attrs);
            g_free(text);
            if (!covered) continue;  // the slides' DejaVu Sans has no mathematical italic
            for (const double size : {5.0, 7.0, 8.5, 10.0, 14.4, 24.0}) {
                EXPECT_EQ(laid_out(named.get(), family, markup, size), laid_out(all.get(), family, markup, size))
                    << family << " | " << markup << " at " << size;
            }
        }
    }
}

// Hostile labels: characters the theme's fonts lack still come from another font (no
// missing-glyph boxes): the paper theme's PDF embeds DejaVu Sans for them, which none of
// its named faces is, and without them it does not.
TEST(PerfFonts, UncoveredLabelsFallBackToOtherFonts) {
    const auto dir = temp_dir("perf-fallback");
    const auto spec = [](const std::string& title) {
        return "[figure]\ntitle = \"" + title + "\"\ncolumns = 1\n\n[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";
    };
    std::ofstream(dir / "fallback.toml") << spec("P\u00e9riod \u2192 \u2605 \u266a \u0416\u0436 \u222e \u210f");
    std::ofstream(dir / "covered.toml") << spec("P\u00e9riod \u2192 \u0416\u0436 \u222e \u210f");
    const auto r = run_cli("render fallback.toml covered.toml --theme paper -f pdf -o .", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "fallback.pdf").find("+DejaVuSans"), std::string::npos);
    EXPECT_EQ(slurp(dir / "covered.pdf").find("+DejaVuSans"), std::string::npos);
    for (const std::string& family : theme_families) {
        const auto all = shaping(plot::thread_font_map());
        const std::string star = laid_out(all.get(), family, "\u2605", 10);
        EXPECT_EQ(star.find("[CMU"), std::string::npos) << star;  // another font's glyph
        EXPECT_EQ(star.find(" 0/"), std::string::npos) << star;    // not the missing glyph
    }
    std::filesystem::remove_all(dir);
}

namespace {

/// The message check_gif_size throws, or "" if the GIF is accepted.
std::string gif_refusal(double frames, int width, int height) {
    try {
        plot::check_gif_size(frames, width, height);
    } catch (const plot::bad_input& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// A GIF's size is bounded before work: at 720p, 1080p and 4K the most frames whose bytes'
// bound (gif_bytes_bound) is within 50 MB are accepted, one frame more refused with the size
// and what to lower (the boundary at more sizes: GifBytes.MostFramesAcceptedOneMoreRefused).
TEST(PerfGif, SizeBoundAcceptsNAndRefusesNPlusOne) {
    for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}, std::pair{3840, 2160}}) {
        const double most = plot::gif_most_frames(w, h);
        EXPECT_EQ(gif_refusal(most, w, h), "") << w << "x" << h;
        const std::string message = gif_refusal(most + 1, w, h);
        EXPECT_NE(message.find(std::to_string(static_cast<long>(most + 1)) + " frames of " + std::to_string(w) + " x " +
                               std::to_string(h) + " pixels"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("50 MB"), std::string::npos) << message;
        EXPECT_NE(message.find("lower --size or --dpi"), std::string::npos) << message;
    }
    EXPECT_EQ(gif_refusal(3684, 1280, 720), "");  // the 30-period swing fits
    EXPECT_NE(gif_refusal(3684, 1920, 1080), "");
}

// The 30-period swing at 1080p and 4K (about 165 MB) is refused before any work: exit 2,
// a message naming the size, no file (4K also passes every animation's bound, whose message
// it gets); the same GIF at the slides' 1280 x 720 stays accepted
// (VideoSpeed.SwingGifOf30PeriodsStaysWithin50MB renders it).
TEST(PerfGif, SwingOf30PeriodsAbove720pRefusedBeforeWork) {
    const auto dir = temp_dir("perf-gif-4k");
    std::string spec = slurp(std::filesystem::path(PENDULUM_TEST_DATA) / "../../src/figures/specs/swing.toml");
    const std::size_t at = spec.find("\nperiods = 3\n");
    ASSERT_NE(at, std::string::npos);
    spec.replace(at, 13, "\nperiods = 30\n");
    std::ofstream(dir / "swing30.toml") << spec;
    for (const std::string size : {"1920x1080", "3840x2160"}) {
        const auto r = run_cli("render swing30.toml --theme slides --size " + size + " -f gif -o .", dir);
        EXPECT_EQ(r.status, 2) << size;
        EXPECT_NE(r.err.find("swing30.gif: "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(" x " + size.substr(size.find('x') + 1) + " pixels "), std::string::npos) << r.err;
        if (size == "1920x1080") {
            EXPECT_NE(r.err.find("MB as a GIF, more than the 50 MB"), std::string::npos) << r.err;
        }
        EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
    }
    std::filesystem::remove_all(dir);
}
