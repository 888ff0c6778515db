// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the plot layer: tick location and labels, output formats, reproducible bytes,
// atomic writes, and errors.
#include "plot/figure.hpp"
#include "plot/math_layout.hpp"
#include "plot/output.hpp"
#include "plot/render.hpp"
#include "plot/text.hpp"
#include "figures/themes.hpp"
#include "plot/theme.hpp"
#include "plot/ticks.hpp"
#include "png_image.hpp"
#include "process.hpp"

#include <glib.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>

using namespace plot;
using std::numbers::pi;
namespace fs = std::filesystem;

namespace {

/// The built-in themes, from their style files.
plot::theme paper_theme() { return figures::load_theme("paper"); }
plot::theme slides_theme() { return figures::load_theme("slides"); }

/// A small figure with every kind of series, used by the format tests.
figure sample_figure() {
    figure f;
    f.cols = 2;
    for (int k = 0; k < 2; ++k) {
        panel p;
        p.label = k == 0 ? "(a)" : "(b)";
        p.x.label = "<i>\u03d1</i><sub>0</sub>";
        p.y.label = "<i>c</i><sup>\u2032</sup><sub>1</sub>";
        p.x.ticks = tick_kind::multiples_of_pi;
        series s{.label = "curve", .line = line_style::dashed, .marker = marker_style::none, .color = 1};
        series m{.label = "points", .line = line_style::none, .marker = marker_style::open_circle, .color = 0};
        for (int i = 0; i <= 50; ++i) {
            s.x.push_back(pi * i / 50);
            s.y.push_back(std::sin(pi * i / 50));
        }
        for (int i = 0; i <= 10; ++i) {
            m.x.push_back(pi * i / 10);
            m.y.push_back(std::sin(pi * i / 10));
        }
        p.data = {s, m};
        f.panels.push_back(p);
    }
    return f;
}

fs::path temp_dir(const std::string& name) {
    const auto dir = fs::temp_directory_path() / ("pendulum-plot-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

}  // namespace

// A thread keeps the texts it has shaped for every figure and format it draws, but no more
// than a bound: an animation's clock, a new text every frame, does not grow the memory, and
// a text shaped again is measured as before.
TEST(Text, ShapedTextsAreKeptUpToABound) {
    const plot::theme theme = figures::load_theme("paper");
    cairo_surface_t* surface = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr);
    cairo_t* cr = cairo_create(surface);
    {
        const plot::text_engine text(cr, theme.font_family);
        const auto first = text.measure("t = 0.000 s", 9);
        const plot::text_shaper& shaper = plot::text_shaper::for_thread(theme.font_family);
        for (int i = 0; i < 3 * static_cast<int>(plot::text_shaper::kept_boxes); ++i) {
            text.measure("t = " + std::to_string(i) + " s", 9);
            ASSERT_LE(shaper.kept(), plot::text_shaper::kept_boxes);
        }
        EXPECT_EQ(text.measure("t = 0.000 s", 9), first);
        // Another engine of the same family in this thread finds the texts shaped already.
        const plot::text_engine again(cr, theme.font_family);
        const std::size_t before = shaper.kept();
        again.measure("t = 5 s", 9);
        again.measure("t = 5 s", 9);
        EXPECT_LE(shaper.kept(), before + 1);
    }
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
}

TEST(Ticks, NiceStepsOnUglyRanges) {
    auto t = linear_ticks(0, pi, 6, true);
    EXPECT_EQ(t.major, (std::vector<double>{0, 1, 2, 3, 4}));
    EXPECT_EQ(t.labels, (std::vector<std::string>{"0", "1", "2", "3", "4"}));
    t = linear_ticks(-1e-3, 1e-3, 5, true);
    ASSERT_EQ(t.major.size(), 5u);
    EXPECT_EQ(t.major[2], 0.0);
    EXPECT_FALSE(std::signbit(t.major[2]));
    EXPECT_EQ(t.labels[0], "\u22121.0\u00d710<sup>\u22123</sup>");
    EXPECT_EQ(t.labels[1], "\u22120.5\u00d710<sup>\u22123</sup>");  // one shared exponent
    t = linear_ticks(1, 1, 5, true);
    EXPECT_GE(t.major.size(), 2u);
    EXPECT_LT(t.lo, 1.0);
    EXPECT_GT(t.hi, 1.0);
    t = linear_ticks(0, 1e6, 6, true);
    EXPECT_EQ(t.major.back(), 1e6);
    EXPECT_EQ(t.labels.back(), "1.0\u00d710<sup>6</sup>");
    EXPECT_EQ(t.labels.front(), "0");
}

TEST(Ticks, MultiplesOfTheStepNeverAccumulated) {
    // Every tick is i * step exactly; summing steps drifts (0.1 * 8 != 0.1 + ... + 0.1).
    const struct {
        double lo, hi;
        int max_ticks;
    } ranges[] = {{0, 1, 11}, {-1e-3, 1e-3, 5}, {0, 1e6, 6}, {-0.14, 3.74, 5}, {0.3, 2.9, 14}, {-7.7, -0.3, 8}};
    for (const auto& r : ranges) {
        const auto t = linear_ticks(r.lo, r.hi, r.max_ticks, true);
        const double step = nice_step(r.lo, r.hi, r.max_ticks, true);
        ASSERT_GE(t.major.size(), 2u);
        const long long first = std::llround(t.major.front() / step);
        for (std::size_t k = 0; k < t.major.size(); ++k) {
            const long long i = first + static_cast<long long>(k);
            EXPECT_EQ(t.major[k], i == 0 ? 0.0 : static_cast<double>(i) * step) << r.lo << ".." << r.hi << " tick " << k;
        }
    }
    const auto t = linear_ticks(0, 1, 11, true);
    ASSERT_EQ(t.major.size(), 11u);
    EXPECT_EQ(t.labels[3], "0.3");
    EXPECT_EQ(t.labels[0], "0.0");  // shared precision
    EXPECT_EQ(t.labels[10], "1.0");
}

TEST(Ticks, EdgeCases) {
    // Table-driven, after matplotlib's TestMaxNLocator.basic_data: range, max ticks, and
    // what the locator must give.
    const struct {
        const char* name;
        tick_set (*locate)(double, double, int, bool);
        double lo, hi;
        int max_ticks;
        std::size_t min_major, max_major;
        bool minor_wanted;
    } cases[] = {
        {"pi over [0, 1e6]", pi_ticks, 0, 1e6, 5, 2, 5, false},
        {"pi over [0, 1e3]", pi_ticks, 0, 1e3, 7, 2, 7, false},
        {"pi over [0, pi]", pi_ticks, 0, pi, 5, 5, 5, true},
        {"log over [0.3, 5]", log_ticks, 0.3, 5, 6, 2, 6, true},
        {"log over [2, 8]", log_ticks, 2, 8, 6, 2, 6, true},
        {"log over [1e-16, 1]", log_ticks, 1e-16, 1, 9, 9, 9, true},
        {"linear over [1, 1]", linear_ticks, 1, 1, 5, 2, 5, true},
        {"linear over [0, 0]", linear_ticks, 0, 0, 5, 2, 5, true},
        {"linear over [0, 1e6]", linear_ticks, 0, 1e6, 6, 2, 6, true},
    };
    for (const auto& c : cases) {
        const auto t = c.locate(c.lo, c.hi, c.max_ticks, false);
        EXPECT_GE(t.major.size(), c.min_major) << c.name;
        EXPECT_LE(t.major.size(), c.max_major) << c.name;
        EXPECT_EQ(t.labels.size(), t.major.size()) << c.name;
        if (c.minor_wanted) {
            EXPECT_FALSE(t.minor.empty()) << c.name;
        }
        EXPECT_TRUE(std::is_sorted(t.major.begin(), t.major.end())) << c.name;
        EXPECT_TRUE(std::is_sorted(t.minor.begin(), t.minor.end())) << c.name;
        for (double v : t.major) {
            EXPECT_GE(v, t.lo - 1e-9 * std::fabs(t.lo)) << c.name;
            EXPECT_LE(v, t.hi + 1e-9 * std::fabs(t.hi)) << c.name;
        }
        for (double v : t.minor) {
            EXPECT_GE(v, t.lo - 1e-9 * std::fabs(t.lo)) << c.name;
            EXPECT_LE(v, t.hi + 1e-9 * std::fabs(t.hi)) << c.name;
        }
        for (const auto& l : t.labels) EXPECT_FALSE(l.empty()) << c.name;
    }
    // Within one decade, 1, 2 and 5 times powers of ten carry plain labels.
    const auto t = log_ticks(0.3, 5, 6, false);
    EXPECT_EQ(t.major, (std::vector<double>{0.5, 1, 2, 5}));
    EXPECT_EQ(t.labels, (std::vector<std::string>{"0.5", "1", "2", "5"}));
    // An empty range still has a step, around its value.
    const struct {
        double lo, hi;
    } empty[] = {{1, 1}, {0, 0}, {-3e-7, -3e-7}, {1e6, 1e6}};
    for (const auto& e : empty) {
        const double step = nice_step(e.lo, e.hi, 5);
        EXPECT_GT(step, 0) << e.lo;
        EXPECT_TRUE(std::isfinite(step)) << e.lo;
    }
}

TEST(Ticks, SharedPrecisionAndMinusSign) {
    const auto t = linear_ticks(-0.5, 1, 4, true);
    EXPECT_EQ(t.labels, (std::vector<std::string>{"\u22120.5", "0.0", "0.5", "1.0"}));
    const auto q = linear_ticks(0, 1, 5, true);
    EXPECT_EQ(q.labels, (std::vector<std::string>{"0.0", "0.5", "1.0"}));
    EXPECT_EQ(nice_step(0, 10, 6), 2.0);
    EXPECT_EQ(nice_step(0, 1, 5), 0.5);
    EXPECT_EQ(nice_step(0, 100, 5), 25.0);  // 2.5 where it adds no decimal
}

TEST(Ticks, ARangeKeepsItsDecimalsWhateverTheNumberOfTicks) {
    // Fewer ticks (a narrower panel, crowded labels thinned) take a coarser step; within a
    // decade its labels need as many decimals as the finer one's: 0.0 0.2 ... 1.0 and 0.0
    // 0.5 1.0 alike. Labels print the decimals of the step's power of ten, no more.
    const struct {
        double lo, hi;
    } ranges[] = {{0, 1}, {0, 0.1}, {-1, 1}, {0, 3}, {0, 10}, {0, 100}, {0.2, 0.7}, {-0.14, 3.74}, {0, 0.03}};
    int checked = 0;
    for (const auto& r : ranges) {
        for (int n = 3; n <= 11; ++n) {
            const double step = nice_step(r.lo, r.hi, n, false);
            const int want = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
            for (const auto& l : linear_ticks(r.lo, r.hi, n, false).labels) {
                const auto point = l.find('.');
                const int d = point == std::string::npos ? 0 : static_cast<int>(l.size() - point - 1);
                EXPECT_EQ(d, want) << r.lo << ".." << r.hi << " at most " << n << " ticks: " << l;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 200);
}

TEST(Ticks, WithoutExpansionStayInsideTheRange) {
    const auto t = linear_ticks(-0.14, 3.74, 5, false);
    EXPECT_EQ(t.lo, -0.14);
    EXPECT_EQ(t.hi, 3.74);
    EXPECT_EQ(t.major, (std::vector<double>{0, 1, 2, 3}));
    for (double m : t.minor) {
        EXPECT_GE(m, t.lo);
        EXPECT_LE(m, t.hi);
    }
}

TEST(Ticks, MultiplesOfPi) {
    auto t = pi_ticks(0, pi, 5, false);
    EXPECT_EQ(t.labels, (std::vector<std::string>{"0", "<i>\u03c0</i>/4", "<i>\u03c0</i>/2", "3<i>\u03c0</i>/4", "<i>\u03c0</i>"}));
    EXPECT_EQ(t.major[2], pi / 2);
    t = pi_ticks(-2.9, 2.9, 7, true);
    EXPECT_EQ(t.labels, (std::vector<std::string>{"\u2212<i>\u03c0</i>", "\u2212<i>\u03c0</i>/2", "0", "<i>\u03c0</i>/2", "<i>\u03c0</i>"}));
    EXPECT_EQ(t.lo, -pi);
    t = pi_ticks(0, 4 * pi, 5, false);
    EXPECT_EQ(t.labels.back(), "4<i>\u03c0</i>");
    t = pi_ticks(-pi / 3, pi / 3, 7, true);  // quarters, not eighths
    EXPECT_EQ(t.labels.front(), "\u2212<i>\u03c0</i>/2");
}

TEST(Ticks, Logarithmic) {
    auto t = log_ticks(1e-16, 1, 9, false);
    EXPECT_EQ(t.major.size(), 9u);
    EXPECT_EQ(t.labels.front(), "10<sup>\u221216</sup>");
    EXPECT_EQ(t.labels.back(), "10<sup>0</sup>");
    t = log_ticks(2e-3, 0.5, 6, true);
    EXPECT_EQ(t.lo, 1e-3);
    EXPECT_EQ(t.hi, 1.0);
    EXPECT_FALSE(t.minor.empty());
    EXPECT_THROW(log_ticks(0, 1, 5, true), std::invalid_argument);
    EXPECT_THROW(linear_ticks(0, std::nan(""), 5, true), std::invalid_argument);
}

TEST(MathLayout, ScriptsStackAfterTheirBase) {
    // c'_1: the prime and the subscript are one piece after c, stacked, as TeX sets them.
    auto p = split_scripts("<i>c</i><sup>\u02b9</sup><sub>1</sub>");
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].base, "<i>c</i>");
    EXPECT_TRUE(p[0].has_sup && p[0].has_sub);
    EXPECT_EQ(p[0].sup, "\u02b9");
    EXPECT_EQ(p[0].sub, "1");
    EXPECT_TRUE(only_primes(p[0].sup));
    EXPECT_FALSE(only_primes("2"));
    p = split_scripts("<i>T</i>/<i>T</i><sub>0</sub> = 1");
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0].base, "<i>T</i>/<i>T</i>");
    EXPECT_EQ(p[0].sub, "0");
    EXPECT_FALSE(p[0].has_sup);
    EXPECT_EQ(p[1].base, " = 1");
    p = split_scripts("<i>x</i><sup>2</sup><sup>3</sup>");  // a second superscript: its own piece
    ASSERT_EQ(p.size(), 2u);
    EXPECT_TRUE(p[1].base.empty());
    EXPECT_EQ(p[1].sup, "3");
    p = split_scripts("<b>a<sub>1</sub></b>");  // nested scripts stay with their element
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].base, "<b>a<sub>1</sub></b>");
}

TEST(Markup, Escaped) {
    EXPECT_EQ(escape_markup("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
}

TEST(Markup, InvalidMarkupIsAnErrorNotAWarning) {
    figure f = sample_figure();
    f.panels[0].x.label = "<i>unclosed";
    EXPECT_THROW(render(f, paper_theme(), "svg", {}), std::invalid_argument);
    f.panels[0].x.label = escape_markup("a < b & c");
    EXPECT_NO_THROW(render(f, paper_theme(), "svg", {}));
}

TEST(Output, FormatTable) {
    EXPECT_EQ(format_names(), (std::vector<std::string>{"png", "pdf", "svg", "eps", "gif", "mp4", "webm", "pdf_tex", "eps_tex"}));
    EXPECT_THROW(check_format("bmp"), std::invalid_argument);
    try {
        check_format("jpg");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "unknown format 'jpg'; formats: png, pdf, svg, eps, gif, mp4, webm, pdf_tex, eps_tex");
    }
    EXPECT_THROW(figures::load_theme("dark"), std::invalid_argument);
    EXPECT_THROW(render(sample_figure(), paper_theme(), "png", {5}), std::invalid_argument);
}

TEST(Output, PngHasSignatureSizeAndResolution) {
    const auto fig = sample_figure();
    const std::string png = render(fig, paper_theme(), "png", {150});
    ASSERT_GT(png.size(), 33u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    auto be32 = [&](std::size_t at) {
        return (static_cast<unsigned>(static_cast<unsigned char>(png[at])) << 24) |
               (static_cast<unsigned>(static_cast<unsigned char>(png[at + 1])) << 16) |
               (static_cast<unsigned>(static_cast<unsigned char>(png[at + 2])) << 8) |
               static_cast<unsigned>(static_cast<unsigned char>(png[at + 3]));
    };
    // Two 6 cm panels side by side at 150 dpi, 0.75 as high.
    const double width_px = 12.0 / 2.54 * 150;
    EXPECT_NEAR(be32(16), width_px, 1.0);
    EXPECT_NEAR(be32(20), 0.75 * width_px / 2, 1.0);
    EXPECT_EQ(png[25], 0);  // colour type 0: the paper theme is pure grey
    EXPECT_NE(png.find("pHYs"), std::string::npos);
    const std::string colour = render(fig, slides_theme(), "png", {72});
    EXPECT_NE(colour[25], 0);  // palette or RGB for colour
}

TEST(Output, PdfIsReadByPopplerWithEmbeddedFonts) {
    const auto dir = temp_dir("pdf");
    save(sample_figure(), paper_theme(), dir / "f.pdf", {});
    const auto info = test_support::run_command("pdfinfo '" + (dir / "f.pdf").string() + "'");
    ASSERT_EQ(info.status, 0) << info.err;
    EXPECT_NE(info.out.find("Pages:           1\n"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("340.157 x 127.559 pts"), std::string::npos) << info.out;
    EXPECT_EQ(info.out.find("CreationDate"), std::string::npos);
    const auto fonts = test_support::run_command("pdffonts '" + (dir / "f.pdf").string() + "'");
    ASSERT_EQ(fonts.status, 0);
    EXPECT_NE(fonts.out.find("CMUSerif"), std::string::npos);
    // The prime is Computer Modern Unicode's own U+02B9, not the fallback's U+2032.
    EXPECT_EQ(fonts.out.find("DejaVuMathTeXGyre"), std::string::npos) << fonts.out;
    EXPECT_EQ(fonts.out.find("Type 3"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Output, PdfDateFromSourceDateEpoch) {
    ::setenv("SOURCE_DATE_EPOCH", "1363824000", 1);  // 2013-03-21
    const std::string a = render(sample_figure(), paper_theme(), "pdf", {});
    const std::string eps = render(sample_figure(), paper_theme(), "eps", {});
    ::unsetenv("SOURCE_DATE_EPOCH");
    EXPECT_NE(a.find("/CreationDate ("), std::string::npos);
    EXPECT_NE(a.find("20130321000000"), std::string::npos);
    EXPECT_NE(eps.find("%%CreationDate: Thu Mar 21 00:00:00 2013"), std::string::npos);
    const std::string b = render(sample_figure(), paper_theme(), "pdf", {});
    EXPECT_EQ(b.find("/CreationDate"), std::string::npos);
}

TEST(Output, SvgParses) {
    const std::string svg = render(sample_figure(), paper_theme(), "svg", {});
    GMarkupParser parser{};
    int elements = 0;
    parser.start_element = [](GMarkupParseContext*, const gchar*, const gchar**, const gchar**, gpointer data,
                              GError**) { ++*static_cast<int*>(data); };
    GMarkupParseContext* ctx = g_markup_parse_context_new(&parser, G_MARKUP_TREAT_CDATA_AS_TEXT, &elements, nullptr);
    GError* error = nullptr;
    const bool ok = g_markup_parse_context_parse(ctx, svg.data(), static_cast<gssize>(svg.size()), &error) &&
                    g_markup_parse_context_end_parse(ctx, &error);
    g_markup_parse_context_free(ctx);
    EXPECT_TRUE(ok) << (error ? error->message : "");
    if (error) g_error_free(error);
    EXPECT_GT(elements, 10);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("width=\"340.15748pt\""), std::string::npos);
}

TEST(Output, EpsHasBoundingBoxAndNoClockDate) {
    ::unsetenv("SOURCE_DATE_EPOCH");
    const std::string eps = render(sample_figure(), paper_theme(), "eps", {});
    EXPECT_EQ(eps.rfind("%!PS-Adobe-3.0 EPSF-3.0\n", 0), 0u);
    EXPECT_NE(eps.find("%%BoundingBox: 0 0 341 128"), std::string::npos);
    EXPECT_EQ(eps.find("%%CreationDate"), std::string::npos);
}

TEST(Output, SameInputSameBytesInEveryFormat) {
    for (const auto& th : {paper_theme(), slides_theme()}) {
        for (const auto& f : format_names()) {
            // A figure drawn in between must not change the next file (no global counters).
            if (f.ends_with("_tex")) {
                const auto g = f.substr(0, 3);
                const auto a = plot::render_overlay(sample_figure(), th, g, "f." + g, {100});
                render(sample_figure(), th, "svg", {100});
                const auto b = plot::render_overlay(sample_figure(), th, g, "f." + g, {100});
                EXPECT_EQ(a.graphics, b.graphics) << th.name << " " << f;
                EXPECT_EQ(a.tex, b.tex) << th.name << " " << f;
                continue;
            }
            if (!find_format(f).write) {
                // A video holds animations only: a still figure is bad input (see test_video).
                EXPECT_THROW(render(sample_figure(), th, f, {100}), plot::bad_input) << f;
                continue;
            }
            const std::string a = render(sample_figure(), th, f, {100});
            render(sample_figure(), th, "svg", {100});
            const std::string b = render(sample_figure(), th, f, {100});
            EXPECT_EQ(a, b) << th.name << " " << f;
        }
    }
}

TEST(Output, WritesAtomicallyAndKeepsTheOldFileOnFailure) {
    const auto dir = temp_dir("atomic");
    const auto path = dir / "f.png";
    save(sample_figure(), paper_theme(), path, {72});
    const std::string good = test_support::slurp(path);
    EXPECT_FALSE(good.empty());
    // A render that fails before writing leaves the previous file alone.
    EXPECT_THROW(save(sample_figure(), paper_theme(), dir / "f.bmp", {72}), std::invalid_argument);
    EXPECT_THROW(save(sample_figure(), paper_theme(), path, {1e6}), std::invalid_argument);
    EXPECT_EQ(test_support::slurp(path), good);
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        ++files;
        EXPECT_EQ(e.path().filename(), "f.png");  // no temporary left behind
    }
    EXPECT_EQ(files, 1u);
    EXPECT_THROW(write_atomically(dir / "missing" / "x.pdf", "x"), std::runtime_error);
    fs::remove_all(dir);
}

TEST(Output, MissingFontIsAnError) {
    theme th = paper_theme();
    th.font_family = "No Such Font Family";
    EXPECT_THROW(render(sample_figure(), th, "pdf", {}), std::runtime_error);
}

TEST(Legend, NeverCoversData) {
    // A parabola leaves only some corners free. The legend's ink is what differs between
    // renders with and without labels; no data may lie under it.
    figure with;
    panel p;
    series s{.label = "a parabola", .line = line_style::solid, .marker = marker_style::none, .color = 0};
    series m{.label = "its points", .line = line_style::none, .marker = marker_style::open_circle, .color = 0};
    for (int i = 0; i <= 200; ++i) {
        const double x = -1 + i / 100.0;
        s.x.push_back(x);
        s.y.push_back(x * x);
        if (i % 20 == 0) {
            m.x.push_back(x);
            m.y.push_back(x * x);
        }
    }
    p.data = {s, m};
    p.x.min = -1.0;
    p.x.max = 1.0;
    p.y.min = 0.0;
    p.y.max = 1.0;
    with.panels.push_back(p);
    figure without = with;
    for (auto& d : without.panels[0].data) d.label.clear();
    const auto a = test_support::decode(render(with, paper_theme(), "png", {200}));
    const auto b = test_support::decode(render(without, paper_theme(), "png", {200}));
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    unsigned x0 = a.width, y0 = a.height, x1 = 0, y1 = 0;
    for (unsigned y = 0; y < a.height; ++y) {
        for (unsigned x = 0; x < a.width; ++x) {
            if (a.at(x, y) != b.at(x, y)) {
                x0 = std::min(x0, x);
                y0 = std::min(y0, y);
                x1 = std::max(x1, x);
                y1 = std::max(y1, y);
            }
        }
    }
    ASSERT_LT(x0, x1) << "no legend was drawn";
    std::size_t data_under_legend = 0;
    for (unsigned y = y0; y <= y1; ++y) {
        for (unsigned x = x0; x <= x1; ++x) data_under_legend += b.at(x, y) < 200;
    }
    EXPECT_EQ(data_under_legend, 0u) << "legend box " << x0 << "," << y0 << " - " << x1 << "," << y1;
}

TEST(Legend, GoesAboveWhenNoCornerIsFree) {
    // Data everywhere: the legend takes a band above the axes, which therefore shrink.
    figure with;
    panel p;
    series s{.label = "zigzag", .line = line_style::solid, .marker = marker_style::none, .color = 0};
    for (int i = 0; i <= 400; ++i) {
        s.x.push_back(i / 400.0);
        s.y.push_back(i % 2);
    }
    p.data = {s};
    with.panels.push_back(p);
    figure without = with;
    without.panels[0].data[0].label.clear();
    const auto a = test_support::decode(render(with, paper_theme(), "png", {100}));
    const auto b = test_support::decode(render(without, paper_theme(), "png", {100}));
    // The frame's top edge: the first row, scanning down the middle column, that is dark
    // across most of the width.
    auto frame_top = [](const test_support::grey_image& im) {
        for (unsigned y = 0; y < im.height; ++y) {
            unsigned dark = 0;
            for (unsigned x = 0; x < im.width; ++x) dark += im.at(x, y) < 128;
            if (dark > im.width / 2) return y;
        }
        return im.height;
    };
    EXPECT_GT(frame_top(a), frame_top(b) + 5);
}

TEST(Ticks, DegreesDivideTheCircle) {
    const auto t = degree_ticks(0, 180, 5, false);
    EXPECT_EQ(t.major, (std::vector<double>{0, 45, 90, 135, 180}));
    EXPECT_EQ(t.labels.front(), "0\u00b0");
    EXPECT_EQ(t.labels.back(), "180\u00b0");
    EXPECT_EQ(degree_ticks(-180, 180, 7, false).labels.front(), "\u2212180\u00b0");
    EXPECT_EQ(degree_ticks(0, 10, 6, false).major, (std::vector<double>{0, 2, 4, 6, 8, 10}));
    for (std::size_t i = 0; i < t.major.size(); ++i) EXPECT_EQ(t.major[i], 45.0 * static_cast<double>(i));
}

/// One panel of a line from (0, 10) to (1, 20), in a figure of a fixed size.
figure line_figure() {
    figure f;
    panel p;
    p.x.label = "<i>x</i>";
    p.y.label = "<i>y</i>";
    p.data = {series{.label = "line", .x = {0, 1}, .y = {10, 20}, .line = line_style::solid, .marker = marker_style::none, .color = 0}};
    f.panels.push_back(p);
    return f;
}

plot::theme fixed_size(double width_cm, double height_cm, const std::vector<std::string>& sets = {}) {
    plot::theme th = figures::load_theme("paper", sets);
    th.fixed_width_cm = width_cm;
    th.fixed_height_cm = height_cm;
    return th;
}

TEST(Layout, FewerTicksWhereTheirLabelsWouldTouch) {
    // The texts the figure puts, as LaTeX: every tick label is there.
    const auto texts = [](const plot::theme& th) {
        return render_overlay(line_figure(), th, "pdf", "f.pdf", {}).tex;
    };
    // Text of the sizes these cases were measured at (7.5 pt ticks, below the paper theme's
    // journal minimum, which is lifted), decided at those sizes alone.
    const std::vector<std::string> small = {"min_text_pt=0", "min_script_pt=0", "tex_agree_pt=0", "tick_font_pt=7.5",
                                            "label_font_pt=8.5", "legend_font_pt=7"};
    const auto fixed_size = [&](double w, double h) { return ::fixed_size(w, h, small); };
    const std::string wide = texts(fixed_size(12, 6));
    for (const char* label : {"$0.0$", "$0.2$", "$0.4$", "$0.6$", "$0.8$", "$1.0$", "$12$"}) {
        EXPECT_NE(wide.find(label), std::string::npos) << label << "\n" << wide;
    }
    // 2.5 cm leaves no room for six labels: three, on the same limits.
    const std::string narrow = texts(fixed_size(2.5, 4));
    EXPECT_EQ(narrow.find("$0.2$"), std::string::npos) << narrow;
    for (const char* label : {"$0.0$", "$0.5$", "$1.0$"}) {
        EXPECT_NE(narrow.find(label), std::string::npos) << label << "\n" << narrow;
    }
    // Low, the y axis keeps its limits with fewer labels too.
    const std::string low = texts(fixed_size(8, 2.1));
    EXPECT_NE(low.find("$10$"), std::string::npos) << low;
    EXPECT_NE(low.find("$20$"), std::string::npos) << low;
    EXPECT_EQ(low.find("$12$"), std::string::npos) << low;
}

TEST(Layout, AxesTooSmallToReadAreAnError) {
    EXPECT_NO_THROW(render(line_figure(), fixed_size(3, 2.5), "svg", {}));
    try {
        render(line_figure(), fixed_size(2, 1), "svg", {});
        FAIL() << "no error";
    } catch (const plot::layout_error& e) {
        EXPECT_NE(std::string(e.what()).find("a figure of 2.0 x 1.0 cm leaves panel 1 of 1 axes of"), std::string::npos)
            << e.what();
    }
}
