// SPDX-License-Identifier: GPL-3.0-or-later
// Rules every figure keeps, built-in or a user's, in every theme and at every size: data
// stand clear of the frame.
#include "figures/batch.hpp"
#include "figures/build_options.hpp"
#include "figures/catalog.hpp"
#include "figures/errors.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/frames.hpp"
#include "plot/render.hpp"
#include "plot/text.hpp"
#include "still_sweep.hpp"

#include <cairo.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using test_support::for_each_still_builtin;
using test_support::still_case;

namespace {

struct case_figure {
    std::string name;
    plot::figure figure;
};

/// Every built-in still figure and a few user specs of every plot kind, built for `theme`.
std::vector<case_figure> figures_for(const plot::theme& theme) {
    std::vector<case_figure> out;
    figures::build_options o;
    o.panel_width_cm = theme.panel_width_cm;
    o.panel_aspect = theme.panel_aspect;
    for (const auto& e : figures::catalog()) {
        if (e.spec.animation) continue;
        out.push_back({e.id, figures::build(e, o)});
    }
    const char* specs[] = {
        "[[panel]]\nplot = \"trajectory\"\ntheta0 = \"170deg\"\nmethods = [\"exact\", \"harmonic\"]\n",
        "[[panel]]\nplot = \"trajectory\"\ntheta0 = \"pi/2\"\nmethods = [{ method = \"exact\", style = \"solid\" }]\n",
        "[[panel]]\nplot = \"phase\"\ntheta0 = [\"pi/3\", \"0.9pi\"]\nmethods = [\"exact\"]\n",
        "[[panel]]\nplot = \"period\"\nmethods = [\"exact\", \"lowest\"]\n",
        "[[panel]]\nplot = \"spectrum\"\ntheta0 = [\"pi/2\", \"0.99pi\"]\nmethods = [\"exact\"]\nharmonics = 9\n",
        "[[panel]]\nplot = \"coefficient\"\nmethods = [\"exact\", \"lowest\"]\n",
    };
    int i = 0;
    for (const char* text : specs) {
        const auto spec = figures::parse_spec(text, "user" + std::to_string(++i) + ".toml");
        out.push_back({"user spec " + std::to_string(i), figures::build_figure(spec, o)});
    }
    return out;
}

/// How far inside the frame a series' ink must stay, in points: its marker or half its
/// line, the frame's half width, and half a point of daylight.
double least_distance(const plot::series& s, const plot::theme& th) {
    const double line = s.line == plot::line_style::none ? 0.0 : 0.5 * th.line_width_pt * s.width_scale;
    const double marker =
        s.marker == plot::marker_style::none ? 0.0 : th.marker_radius_pt * s.marker_scale + 0.5 * th.line_width_pt;
    return std::max(line, marker) + 0.5 * th.frame_width_pt + 0.5;
}

double to_unit(double v, bool log) { return log ? std::log10(v) : v; }

}  // namespace

TEST(FigureRules, DataStandClearOfTheFrameInEveryThemeAndSize) {
    int checked = 0;
    for (const auto& builtin : figures::builtin_themes()) {
        for (const char* size : {"", "figure_width_cm=8.6", "panel_width_cm=4.2", "figure_width_cm=17"}) {
            std::vector<std::string> sets;
            if (*size) sets.emplace_back(size);
            const plot::theme theme = figures::load_theme(std::string(builtin.name), sets);
            for (const auto& [name, fig] : figures_for(theme)) {
                std::vector<plot::panel_frame> frames;
                try {
                    frames = plot::panel_frames(fig, theme);
                } catch (const plot::layout_error&) {
                    continue;  // a size too small for the theme's text is refused, not drawn
                }
                ASSERT_EQ(frames.size(), fig.panels.size()) << name;
                for (std::size_t i = 0; i < fig.panels.size(); ++i) {
                    const auto& p = fig.panels[i];
                    const auto& f = frames[i];
                    if (f.frameless) continue;
                    const bool xlog = p.x.kind == plot::scale::log;
                    const bool ylog = p.y.kind == plot::scale::log;
                    const double x_per_pt = (to_unit(f.x_hi, xlog) - to_unit(f.x_lo, xlog)) / f.w;
                    const double y_per_pt = (to_unit(f.y_hi, ylog) - to_unit(f.y_lo, ylog)) / f.h;
                    for (const auto& s : p.data) {
                        if (!s.autoscale || !s.sets_limits) continue;
                        if (s.line == plot::line_style::none && s.marker == plot::marker_style::none) continue;
                        const double d = least_distance(s, theme);
                        const std::string where = builtin.name.data() + std::string(" ") + size + " " + name +
                                                  " panel " + std::to_string(i + 1) + " '" + s.label.markup + "'";
                        for (std::size_t k = 0; k < s.x.size(); ++k) {
                            const double x = s.x[k];
                            const double y = s.y[k];
                            if (!std::isfinite(x) || !std::isfinite(y)) continue;
                            if ((xlog && !(x > 0)) || (ylog && !(y > 0))) continue;
                            if (!p.y.max) {
                                EXPECT_GE((to_unit(f.y_hi, ylog) - to_unit(y, ylog)) / y_per_pt, d) << where;
                            }
                            if (!p.y.min) {
                                EXPECT_GE((to_unit(y, ylog) - to_unit(f.y_lo, ylog)) / y_per_pt, d) << where;
                            }
                            if (!p.x.max) {
                                EXPECT_GE((to_unit(f.x_hi, xlog) - to_unit(x, xlog)) / x_per_pt, d) << where;
                            }
                            if (!p.x.min) {
                                EXPECT_GE((to_unit(x, xlog) - to_unit(f.x_lo, xlog)) / x_per_pt, d) << where;
                            }
                            ++checked;
                        }
                    }
                    if (HasFailure()) return;
                }
            }
        }
    }
    EXPECT_GT(checked, 10000);
}

TEST(FigureRules, SizeSettingsApplyToEveryFigureInOrder) {
    // The command line over a style file over a spec over a theme, for every figure.
    constexpr double pt_per_cm = 72.0 / 2.54;
    const auto dir = std::filesystem::temp_directory_path() / "pendulum-figures-size-order";
    std::filesystem::create_directories(dir);
    const auto style = (dir / "narrow.toml").string();
    {
        std::ofstream(style) << "panel_width_cm = 4.5\npanel_aspect = 0.5\n";
    }
    for (const auto& builtin : figures::builtin_themes()) {
        const std::string name(builtin.name);
        const plot::theme plain = figures::load_theme(name);
        const plot::theme wide = figures::load_theme(name, {"figure_width_cm=17.8"});
        const plot::theme narrow = figures::load_theme(name, {"panel_width_cm=4.3"});
        const plot::theme file = figures::load_theme(style);
        const plot::theme file_and_set = figures::load_theme(style, {"panel_width_cm=5.1"});
        for (const auto& e : figures::catalog()) {
            const auto size = [&](const plot::theme& th) {
                return plot::figure_size(figures::build(e, figures::sized_by({}, th)), th);
            };
            const int cols = figures::build(e, figures::sized_by({}, plain)).cols;
            if (plain.fixed_height_cm == 0) {
                EXPECT_NEAR(size(wide).width_pt, 17.8 * pt_per_cm, 1e-9) << name << " " << e.id;
            }
            if (plain.fixed_width_cm == 0) {
                EXPECT_NEAR(size(narrow).width_pt, cols * 4.3 * pt_per_cm, 1e-9) << name << " " << e.id;
                EXPECT_NEAR(size(file_and_set).width_pt, cols * 5.1 * pt_per_cm, 1e-9) << name << " " << e.id;
            }
            if (name == "paper") {
                EXPECT_NEAR(size(file).width_pt, cols * 4.5 * pt_per_cm, 1e-9) << e.id;
                const auto f = figures::build(e, figures::sized_by({}, file));
                EXPECT_NEAR(size(file).height_pt, f.rows * 4.5 * 0.5 * pt_per_cm, 1e-9) << e.id;
            }
        }
    }
    std::filesystem::remove_all(dir);
}

TEST(FigureRules, AmplitudeRangesInsideZeroToPiAreDrawnAsAsked) {
    const std::pair<const char*, const char*> ranges[] = {
        {"pi-1e-6", "pi-1e-9"}, {"1e-6", "1e-3"}, {"0", "pi"}, {"3", "pi"}, {"0", "1e-4"}};
    for (const char* plot : {"period", "coefficient"}) {
        for (const auto& [lo, hi] : ranges) {
            const std::string text = std::string("[[panel]]\nplot = \"") + plot + "\"\nmethods = [\"exact\", \"second\"]\n" +
                                     "range = [\"" + lo + "\", \"" + hi + "\"]\n";
            const auto spec = figures::parse_spec(text, "range.toml");
            const auto fig = figures::build_figure(spec);
            const double a = spec.panels.front().range->at(0);
            const double b = spec.panels.front().range->at(1);
            for (const auto& s : fig.panels.front().data) {
                ASSERT_GE(s.x.size(), 3u) << plot << " " << lo << ".." << hi << " " << s.label.markup;
                EXPECT_TRUE(std::is_sorted(s.x.begin(), s.x.end())) << plot << " " << lo << ".." << hi;
                EXPECT_GE(s.x.front(), a) << plot << " " << lo << ".." << hi;
                EXPECT_LE(s.x.back(), b) << plot << " " << lo << ".." << hi;
                // Spread over the range, not squeezed into a corner of it.
                EXPECT_GE(s.x.back() - s.x.front(), 0.9 * (b - a)) << plot << " " << lo << ".." << hi;
            }
        }
    }
}

TEST(FigureRules, AMethodWithoutValueIsRefusedInEveryPlotKind) {
    const char* specs[] = {
        "[[panel]]\nplot = \"trajectory\"\ntheta0 = \"pi-1e-6\"\nmethods = [\"exact\", \"order:6\"]\n",
        "[[panel]]\nplot = \"phase\"\ntheta0 = [\"pi-1e-6\"]\nmethods = [\"exact\", \"order:6\"]\n",
        "[[panel]]\nplot = \"period\"\nrange = [\"pi-1e-6\", \"pi-1e-7\"]\nmethods = [\"exact\", \"order:6\"]\n",
    };
    for (const char* text : specs) {
        const auto spec = figures::parse_spec(text, "nan.toml");
        try {
            (void)figures::build_figure(spec);
            ADD_FAILURE() << "no error for\n" << text;
        } catch (const figures::bad_input& e) {
            EXPECT_NE(std::string(e.what()).find("'order 6' has no value"), std::string::npos) << e.what();
        }
    }
}

TEST(FigureRules, EveryPaletteColourStandsOutFromItsBackground) {
    // WCAG 2.1 asks 3:1 of graphics against what is next to them.
    const auto luminance = [](const plot::rgb& c) {
        const auto linear = [](double v) { return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
        return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
    };
    for (const auto& builtin : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(std::string(builtin.name));
        const double bg = luminance(th.background);
        for (const auto& c : th.palette) {
            const double fg = luminance(c);
            const double ratio = (std::max(fg, bg) + 0.05) / (std::min(fg, bg) + 0.05);
            EXPECT_GE(ratio, 3.0) << builtin.name << ": colour " << c.r << " " << c.g << " " << c.b;
        }
    }
}

TEST(FigureRules, ASizeInPixelsIsTheRastersSizeForEveryFigure) {
    for (const auto& builtin : figures::builtin_themes()) {
        for (const char* size : {"1920x1080", "1280x720", "800x800", "3840x2160"}) {
            for (const char* dpi : {"", "dpi=96"}) {
                std::vector<std::string> sets;
                if (*dpi) sets.emplace_back(dpi);
                sets.push_back(std::string("size_px=") + size);
                const plot::theme th = figures::load_theme(std::string(builtin.name), sets);
                int w = 0;
                int h = 0;
                ASSERT_EQ(std::sscanf(size, "%dx%d", &w, &h), 2);
                for (const auto& e : figures::catalog()) {
                    const auto f = figures::build(e, figures::sized_by({}, th));
                    const auto [pw, ph] = plot::pixel_size(f, th, th.dpi);
                    EXPECT_EQ(pw, w) << builtin.name << " " << e.id << " " << size << " " << dpi;
                    EXPECT_EQ(ph, h) << builtin.name << " " << e.id << " " << size << " " << dpi;
                }
            }
        }
    }
    EXPECT_THROW((void)figures::load_theme("paper", {"size_px=1920"}), figures::spec_error);
    EXPECT_THROW((void)figures::load_theme("paper", {"size_px=1920x1080", "figure_width_cm=8"}), figures::spec_error);
}

namespace {

/// The texts a figure draws, in points, as the LaTeX overlay receives them.
std::vector<plot::placed_text> texts_of(const plot::figure& fig, const plot::theme& th,
                                        std::vector<plot::panel_frame>& frames) {
    const plot::page_size size = plot::figure_size(fig, th);
    cairo_surface_t* surface = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr);
    cairo_t* cr = cairo_create(surface);
    std::vector<plot::placed_text> texts;
    plot::draw_figure(cr, fig, th, size, plot::draw_pass::all, &texts, true, &frames);
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    return texts;
}

}  // namespace

// --paper-files writes each panel of a figure to a file of its own: a figure with one legend
// shows it in exactly one of them (the one the whole figure would put it in, or a band over
// the first), and every file's frame stays where its neighbours' are, in every theme and size.
TEST(FigureRules, PaperFilesShowOneLegendPerFigureAndKeepTheirFramesInLine) {
    int figures_checked = 0;
    for (const auto& builtin : figures::builtin_themes()) {
        for (const char* size : {"", "panel_width_cm=4.2", "panel_width_cm=9"}) {
            std::vector<std::string> sets;
            if (*size) sets.emplace_back(size);
            const plot::theme theme = figures::load_theme(std::string(builtin.name), sets);
            figures::build_options o;
            o.panel_width_cm = theme.panel_width_cm;
            o.panel_aspect = theme.panel_aspect;
            for (const auto& e : figures::catalog()) {
                if (e.spec.animation || e.spec.panels.size() < 2) continue;
                const plot::figure whole = figures::build(e, o);
                // The legend entries every panel shares: the first entry's text stands for the legend.
                std::vector<std::string> first_entries;
                for (const auto& p : whole.panels) {
                    for (const auto& s : p.data) {
                        if (!s.label.markup.empty()) {
                            first_entries.push_back(s.label.markup);
                            break;
                        }
                    }
                }
                if (!whole.shared_legend || first_entries.empty()) continue;
                int with_legend = 0;
                std::vector<plot::panel_frame> first_frame;
                const plot::layout_notes notes;  // what the files left out, and why
                for (std::size_t i = 0; i < whole.panels.size(); ++i) {
                    const plot::figure one = figures::single_panel(whole, static_cast<int>(i), whole.panel_width_cm);
                    std::vector<plot::panel_frame> frames;
                    std::vector<plot::placed_text> texts;
                    try {
                        texts = texts_of(one, theme, frames);
                    } catch (const plot::layout_error&) {
                        break;  // too small for the theme's text: refused, not drawn
                    }
                    const bool legend = std::any_of(texts.begin(), texts.end(), [&](const plot::placed_text& t) {
                        return t.text.markup == first_entries.front();
                    });
                    with_legend += legend ? 1 : 0;
                    ASSERT_EQ(frames.size(), 1u);
                    if (i == 0) {
                        first_frame = frames;
                        continue;
                    }
                    EXPECT_NEAR(frames[0].y, first_frame[0].y, 1e-6) << e.id << " panel " << i + 1 << " " << size;
                    EXPECT_NEAR(frames[0].h, first_frame[0].h, 1e-6) << e.id << " panel " << i + 1 << " " << size;
                    EXPECT_NEAR(frames[0].x, first_frame[0].x, 1e-6) << e.id << " panel " << i + 1 << " " << size;
                }
                if (first_frame.empty()) continue;
                // Files too small for a band over their axes (at the sizes the contents are
                // decided at: the paper theme's 12-pt overlay text) may have no legend, never
                // two; where none has it, the layout says so.
                EXPECT_LE(with_legend, 1) << e.id << " in " << builtin.name << " " << size;
                if (with_legend == 0) {
                    EXPECT_EQ(notes.lines().size(), 1u) << e.id << " in " << builtin.name << " " << size;
                }
                ++figures_checked;
            }
        }
    }
    EXPECT_GE(figures_checked, 12);
}

namespace {

/// The decimals a tick label prints: the digits after its point, or 0 ("π/2", "10").
int decimals_of(const std::string& label) {
    const auto point = label.find('.');
    if (point == std::string::npos) return 0;
    int n = 0;
    for (std::size_t i = point + 1; i < label.size() && label[i] >= '0' && label[i] <= '9'; ++i) ++n;
    return n;
}

/// The decimals of an axis' labels, "0.00 0.25 ..." gives 2; -1 for an axis without numbers.
int axis_decimals(const std::vector<std::string>& labels) {
    int most = -1;
    for (const auto& l : labels) {
        if (l.empty() || l.find_first_of("0123456789") == std::string::npos) continue;
        most = std::max(most, decimals_of(l));
    }
    return most;
}

}  // namespace

// An axis of one quantity over one range prints its ticks with one number of decimals in every
// built-in figure and theme: t/T from 0 to 1 reads 0.0 ... 1.0 in every figure, never 0.00
// ... 1.00 in one figure and 0.0 ... 1.0 in the next, whatever room each panel has.
TEST(FigureRules, AxesOfOneQuantityAndRangePrintOneNumberOfDecimals) {
    struct seen {
        int decimals;
        std::string where;
    };
    std::map<std::string, seen> first;  // by axis label and range
    int axes = 0;
    for (const auto& builtin : figures::builtin_themes()) {
        const plot::theme theme = figures::load_theme(std::string(builtin.name));
        for (const auto& e : figures::catalog()) {
            const plot::figure fig = figures::build(e, figures::sized_by({}, theme));
            const auto frames = plot::panel_frames(fig, theme);
            ASSERT_EQ(frames.size(), fig.panels.size()) << e.id;
            for (std::size_t i = 0; i < fig.panels.size(); ++i) {
                const auto& f = frames[i];
                if (f.frameless) continue;
                for (const bool horizontal : {true, false}) {
                    const auto& a = horizontal ? fig.panels[i].x : fig.panels[i].y;
                    const int d = axis_decimals(horizontal ? f.x_labels : f.y_labels);
                    if (d < 0 || a.label.empty()) continue;
                    char range[64];
                    std::snprintf(range, sizeof range, " [%.6g, %.6g]", horizontal ? f.x_lo : f.y_lo,
                                  horizontal ? f.x_hi : f.y_hi);
                    const std::string key = a.label.markup + range;
                    std::string labels;
                    for (const auto& l : horizontal ? f.x_labels : f.y_labels) labels += " " + l;
                    const std::string where = std::string(builtin.name) + " " + e.id + " panel " +
                                              std::to_string(i + 1) + (horizontal ? " x:" : " y:") + labels;
                    const auto [it, fresh] = first.try_emplace(key, seen{d, where});
                    EXPECT_EQ(d, it->second.decimals) << key << "\n  " << where << "\n  " << it->second.where;
                    ++axes;
                }
            }
        }
    }
    EXPECT_GE(axes, 50);
    EXPECT_GE(first.size(), 5u);
}

// No two tick labels come within a tenth of their size of each other in any built-in figure
// and theme: at the corner of a frame, the lowest y label (−π/2, whose slash hangs below
// the line) and the first x label stay apart.
TEST(FigureRules, TickLabelsKeepApartAtTheCorners) {
    cairo_surface_t* surface = cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, nullptr);
    cairo_t* cr = cairo_create(surface);
    int pairs = 0;
    for (const auto& builtin : figures::builtin_themes()) {
        const plot::theme theme = figures::load_theme(std::string(builtin.name));
        plot::text_engine text(cr, theme.font_family);
        for (const auto& e : figures::catalog()) {
            if (e.spec.animation) continue;
            std::vector<plot::panel_frame> frames;
            const auto texts = texts_of(figures::build(e, figures::sized_by({}, theme)), theme, frames);
            struct box {
                double x0, y0, x1, y1;
                std::string what;
            };
            std::vector<box> boxes;
            const double grow = 0.05 * theme.tick_font_pt;
            for (const auto& t : texts) {
                if (t.rotate || std::fabs(t.size_pt - theme.tick_font_pt) > 1e-9) continue;
                const plot::text_ink i = text.ink(t.text.markup, t.size_pt);
                boxes.push_back({t.x + i.x - grow, t.y + i.y - grow, t.x + i.x + i.w + grow, t.y + i.y + i.h + grow,
                                 t.text.markup});
            }
            for (std::size_t a = 0; a < boxes.size(); ++a) {
                for (std::size_t b = a + 1; b < boxes.size(); ++b) {
                    const box& p = boxes[a];
                    const box& q = boxes[b];
                    const bool touch = p.x0 < q.x1 && q.x0 < p.x1 && p.y0 < q.y1 && q.y0 < p.y1;
                    EXPECT_FALSE(touch) << builtin.name << " " << e.id << ": '" << p.what << "' and '" << q.what
                                        << "' overlap by " << std::min(p.y1 - q.y0, q.y1 - p.y0) << " pt";
                    ++pairs;
                }
            }
        }
    }
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    EXPECT_GT(pairs, 1000);
}

// Panels of one figure whose axes show one quantity over one range carry the same ticks at
// every size: a panel crowded into fewer ticks takes its neighbours with it.
TEST(FigureRules, PanelsOfAFigureShareTheTicksOfAnAxisTheyShare) {
    int compared = 0;
    const std::vector<std::string> sizes = {"", "figure_width_cm=8.6", "panel_width_cm=3.5", "tick_font_pt=11"};
    for_each_still_builtin(sizes, [&](const still_case& c) {
        const auto frames = plot::panel_frames(c.figure, c.theme);  // too small for its text: refused
        std::map<std::string, std::pair<std::vector<std::string>, std::size_t>> first;
        for (std::size_t i = 0; i < c.figure.panels.size(); ++i) {
            if (frames[i].frameless) continue;
            for (const bool horizontal : {true, false}) {
                const auto& a = horizontal ? c.figure.panels[i].x : c.figure.panels[i].y;
                const auto& f = frames[i];
                char range[64];
                std::snprintf(range, sizeof range, " [%.6g, %.6g]", horizontal ? f.x_lo : f.y_lo,
                              horizontal ? f.x_hi : f.y_hi);
                const std::string key = a.label.markup + range;
                const auto& labels = horizontal ? f.x_labels : f.y_labels;
                const auto [it, fresh] = first.try_emplace(key, labels, i);
                if (fresh) continue;
                EXPECT_EQ(labels, it->second.first)
                    << c.where() << " panel " << i + 1 << " and " << it->second.second + 1 << ": " << key;
                ++compared;
            }
        }
    });
    EXPECT_GT(compared, 100);
}

// An open marker on its own series' line stays open in every built-in figure and theme: the
// pixel at its centre is the background, not the line running through it.
TEST(FigureRules, OpenMarkersOnTheirOwnLineStayOpen) {
    const double dpi = 150;
    int markers = 0;
    int open = 0;
    for (const auto& builtin : figures::builtin_themes()) {
        const plot::theme theme = figures::load_theme(std::string(builtin.name));
        for (const auto& e : figures::catalog()) {
            if (e.spec.animation) continue;
            const plot::figure fig = figures::build(e, figures::sized_by({}, theme));
            const auto frames = plot::panel_frames(fig, theme);
            const plot::argb_image image = plot::render_argb(fig, theme, dpi);
            const auto background = [&](int x, int y) {
                const unsigned char* p = &image.data[static_cast<std::size_t>(y) * image.stride + 4 * x];
                const auto near = [](unsigned char v, double want) { return std::fabs(v - 255 * want) < 40; };
                return near(p[2], theme.background.r) && near(p[1], theme.background.g) && near(p[0], theme.background.b);
            };
            // The markers as drawn (a method's spaced on the page; where two series' would
            // pile, the earlier one's stands for both), their centres in points.
            const auto drawn = plot::marker_centres(fig, theme);
            for (std::size_t i = 0; i < fig.panels.size(); ++i) {
                const auto& f = frames[i];
                if (f.frameless) continue;
                for (std::size_t k = 0; k < fig.panels[i].data.size(); ++k) {
                    const auto& s = fig.panels[i].data[k];
                    if (s.marker != plot::marker_style::open_circle || s.line == plot::line_style::none) continue;
                    for (const auto& [cx, cy] : drawn[i][k].centres) {
                        const double u = (cx - f.x) / f.w;
                        const double v = (cy - f.y) / f.h;
                        if (u < 0.02 || u > 0.98 || v < 0.02 || v > 0.98) continue;
                        ++markers;
                        open += background(static_cast<int>(std::lround(cx * dpi / 72)),
                                           static_cast<int>(std::lround(cy * dpi / 72)))
                                    ? 1
                                    : 0;
                    }
                }
            }
        }
    }
    EXPECT_GT(markers, 100);
    // A later series' line may cross a few.
    EXPECT_GE(open, 0.9 * markers) << open << " of " << markers << " open";
}
