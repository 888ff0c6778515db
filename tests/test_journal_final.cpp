// SPDX-License-Identifier: GPL-3.0-or-later
// Journal rules, the last: markers of different series kept apart in a panel, one legend
// entry per figure, and a legend glyph that draws what its series draw.
#include "figures/catalog.hpp"
#include "figures/spec.hpp"
#include "figures/themes.hpp"
#include "plot/render.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

using namespace test_support;
namespace fs = std::filesystem;

namespace {

/// The closest two markers of different spaced series in one panel, as a multiple of
/// 1.5 times their diameters' mean (1: exactly as close as the rule allows).
double closest_across_series(const std::vector<plot::marker_centres_of>& panel, std::size_t* pairs) {
    double closest = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < panel.size(); ++a) {
        for (std::size_t b = a + 1; b < panel.size(); ++b) {
            // Measured data keeps every point (each is a measurement): the data forces them.
            if (!panel[a].spaced || !panel[b].spaced) continue;
            const double least = 1.5 * (panel[a].radius + panel[b].radius);
            for (const auto& [xa, ya] : panel[a].centres) {
                for (const auto& [xb, yb] : panel[b].centres) {
                    if (pairs) ++*pairs;
                    closest = std::min(closest, std::hypot(xa - xb, ya - yb) / least);
                }
            }
        }
    }
    return closest;
}

/// True if two glyphs are one legend entry: one label, line, width, marker and colour.
bool same_glyph(const plot::glyph& a, const plot::glyph& b) {
    const bool same_rgb = a.rgb_color.has_value() == b.rgb_color.has_value() &&
                          (!a.rgb_color || (a.rgb_color->r == b.rgb_color->r && a.rgb_color->g == b.rgb_color->g &&
                                            a.rgb_color->b == b.rgb_color->b));
    return a.label == b.label && a.line == b.line && a.width_scale == b.width_scale && a.marker == b.marker &&
           a.color == b.color && same_rgb;
}

/// A series' label names the entry's, the one maybe said more fully ("E = 1" and "E = 1, libration").
bool names_entry(const std::string& series_label, const std::string& entry) {
    return series_label == entry || series_label.starts_with(entry + ", ") || entry.starts_with(series_label + ", ");
}

/// A panel of one-point series with circles at x = 0 and x = `apart` points on the page,
/// on axes of exactly [0, 10] x [-1, 1].
plot::figure two_markers(double apart_in_data) {
    plot::figure fig;
    plot::panel p;
    p.x.min = 0;
    p.x.max = 10;
    p.x.exact_range = true;
    p.y.min = -1;
    p.y.max = 1;
    p.y.exact_range = true;
    p.legend = plot::legend_place::none;
    for (const double x : {1.0, 1.0 + apart_in_data}) {
        plot::series s;
        s.x = {x};
        s.y = {0};
        s.line = plot::line_style::none;
        s.marker = plot::marker_style::open_circle;
        p.data.push_back(s);
    }
    fig.panels.push_back(p);
    return fig;
}

}  // namespace

// Every built-in still figure in every theme, at the paper's narrowest panel (4.2 cm) and a
// large one: no two markers of different series in one panel closer than 1.5 diameters.
// The data forces markers closer only for measured data (every point a measurement, not
// spaced), which this leaves out, as the within-series test does.
TEST(JournalFinal, NoTwoMarkersOfAnySeriesCloserThanOneAndAHalfDiameters) {
    std::size_t pairs = 0;
    int refused = 0;
    for (const auto& e : figures::catalog()) {
        if (e.spec.animation) continue;
        for (const auto& b : figures::builtin_themes()) {
            for (const char* width : {"panel_width_cm=4.2", "panel_width_cm=12"}) {
                const plot::theme th = figures::load_theme(b.name, {width});
                const plot::figure fig = figures::build(e, figures::sized_by({}, th));
                std::vector<std::vector<plot::marker_centres_of>> panels;
                try {
                    panels = plot::marker_centres(fig, th);
                } catch (const plot::layout_error&) {
                    ++refused;  // too small for its text: refused with a message, nothing drawn
                    continue;
                }
                for (std::size_t i = 0; i < panels.size(); ++i) {
                    EXPECT_GE(closest_across_series(panels[i], &pairs), 1 - 1e-9)
                        << e.id << " " << b.name << " " << width << " panel " << i;
                }
            }
        }
    }
    EXPECT_GE(pairs, 1000u) << "markers of different series were compared";
    EXPECT_LE(refused, 10);
}

// The reproduction: spectrum's first three coefficients of its four series piled into blobs
// (centres 0.2-0.5 diameters apart). The earlier series' marker now stands for both.
TEST(JournalFinal, SpectrumMarkersNoLongerPile) {
    for (const auto& b : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(b.name);
        const plot::figure fig = figures::build(figures::find("spectrum"), figures::sized_by({}, th));
        const auto panels = plot::marker_centres(fig, th);
        ASSERT_EQ(panels.size(), 1u);
        ASSERT_GE(panels[0].size(), 4u);
        EXPECT_GE(closest_across_series(panels[0], nullptr), 1 - 1e-9) << b.name;
        // The first series keeps every marker; a later one gives up only those within reach.
        std::size_t later = 0;
        for (std::size_t k = 1; k < panels[0].size(); ++k) later += panels[0][k].centres.size();
        EXPECT_EQ(panels[0][0].centres.size(), fig.panels[0].data[0].x.size()) << b.name;
        EXPECT_GT(later, 2 * fig.panels[0].data[1].x.size()) << b.name;
    }
}

// The boundary: markers of two series exactly 1.5 diameters apart are both drawn; 1 %
// closer, the later one is left out (the earlier stands for both).
TEST(JournalFinal, AcrossSeriesBoundary) {
    const plot::theme th = figures::load_theme("paper");
    const auto frames = plot::panel_frames(two_markers(1.0), th);
    ASSERT_EQ(frames.size(), 1u);
    const double pt_per_unit = frames[0].w / (frames[0].x_hi - frames[0].x_lo);
    const double least = 1.5 * 2 * th.marker_radius_pt;
    const auto at = [&](double factor) {
        const auto panels = plot::marker_centres(two_markers(factor * least / pt_per_unit), th);
        return std::make_pair(panels[0][0].centres.size(), panels[0][1].centres.size());
    };
    EXPECT_EQ(at(1.0 + 1e-9), std::make_pair(std::size_t{1}, std::size_t{1})) << "1.5 diameters apart: both";
    EXPECT_EQ(at(0.99), std::make_pair(std::size_t{1}, std::size_t{0})) << "closer: the earlier only";
    // Drawn as marker_centres says: the glyph log sees the later series without a marker.
    const plot::drawn_glyphs g = plot::glyphs_drawn(two_markers(0.99 * least / pt_per_unit), th);
    ASSERT_EQ(g.series.size(), 1u);
}

// Every built-in still figure in every theme: no legend entry (label and glyph) drawn twice
// in a figure; entries several panels share are shown once, panels keep their own.
TEST(JournalFinal, NoLegendEntryTwiceInAFigure) {
    std::size_t entries = 0;
    for (const auto& e : figures::catalog()) {
        if (e.spec.animation) continue;
        for (const auto& b : figures::builtin_themes()) {
            const plot::theme th = figures::load_theme(b.name);
            const plot::drawn_glyphs g = plot::glyphs_drawn(figures::build(e, figures::sized_by({}, th)), th);
            entries += g.legend.size();
            for (std::size_t i = 0; i < g.legend.size(); ++i) {
                for (std::size_t j = i + 1; j < g.legend.size(); ++j) {
                    EXPECT_FALSE(same_glyph(g.legend[i], g.legend[j]))
                        << e.id << " " << b.name << ": \"" << g.legend[i].label << "\" in panels "
                        << g.legend[i].panel << " and " << g.legend[j].panel;
                }
            }
        }
    }
    EXPECT_GE(entries, 100u);
}

// The reproduction: regimes showed three one-entry "exact" legends, in (b), (c) and (d).
TEST(JournalFinal, RegimesShowsExactOnce) {
    for (const auto& b : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(b.name);
        const plot::drawn_glyphs g = plot::glyphs_drawn(figures::build(figures::find("regimes"), figures::sized_by({}, th)), th);
        const auto exact = std::count_if(g.legend.begin(), g.legend.end(), [](const plot::glyph& x) { return x.label == "exact"; });
        EXPECT_EQ(exact, 1) << b.name;
        // (a) keeps its three energies: entries of its own.
        const auto in_a = std::count_if(g.legend.begin(), g.legend.end(), [](const plot::glyph& x) { return x.panel == 0; });
        EXPECT_EQ(in_a, 3) << b.name;
    }
}

// Every built-in still figure in every theme: each legend entry's glyph strokes what every
// series it names strokes in its panel (line style, width, marker), the thin line of a
// crowded series of circles included.
TEST(JournalFinal, LegendGlyphDrawsWhatItsSeriesDraw) {
    std::size_t compared = 0;
    std::size_t thin = 0;
    for (const auto& e : figures::catalog()) {
        if (e.spec.animation) continue;
        for (const auto& b : figures::builtin_themes()) {
            const plot::theme th = figures::load_theme(b.name);
            const plot::drawn_glyphs g = plot::glyphs_drawn(figures::build(e, figures::sized_by({}, th)), th);
            for (const plot::glyph& entry : g.legend) {
                for (const plot::glyph& s : g.series) {
                    const bool same_colour = s.color == entry.color && s.rgb_color.has_value() == entry.rgb_color.has_value();
                    if (!same_colour || !names_entry(s.label, entry.label)) continue;
                    ++compared;
                    thin += s.line != plot::line_style::none && s.width_scale < 1 && s.marker != plot::marker_style::none;
                    const std::string where = e.id + " " + std::string(b.name) + " \"" + entry.label + "\" panel " +
                                              std::to_string(s.panel);
                    EXPECT_EQ(s.line, entry.line) << where;
                    EXPECT_DOUBLE_EQ(s.width_scale, entry.width_scale) << where;
                    EXPECT_EQ(s.marker, entry.marker) << where;
                }
            }
        }
    }
    EXPECT_GE(compared, 200u);
    EXPECT_GE(thin, 3u) << "crowded series of circles (regimes, trajectory-second) were compared";
}

// The reproduction: trajectory-second (c)'s circles were joined by a thin line the legend's
// circle did not show; every panel's exact series and the glyph now show the same thin line.
TEST(JournalFinal, TrajectorySecondGlyphShowsTheThinLine) {
    const plot::theme th = figures::load_theme("paper");
    const plot::drawn_glyphs g =
        plot::glyphs_drawn(figures::build(figures::find("trajectory-second"), figures::sized_by({}, th)), th);
    const auto entry = std::find_if(g.legend.begin(), g.legend.end(), [](const plot::glyph& x) { return x.label == "exact"; });
    ASSERT_NE(entry, g.legend.end());
    EXPECT_EQ(entry->line, plot::line_style::solid);
    EXPECT_LT(entry->width_scale, 1.0);
    EXPECT_EQ(entry->marker, plot::marker_style::open_circle);
    int exact = 0;
    for (const auto& s : g.series) {
        if (s.label != "exact") continue;
        ++exact;
        EXPECT_EQ(s.line, entry->line) << "panel " << s.panel;
        EXPECT_DOUBLE_EQ(s.width_scale, entry->width_scale) << "panel " << s.panel;
    }
    EXPECT_EQ(exact, 3);
}

// A user's figure: two panels with a series of one label, one drawn alike in both (one
// entry), one drawn differently (an entry each), and labels of markup that reaches Pango
// (escaped ampersands and tags) compared as given.
TEST(JournalFinal, UserPanelsShareOnlyEntriesDrawnAlike) {
    plot::figure fig;
    fig.cols = 2;
    for (int i = 0; i < 2; ++i) {
        plot::panel p;
        for (int k = 0; k < 3; ++k) {
            plot::series s;
            s.x = {0, 1, 2};
            s.y = {0, 1, static_cast<double>(k)};
            s.color = k;
            s.label = k == 0 ? plot::label("a &amp; <i>b</i>") : k == 1 ? plot::label("same") : plot::label("styled");
            if (k == 2 && i == 1) s.line = plot::line_style::dashed;
            p.data.push_back(s);
        }
        fig.panels.push_back(p);
    }
    const plot::drawn_glyphs g = plot::glyphs_drawn(fig, figures::load_theme("paper"));
    std::vector<std::pair<std::size_t, std::string>> shown;
    for (const auto& e : g.legend) shown.emplace_back(e.panel, e.label);
    const std::vector<std::pair<std::size_t, std::string>> expected = {
        {0, "a &amp; <i>b</i>"}, {0, "same"}, {0, "styled"}, {1, "styled"}};
    EXPECT_EQ(shown, expected);
}
