// SPDX-License-Identifier: GPL-3.0-or-later
// The alt text's cost: the words of a drawn figure (a PDF's, an SVG's) take their curves at
// the vertices the file's drawing drew (their values in the curve's memo) instead of evaluating
// each curve at 512 parameters more, and say the same words as before, every built-in x theme x size,
// except the crossings of reference lines, which are now where the segment between two points
// meets the line (an mpmath reference holds period-error's) instead of the first point past it.
#include "figures/batch.hpp"
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/themes.hpp"
#include "plot/figure.hpp"
#include "plot/geometry.hpp"
#include "plot/output.hpp"
#include "plot/render.hpp"
#include "plot/theme.hpp"
#include "process.hpp"
#include "still_sweep.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

const plot::theme& paper() {
    static const plot::theme th = figures::load_theme("paper", {});
    return th;
}

/// FNV-1a, 64 bits: the sums below were made with it from the start's SVG <title> and <desc>.
std::uint64_t fnv1a(const std::string& s) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const unsigned char c : s) {
        h ^= c;
        h *= 0x100000001b3ULL;
    }
    return h;
}

/// The words' sum: the alt text, a newline, the description.
std::uint64_t sum_of(const plot::figure_words& w) { return fnv1a(w.alt + "\n" + w.description); }

struct start_sum {
    const char* id;
    const char* theme;
    const char* setting;
    std::uint64_t sum;
};

// The words of every built-in still x theme x size at the start of this change (the SVG's
// <title> and <desc> of `render --all -f svg --theme T --set S`, each figure refused at
// 8.6 cm left out: coefficients-second and trajectory-second in every theme, regimes in paper).
// clang-format off
const std::vector<start_sum> start_sums = {
    {"c1-lowest", "paper", "", 0x24ca996e193609c3ULL},
    {"coefficients-first", "paper", "", 0x70310e6150441207ULL},
    {"coefficients-second", "paper", "", 0x5ae7e06523606971ULL},
    {"convergence", "paper", "", 0xc225bf1485fe3458ULL},
    {"period-error", "paper", "", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "paper", "", 0xca51842f59ecb682ULL},
    {"period", "paper", "", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "paper", "", 0x3b67d8a5e1a04dc2ULL},
    {"regimes", "paper", "", 0x250b6fe77fd3dbf9ULL},
    {"spectrum", "paper", "", 0x139f4d132b230f87ULL},
    {"trajectory-first", "paper", "", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "paper", "", 0x82029f0dc04a675bULL},
    {"trajectory-second", "paper", "", 0xf1bb9323a7d2ced7ULL},
    {"c1-lowest", "paper", "figure_width_cm=8.6", 0x24ca996e193609c3ULL},
    {"coefficients-first", "paper", "figure_width_cm=8.6", 0x70310e6150441207ULL},
    {"convergence", "paper", "figure_width_cm=8.6", 0xc225bf1485fe3458ULL},
    {"period-error", "paper", "figure_width_cm=8.6", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "paper", "figure_width_cm=8.6", 0xca51842f59ecb682ULL},
    {"period", "paper", "figure_width_cm=8.6", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "paper", "figure_width_cm=8.6", 0x3b67d8a5e1a04dc2ULL},
    {"spectrum", "paper", "figure_width_cm=8.6", 0x139f4d132b230f87ULL},
    {"trajectory-first", "paper", "figure_width_cm=8.6", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "paper", "figure_width_cm=8.6", 0x82029f0dc04a675bULL},
    {"c1-lowest", "paper", "figure_width_cm=17.8", 0x24ca996e193609c3ULL},
    {"coefficients-first", "paper", "figure_width_cm=17.8", 0x70310e6150441207ULL},
    {"coefficients-second", "paper", "figure_width_cm=17.8", 0x5ae7e06523606971ULL},
    {"convergence", "paper", "figure_width_cm=17.8", 0xc225bf1485fe3458ULL},
    {"period-error", "paper", "figure_width_cm=17.8", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "paper", "figure_width_cm=17.8", 0xca51842f59ecb682ULL},
    {"period", "paper", "figure_width_cm=17.8", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "paper", "figure_width_cm=17.8", 0x3b67d8a5e1a04dc2ULL},
    {"regimes", "paper", "figure_width_cm=17.8", 0x250b6fe77fd3dbf9ULL},
    {"spectrum", "paper", "figure_width_cm=17.8", 0x139f4d132b230f87ULL},
    {"trajectory-first", "paper", "figure_width_cm=17.8", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "paper", "figure_width_cm=17.8", 0x82029f0dc04a675bULL},
    {"trajectory-second", "paper", "figure_width_cm=17.8", 0xf1bb9323a7d2ced7ULL},
    {"c1-lowest", "slides", "", 0x24ca996e193609c3ULL},
    {"coefficients-first", "slides", "", 0x70310e6150441207ULL},
    {"coefficients-second", "slides", "", 0x5ae7e06523606971ULL},
    {"convergence", "slides", "", 0xc225bf1485fe3458ULL},
    {"period-error", "slides", "", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "slides", "", 0xca51842f59ecb682ULL},
    {"period", "slides", "", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "slides", "", 0x3b67d8a5e1a04dc2ULL},
    {"regimes", "slides", "", 0x250b6fe77fd3dbf9ULL},
    {"spectrum", "slides", "", 0x139f4d132b230f87ULL},
    {"trajectory-first", "slides", "", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "slides", "", 0x82029f0dc04a675bULL},
    {"trajectory-second", "slides", "", 0xf1bb9323a7d2ced7ULL},
    {"c1-lowest", "slides", "figure_width_cm=8.6", 0x24ca996e193609c3ULL},
    {"coefficients-first", "slides", "figure_width_cm=8.6", 0x70310e6150441207ULL},
    {"convergence", "slides", "figure_width_cm=8.6", 0xc225bf1485fe3458ULL},
    {"period-error", "slides", "figure_width_cm=8.6", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "slides", "figure_width_cm=8.6", 0xca51842f59ecb682ULL},
    {"period", "slides", "figure_width_cm=8.6", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "slides", "figure_width_cm=8.6", 0x3b67d8a5e1a04dc2ULL},
    {"regimes", "slides", "figure_width_cm=8.6", 0x250b6fe77fd3dbf9ULL},
    {"spectrum", "slides", "figure_width_cm=8.6", 0x139f4d132b230f87ULL},
    {"trajectory-first", "slides", "figure_width_cm=8.6", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "slides", "figure_width_cm=8.6", 0x82029f0dc04a675bULL},
    {"c1-lowest", "slides", "figure_width_cm=17.8", 0x24ca996e193609c3ULL},
    {"coefficients-first", "slides", "figure_width_cm=17.8", 0x70310e6150441207ULL},
    {"coefficients-second", "slides", "figure_width_cm=17.8", 0x5ae7e06523606971ULL},
    {"convergence", "slides", "figure_width_cm=17.8", 0xc225bf1485fe3458ULL},
    {"period-error", "slides", "figure_width_cm=17.8", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "slides", "figure_width_cm=17.8", 0xca51842f59ecb682ULL},
    {"period", "slides", "figure_width_cm=17.8", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "slides", "figure_width_cm=17.8", 0x3b67d8a5e1a04dc2ULL},
    {"regimes", "slides", "figure_width_cm=17.8", 0x250b6fe77fd3dbf9ULL},
    {"spectrum", "slides", "figure_width_cm=17.8", 0x139f4d132b230f87ULL},
    {"trajectory-first", "slides", "figure_width_cm=17.8", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "slides", "figure_width_cm=17.8", 0x82029f0dc04a675bULL},
    {"trajectory-second", "slides", "figure_width_cm=17.8", 0xf1bb9323a7d2ced7ULL},
    {"c1-lowest", "slides-dark", "", 0x24ca996e193609c3ULL},
    {"coefficients-first", "slides-dark", "", 0x70310e6150441207ULL},
    {"coefficients-second", "slides-dark", "", 0x5ae7e06523606971ULL},
    {"convergence", "slides-dark", "", 0xc225bf1485fe3458ULL},
    {"period-error", "slides-dark", "", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "slides-dark", "", 0xca51842f59ecb682ULL},
    {"period", "slides-dark", "", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "slides-dark", "", 0x3b67d8a5e1a04dc2ULL},
    {"regimes", "slides-dark", "", 0x250b6fe77fd3dbf9ULL},
    {"spectrum", "slides-dark", "", 0x139f4d132b230f87ULL},
    {"trajectory-first", "slides-dark", "", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "slides-dark", "", 0x82029f0dc04a675bULL},
    {"trajectory-second", "slides-dark", "", 0xf1bb9323a7d2ced7ULL},
    {"c1-lowest", "slides-dark", "figure_width_cm=8.6", 0x24ca996e193609c3ULL},
    {"coefficients-first", "slides-dark", "figure_width_cm=8.6", 0x70310e6150441207ULL},
    {"convergence", "slides-dark", "figure_width_cm=8.6", 0xc225bf1485fe3458ULL},
    {"period-error", "slides-dark", "figure_width_cm=8.6", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "slides-dark", "figure_width_cm=8.6", 0xca51842f59ecb682ULL},
    {"period", "slides-dark", "figure_width_cm=8.6", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "slides-dark", "figure_width_cm=8.6", 0x3b67d8a5e1a04dc2ULL},
    {"regimes", "slides-dark", "figure_width_cm=8.6", 0x250b6fe77fd3dbf9ULL},
    {"spectrum", "slides-dark", "figure_width_cm=8.6", 0x139f4d132b230f87ULL},
    {"trajectory-first", "slides-dark", "figure_width_cm=8.6", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "slides-dark", "figure_width_cm=8.6", 0x82029f0dc04a675bULL},
    {"c1-lowest", "slides-dark", "figure_width_cm=17.8", 0x24ca996e193609c3ULL},
    {"coefficients-first", "slides-dark", "figure_width_cm=17.8", 0x70310e6150441207ULL},
    {"coefficients-second", "slides-dark", "figure_width_cm=17.8", 0x5ae7e06523606971ULL},
    {"convergence", "slides-dark", "figure_width_cm=17.8", 0xc225bf1485fe3458ULL},
    {"period-error", "slides-dark", "figure_width_cm=17.8", 0xd8b2c5df9f3bff1dULL},
    {"period-formulas", "slides-dark", "figure_width_cm=17.8", 0xca51842f59ecb682ULL},
    {"period", "slides-dark", "figure_width_cm=17.8", 0xa98c9b83e168c0d8ULL},
    {"phase-portrait", "slides-dark", "figure_width_cm=17.8", 0x3b67d8a5e1a04dc2ULL},
    {"regimes", "slides-dark", "figure_width_cm=17.8", 0x250b6fe77fd3dbf9ULL},
    {"spectrum", "slides-dark", "figure_width_cm=17.8", 0x139f4d132b230f87ULL},
    {"trajectory-first", "slides-dark", "figure_width_cm=17.8", 0x4ea0f0aa2593d94cULL},
    {"trajectory-lowest", "slides-dark", "figure_width_cm=17.8", 0x82029f0dc04a675bULL},
    {"trajectory-second", "slides-dark", "figure_width_cm=17.8", 0xf1bb9323a7d2ced7ULL},
};
// clang-format on

// period-error's words changed, alone: its crossings of the 0.1 % and 0.2 % lines were the
// first of 512 points past the line (0.403pi, 0.89pi; 0.469pi, 0.96pi), up to pi/512 late;
// they are now where the segment between two points meets it (0.401pi, 0.888pi; 0.468pi,
// 0.959pi), as mpmath finds them (tests/data/describe_crossings.csv, checked below).
constexpr std::uint64_t period_error_start = 0xd8b2c5df9f3bff1dULL;
constexpr std::uint64_t period_error_now = 0xfda6129257e69e6dULL;

/// The sum the words should have: the start's, or period-error's new one.
std::uint64_t expected_sum(const test_support::still_case& c, bool& listed) {
    for (const auto& s : start_sums) {
        if (c.entry.id == s.id && c.theme_name == s.theme && c.setting == s.setting) {
            listed = true;
            if (c.entry.id == "period-error") {
                EXPECT_EQ(s.sum, period_error_start) << c.where();
                return period_error_now;
            }
            return s.sum;
        }
    }
    listed = false;
    return 0;
}

/// The words describe finds with no drawing (the `describe` command's).
plot::figure_words own_words(const figures::entry& e, const plot::figure& fig, const plot::theme& th) {
    const figures::figure_description d = figures::describe(e, fig, figures::sized_by({}, th));
    return {d.alt, d.text};
}

/// A figure whose curves count their evaluations: each curve's count, in the order of the
/// panels and their series.
struct counted_figure {
    plot::figure fig;
    std::vector<std::shared_ptr<std::atomic<long>>> counts;

    /// Every curve's evaluations so far.
    std::vector<long> now() const {
        std::vector<long> out;
        for (const auto& n : counts) out.push_back(*n);
        return out;
    }
};

/// `fig` with each curve replaced by one that counts its evaluations, with a memo of its own
/// (empty): every evaluation counted is of a parameter not evaluated before.
counted_figure counted(const plot::figure& fig) {
    counted_figure out{fig, {}};
    for (auto& p : out.fig.panels) {
        for (auto& s : p.data) {
            if (!s.curve) continue;
            auto count = std::make_shared<std::atomic<long>>(0);
            auto c = std::make_shared<plot::curve>();
            c->u0 = s.curve->u0;
            c->u1 = s.curve->u1;
            c->pieces = s.curve->pieces;
            c->at = [inner = s.curve, count](double u) {
                ++*count;
                return inner->at(u);
            };
            s.curve = std::move(c);
            out.counts.push_back(std::move(count));
        }
    }
    return out;
}

/// b - a, element by element.
std::vector<long> minus(const std::vector<long>& b, const std::vector<long>& a) {
    std::vector<long> out;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) out.push_back(b[i] - a[i]);
    return out;
}

/// Fig. 7 as `render` builds it in the paper theme.
plot::figure fig7() { return figures::build(figures::find("period"), figures::sized_by({}, paper())); }

/// What each curve was evaluated for: by the drawing (before the words were asked for), and by describe.
struct words_cost {
    std::vector<long> drawing;   ///< each curve's evaluations before describe
    std::vector<long> describe;  ///< each curve's new evaluations within describe (empty: never asked)
    plot::figure_words words;    ///< the words found
};

/// Renders the counted figure to `format` with words from describe given the file's drawing.
words_cost render_counted(counted_figure& c, const figures::entry& e, const plot::theme& th, const std::string& format) {
    words_cost cost;
    c.fig.words = [&](const plot::drawing* drawn) {
        cost.drawing = c.now();
        const figures::figure_description d = figures::describe(e, c.fig, figures::sized_by({}, th), drawn);
        cost.describe = minus(c.now(), cost.drawing);
        cost.words = {d.alt, d.text};
        return cost.words;
    };
    (void)plot::render(c.fig, th, format, {});
    return cost;
}

}  // namespace

// The reproduction: Fig. 7's PDF made describe evaluate each curve at ~512 parameters the
// drawing had not (an MPFR period error each in panel (b)): 29 M of its 213 M instructions.
// Now describe takes the curves the drawing drew at the drawing's own vertices, and evaluates
// them only where a departure's bisection looks between two vertices (at most 80 values each).
// Panel (a)'s exact curve is drawn as 23 circles, its line not drawn: describe evaluates it at
// 513 parameters (a double-precision elliptic integral each), as it did, for the axis' range,
// and where the departures from it are looked for.
TEST(DescribeCost, Fig7PdfWordsTakeTheDrawnVerticesAndBisectOnly) {
    const figures::entry& e = figures::find("period");
    const plot::figure_words own = own_words(e, fig7(), paper());
    for (const std::string format : {"pdf", "svg"}) {
        counted_figure c = counted(fig7());
        ASSERT_EQ(c.counts.size(), 7u);  // (a) exact, lowest, first, second; (b) lowest, first, second
        const words_cost cost = render_counted(c, e, paper(), format);
        ASSERT_EQ(cost.describe.size(), 7u) << format;
        EXPECT_EQ(cost.drawing[0], 0) << format << ": the exact curve's line is not drawn";
        EXPECT_GE(cost.describe[0], 513) << format << ": 32 pieces, each halved 4 times";
        EXPECT_LE(cost.describe[0], 1000) << format;
        for (std::size_t i = 1; i < 7; ++i) {
            EXPECT_GT(cost.drawing[i], 0) << format << " curve " << i;
            EXPECT_LE(cost.describe[i], 80) << format << " curve " << i << ": one bisection at most";
        }
        EXPECT_EQ(cost.words.alt, own.alt) << format;
        EXPECT_EQ(cost.words.description, own.description) << format;

        // The file with describe's words evaluates what the file with the words given does,
        // but for the exact curve's and the bisections'.
        counted_figure told = counted(fig7());
        told.fig.words = [own](const plot::drawing*) { return own; };
        (void)plot::render(told.fig, paper(), format, {});
        const std::vector<long> more = minus(c.now(), told.now());
        ASSERT_EQ(more.size(), 7u);
        EXPECT_GE(more[0], 513) << format;
        for (std::size_t i = 1; i < 7; ++i) EXPECT_LE(more[i], 80) << format << " curve " << i;
    }
}

// Without a drawing (the `describe` command), describe evaluates its curves as before: 513
// values of each at least (and the departures' bisections), the same words.
TEST(DescribeCost, WithoutADrawingDescribeEvaluatesItsOwn) {
    const figures::entry& e = figures::find("period");
    const counted_figure c = counted(fig7());
    const plot::figure_words words = own_words(e, c.fig, paper());
    for (const long n : c.now()) EXPECT_GE(n, 513);
    EXPECT_EQ(words.description, own_words(e, fig7(), paper()).description);
}

// Hostile: a drawing that did not draw the curves described (another figure's, a file of one
// panel) lends neither its layout nor values: describe lays the figure out itself, as without
// a drawing, takes the values that layout evaluated, and says the same words.
TEST(DescribeCost, CurvesNotDrawnAreEvaluatedAsWithoutADrawing) {
    const figures::entry& e = figures::find("period");
    const plot::figure_words own = own_words(e, fig7(), paper());
    const counted_figure c = counted(fig7());
    const plot::figure other = fig7();
    (void)plot::render(other, paper(), "png", {});
    const plot::drawing elsewhere{&other, &paper(), false, plot::panel_frames(other, paper())};
    const figures::figure_description d = figures::describe(e, c.fig, figures::sized_by({}, paper()), &elsewhere);
    // Its own layout samples the curves drawn with a line; the exact curve's line is not drawn.
    const std::vector<long> evaluated = c.now();
    ASSERT_EQ(evaluated.size(), 7u);
    EXPECT_GE(evaluated[0], 513);
    for (std::size_t i = 1; i < 7; ++i) EXPECT_GT(evaluated[i], 0) << i;
    EXPECT_EQ(d.alt, own.alt);
    EXPECT_EQ(d.text, own.description);

    // A file of one panel, (b), is not the words' layout: describe lays the figure out (which
    // samples its curves) and takes the values that layout evaluated, but for the exact curve's.
    const counted_figure whole = counted(fig7());
    const plot::figure one = figures::single_panel(whole.fig, 1, whole.fig.panel_width_cm);
    (void)plot::render(one, paper(), "png", {});
    const std::vector<long> drawn = whole.now();
    const plot::drawing of_one{&one, &paper(), false, plot::panel_frames(one, paper())};
    const figures::figure_description both =
        figures::describe(e, whole.fig, figures::sized_by({}, paper()), &of_one);
    const std::vector<long> words = minus(whole.now(), drawn);
    ASSERT_EQ(words.size(), 7u);
    EXPECT_EQ(drawn[0], 0);
    EXPECT_GE(words[0], 513);
    EXPECT_EQ(both.text, own.description);
}

// The words of a file are its own drawing's: a curve's memo holding other values (a PNG drawn
// first at another scale, or values asked for anywhere on the curve, as a parallel render
// may leave them) changes neither the words nor the evaluations describe makes.
TEST(DescribeCost, WordsAreTheFilesWhateverTheMemoHolds) {
    for (const char* id : {"period", "period-error", "spectrum"}) {
        SCOPED_TRACE(id);
        const figures::entry& e = figures::find(id);
        const auto build = [&] { return figures::build(e, figures::sized_by({}, paper())); };
        counted_figure fresh = counted(build());
        const words_cost alone = render_counted(fresh, e, paper(), "pdf");
        counted_figure busy = counted(build());
        plot::output_options fine;
        fine.dpi = 1200;
        (void)plot::render(busy.fig, paper(), "png", fine);
        for (const auto& p : busy.fig.panels) {
            for (const auto& s : p.data) {
                if (!s.curve) continue;
                for (int k = 0; k <= 997; ++k) (void)plot::curve_at(*s.curve, s.curve->u0 + (s.curve->u1 - s.curve->u0) * k / 997.0);
            }
        }
        const words_cost after = render_counted(busy, e, paper(), "pdf");
        EXPECT_EQ(after.words.alt, alone.words.alt);
        EXPECT_EQ(after.words.description, alone.words.description);
    }
}

namespace {

/// "0.401pi": an amplitude over pi as describe says it (three significant digits).
std::string said_pi(double over_pi) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3gpi", over_pi);
    return buf;
}

/// The crossings' sentences as mpmath finds them: level -> "first crossed by ... ."
std::map<std::string, std::string> reference_crossings() {
    std::ifstream in(std::string(PENDULUM_TEST_DATA) + "/describe_crossings.csv");
    std::map<std::string, std::map<std::string, double>> at;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line.starts_with("method")) continue;
        std::stringstream row(line);
        std::string method, level, value;
        std::getline(row, method, ',');
        std::getline(row, level, ',');
        std::getline(row, value);
        at[level][method] = std::stod(value);
    }
    std::map<std::string, std::string> out;
    for (auto& [level, m] : at) {
        out[level] = "first crossed by lowest order at theta0 = " + said_pi(m["lowest"]) +
                     ", first order at theta0 = " + said_pi(m["first"]) + ", and second order at theta0 = " +
                     said_pi(m["second"]) + ".";
    }
    return out;
}

}  // namespace

// The crossings of the paper's claims, with a drawing (every theme's PDF) and without (the
// `describe` command): where mpmath's errors meet the lines, to the three digits said.
TEST(DescribeCost, CrossingsAreWhereMpmathFindsThem) {
    const auto reference = reference_crossings();
    ASSERT_EQ(reference.size(), 2u);
    EXPECT_EQ(reference.at("0.001"), "first crossed by lowest order at theta0 = 0.401pi, first order at theta0 = "
                                     "0.213pi, and second order at theta0 = 0.888pi.");
    const figures::entry& e = figures::find("period-error");
    const auto r = test_support::run_cli("describe period-error");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const auto& [level, words] : reference) {
        EXPECT_NE(r.out.find("= " + level + " ("), std::string::npos) << level;
        EXPECT_NE(r.out.find(words), std::string::npos) << r.out;
    }
    for (const auto& builtin : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(builtin.name, {});
        const plot::figure fig = figures::build(e, figures::sized_by({}, th));
        // A raster first: its values join the memo the PDF's words read.
        (void)plot::render(fig, th, "png", {});
        (void)plot::render(fig, th, "pdf", {});
        const std::string said = fig.words(nullptr).description;
        for (const auto& [level, words] : reference) EXPECT_NE(said.find(words), std::string::npos) << builtin.name;
        EXPECT_EQ(said, own_words(e, fig, th).description) << builtin.name;
    }
}

// Every built-in still x theme x size: the PDF's words (from its drawing's values) are
// describe's own (no drawing), and both are the start's, period-error's listed above.
TEST(DescribeCost, EveryBuiltinSaysTheWordsOfTheStart) {
    int listed_cases = 0;
    const auto counts = test_support::for_each_still_builtin(
        {"", "figure_width_cm=8.6", "figure_width_cm=17.8"}, [&](const test_support::still_case& c) {
            (void)plot::render(c.figure, c.theme, "pdf", {});
            const plot::figure_words found = c.figure.words(nullptr);
            const plot::figure_words own = own_words(c.entry, c.figure, c.theme);
            EXPECT_EQ(found.alt, own.alt) << c.where();
            EXPECT_EQ(found.description, own.description) << c.where();
            bool listed = false;
            const std::uint64_t expected = expected_sum(c, listed);
            EXPECT_TRUE(listed) << c.where();
            listed_cases += listed ? 1 : 0;
            EXPECT_EQ(sum_of(own), expected) << c.where() << "\n" << own.alt << "\n" << own.description;
        });
    EXPECT_EQ(counts.checked, 110);
    EXPECT_EQ(counts.refused, 7);
    EXPECT_EQ(listed_cases, static_cast<int>(start_sums.size()));
}

namespace {

/// A spectrum (|c_(2k+1)| on a logarithmic axis, points joined by lines) with a reference line at y = `line`.
std::string spectrum_with_line(const std::string& line) {
    return "[figure]\ndescription = \"spectrum with a line\"\npanel_width_cm = 8.0\npanel_aspect = 0.7\n\n"
           "[[panel]]\nplot = \"spectrum\"\ntheta0 = [\"0.5pi\", \"0.9pi\", \"0.99pi\", \"0.999pi\"]\n"
           "methods = [\"exact\"]\nharmonics = 15\n\n[[panel.line]]\ny = " +
           line + "\n";
}

/// Each series' points as `data` prints them (long CSV), by id, in order.
std::map<std::string, std::vector<std::pair<double, double>>> data_points(const std::string& csv) {
    std::map<std::string, std::vector<std::pair<double, double>>> out;
    std::stringstream in(csv);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        // panel,series,x,y,id: the label may hold no comma here ("ϑ0 = 0.5π").
        std::stringstream row(line);
        std::string panel, label, x, y, id;
        std::getline(row, panel, ',');
        std::getline(row, label, ',');
        std::getline(row, x, ',');
        std::getline(row, y, ',');
        std::getline(row, id);
        if (id.starts_with("theta0:")) out[id].emplace_back(std::stod(x), std::stod(y));
    }
    return out;
}

/// "4.74": where the segment between the first two points on either side of y meets it, on a
/// logarithmic y axis (straight in the logarithms, as drawn); empty if none does.
std::string crossing_said(const std::vector<std::pair<double, double>>& pts, double y) {
    for (std::size_t i = 1; i < pts.size(); ++i) {
        const double a = std::log10(pts[i - 1].second) - std::log10(y);
        const double b = std::log10(pts[i].second) - std::log10(y);
        if ((a < 0) != (b < 0)) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.3g", pts[i - 1].first + (pts[i].first - pts[i - 1].first) * a / (a - b));
            return buf;
        }
    }
    return {};
}

}  // namespace

// A line on a logarithmic axis is crossed where the segment drawn between two points (straight
// in the logarithms) meets it: theta0 = 0.5pi between 2k+1 = 3 and 5 at 4.74 (the first point
// past it, 5, before). Hostile: a line through a point is crossed at that point; lines at zero,
// below zero and above every point are crossed by none.
TEST(DescribeCost, CrossingsOnALogarithmicAxisAreBetweenThePointsAsDrawn) {
    const auto dir = test_support::temp_dir("describe-crossings");
    const auto spec = (dir / "spectrum-line.toml").string();
    const auto write = [&](const std::string& line) { std::ofstream(spec) << spectrum_with_line(line); };
    write("1e-3");
    const auto data = test_support::run_cli("data '" + spec + "'");
    ASSERT_EQ(data.status, 0) << data.err;
    const auto points = data_points(data.out);
    ASSERT_EQ(points.size(), 4u);
    const auto said = test_support::run_cli("describe '" + spec + "'");
    ASSERT_EQ(said.status, 0) << said.err;
    const char* names[] = {"0.5pi", "0.9pi", "0.99pi", "0.999pi"};
    std::string expected = "; first crossed by ";
    for (int i = 0; i < 4; ++i) {
        const std::string at = crossing_said(points.at("theta0:" + std::to_string(i + 1)), 1e-3);
        ASSERT_FALSE(at.empty()) << names[i];
        expected += std::string(i == 0 ? "" : i == 3 ? ", and " : ", ") + "theta0 = " + names[i] + " at 2k + 1 = " + at;
    }
    EXPECT_NE(said.out.find(expected + "."), std::string::npos) << said.out << "\n" << expected;
    EXPECT_NE(said.out.find("theta0 = 0.5pi at 2k + 1 = 4.74,"), std::string::npos) << said.out;

    // Through a point: 0.5pi's at 2k+1 = 3, as `data` prints it.
    const auto& half = points.at("theta0:1");
    char through[40];
    std::snprintf(through, sizeof through, "%.17g", half.at(1).second);
    write(through);
    const auto on_point = test_support::run_cli("describe '" + spec + "'");
    ASSERT_EQ(on_point.status, 0) << on_point.err;
    EXPECT_NE(on_point.out.find("first crossed by theta0 = 0.5pi at 2k + 1 = 3,"), std::string::npos) << on_point.out;

    for (const std::string line : {"0", "-1", "10"}) {
        write(line);
        const auto none = test_support::run_cli("describe '" + spec + "'");
        ASSERT_EQ(none.status, 0) << line << ": " << none.err;
        EXPECT_NE(none.out.find("; no curve crosses it."), std::string::npos) << line << ": " << none.out;
    }
    std::filesystem::remove_all(dir);
}
