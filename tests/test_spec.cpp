// SPDX-License-Identifier: GPL-3.0-or-later
// Figure specs: what a good spec reads as, and one message per problem for bad ones.
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace {

using namespace figures;
using std::numbers::pi;

/// The problems of a bad spec, one per line; "accepted" if it parses.
std::string problems_of(const std::string& text) {
    try {
        parse_spec(text, "my-figure.toml");
    } catch (const spec_error& e) {
        return e.what();
    }
    return "accepted";
}

TEST(Spec, TheTeachersFigure) {
    const auto f = parse_spec(R"(
[figure]
columns = 2
panel_width_cm = 8.6
panel_aspect = 0.6
legend = "each"
title = "Large swings"

[pendulum]
length_m = 0.5

[[panel]]
plot = "trajectory"
theta0 = "170deg"
methods = ["exact", "harmonic", { method = "order:6", label = "sixth order", style = "dashed", color = "#d55e00", marker = "circle" }]
time = "t/s"
range = [0, 3]
paper_file = "Fig.Teacher"

[[panel]]
plot = "period"
methods = ["exact", "lowest", "kidd-fogg", "agm:2"]
y = "error-log"
range = ["0", "0.99pi"]
angle_unit = "deg"
[[panel.line]]
y = 0.001
label = "0.1 %"
)",
                              "dir/teacher.toml");
    EXPECT_EQ(f.id, "teacher");
    EXPECT_EQ(f.columns, 2);
    EXPECT_EQ(f.panel_width_cm, 8.6);
    EXPECT_EQ(f.panel_aspect, 0.6);
    EXPECT_EQ(f.legend, legend_mode::each);
    EXPECT_EQ(f.title, "Large swings");
    ASSERT_TRUE(f.pendulum);
    EXPECT_EQ(f.pendulum->length_m, 0.5);
    EXPECT_EQ(f.pendulum->g, 9.80665);
    ASSERT_EQ(f.panels.size(), 2u);
    const auto& a = f.panels[0];
    EXPECT_EQ(a.plot->name, "trajectory");
    ASSERT_EQ(a.theta0.size(), 1u);
    EXPECT_EQ(a.theta0[0].text, "170deg");
    EXPECT_DOUBLE_EQ(a.theta0[0].value, 170 * pi / 180);
    ASSERT_EQ(a.methods.size(), 3u);
    EXPECT_EQ(a.methods[2].method.text(), "order:6");
    EXPECT_EQ(a.methods[2].label, "sixth order");
    EXPECT_EQ(a.methods[2].style, plot::line_style::dashed);
    ASSERT_TRUE(a.methods[2].color);
    EXPECT_DOUBLE_EQ(a.methods[2].color->r, 0xd5 / 255.0);
    EXPECT_EQ(a.methods[2].marker, plot::marker_style::open_circle);
    EXPECT_EQ(a.time, time_unit::seconds);
    EXPECT_EQ(a.range, (std::array<double, 2>{0, 3}));
    EXPECT_EQ(a.paper_file, "Fig.Teacher");
    const auto& b = f.panels[1];
    EXPECT_EQ(b.plot->name, "period");
    EXPECT_EQ(b.y, period_axis::error_log);
    EXPECT_TRUE(b.degrees);
    ASSERT_TRUE(b.range);
    EXPECT_DOUBLE_EQ((*b.range)[1], 0.99 * pi);
    ASSERT_EQ(b.lines.size(), 1u);
    EXPECT_EQ(b.lines[0].y, 0.001);
    EXPECT_EQ(b.lines[0].label, "0.1 %");
}

TEST(Spec, DefaultsOfAMinimalSpec) {
    const auto f = parse_spec("[[panel]]\nplot = \"convergence\"\ntheta0 = [\"pi/2\", \"9pi/10\"]\n", "c.toml");
    EXPECT_FALSE(f.columns);
    EXPECT_FALSE(f.panel_width_cm);
    EXPECT_EQ(f.legend, legend_mode::first);
    EXPECT_FALSE(f.pendulum);
    ASSERT_EQ(f.panels.size(), 1u);
    EXPECT_EQ(f.panels[0].orders, (std::array<int, 2>{0, 40}));
    EXPECT_EQ(f.panels[0].theta0.size(), 2u);
    EXPECT_FALSE(f.panels[0].title);
}

TEST(Spec, MisspeltKeysGetASuggestionWithFileLineAndColumn) {
    EXPECT_EQ(problems_of("[[panel]]\nplot = \"trajectory\"\ntheta0 = \"1\"\nmetods = [\"exact\"]\n"),
              "my-figure.toml:1:1: a trajectory panel needs methods, e.g. [\"exact\", \"lowest\"]\n"
              "my-figure.toml:4:1: unknown key 'metods' in a trajectory panel; did you mean methods?");
    EXPECT_EQ(problems_of("[figure]\ncolums = 2\n[[panel]]\nplot = \"convergence\"\ntheta0 = 1\n"),
              "my-figure.toml:2:1: unknown key 'colums' in [figure]; did you mean columns?");
    EXPECT_EQ(problems_of("[[panel]]\nplot = \"trajectry\"\n"),
              "my-figure.toml:2:8: unknown plot 'trajectry'; plots: trajectory, phase, period, coefficient, "
              "convergence, spectrum, pendulum; did you mean trajectory?");
}

TEST(Spec, EveryProblemIsReportedOnce) {
    const std::string text = R"([figure]
columns = 0
legend = "frist"
[[panel]]
plot = "trajectory"
theta0 = "4"
methods = ["exact", "lowst", "kidd-fogg", "order:300"]
separatrix = true
range = [2, 1]
[[panel]]
plot = "coefficient"
harmonic = 2
methods = [{ method = "exact", color = "red", style = "wavy" }]
)";
    const std::string got = problems_of(text);
    const char* const expected[] = {
        "my-figure.toml:2:11: 'columns' = 0 is out of range; allowed 1 to 6",
        "my-figure.toml:3:10: 'legend' = \"frist\" is not one of first, each, none; did you mean first?",
        "my-figure.toml:6:10: 'theta0': theta0 must be strictly between 0 and pi, got 4",
        "my-figure.toml:7:21: unknown method 'lowst'",
        "did you mean lowest?",
        "my-figure.toml:7:30: method kidd-fogg gives a period only; plot 'trajectory' needs a law of motion",
        "my-figure.toml:7:43: method 'order:300': N must be a whole number in 0..200",
        "my-figure.toml:8:1: key 'separatrix' does not apply to plot 'trajectory'",
        "my-figure.toml:9:9: 'range' must go from a smaller to a larger value",
        "my-figure.toml:12:12: 'harmonic' must be odd",
        "my-figure.toml:13:40: 'color' = \"red\" is not a colour #rrggbb",
        "my-figure.toml:13:55: 'style' = \"wavy\" is not one of solid, dashed, dotted, dash-dot, dash-dot-dot, none",
    };
    for (const char* e : expected) EXPECT_NE(got.find(e), std::string::npos) << "missing: " << e << "\nin:\n" << got;
}

TEST(Spec, WrongTypesAndStructure) {
    EXPECT_NE(problems_of("").find("my-figure.toml: the spec has no [[panel]]"), std::string::npos);
    EXPECT_NE(problems_of("panel = 3\n").find("panels are [[panel]] tables"), std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = 3\n").find("a panel needs plot ="), std::string::npos);
    EXPECT_NE(problems_of("[figure]\ncolumns = \"2\"\n[[panel]]\nplot = \"convergence\"\ntheta0 = 1\n")
                  .find("'columns' must be a whole number"),
              std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"trajectory\"\ntheta0 = [1, 2]\nmethods = [\"exact\"]\n")
                  .find("a trajectory panel takes one theta0"),
              std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"trajectory\"\ntheta0 = 1\nmethods = [\"exact\"]\ntime = \"t/s\"\n")
                  .find("needs a [pendulum] table"),
              std::string::npos);
    EXPECT_NE(problems_of("[pendulum]\nlength_m = -1\n[[panel]]\nplot = \"convergence\"\ntheta0 = 1\n")
                  .find("'length_m' = -1 is out of range"),
              std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"convergence\"\ntheta0 = \"pi/2 +\"\n").find("incomplete expression"),
              std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"convergence\"\ntheta0 = 1\norders = [5, 3]\n")
                  .find("'orders' must satisfy"),
              std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"phase\"\ntheta0 = 1\nmethods = [\"exact\"]\npaper_file = \"../x\"\n")
                  .find("without a directory"),
              std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n[[panel.line]]\nlabel = \"x\"\n")
                  .find("either x = ... or y = ..."),
              std::string::npos);
}

TEST(Spec, InvalidTomlNamesThePlace) {
    EXPECT_EQ(problems_of("[[panel]]\nplot = \"phase\n").substr(0, 20), "my-figure.toml:2:14:");
}

TEST(Spec, Suggestions) {
    const std::vector<std::string> names = {"methods", "theta0", "range", "time"};
    EXPECT_EQ(suggest("metods", names), "methods");
    EXPECT_EQ(suggest("theta", names), "theta0");
    EXPECT_EQ(suggest("tim", names), "time");
    EXPECT_EQ(suggest("colour", names), "");
    EXPECT_EQ(suggest("", names), "");
    EXPECT_EQ(suggest("frist", {"first", "each", "none"}), "first");
}

TEST(Spec, PlotTableHasOneRowPerKind) {
    EXPECT_EQ(plot_table().size(), 7u);
    for (const auto& row : plot_table()) {
        EXPECT_FALSE(row.description.empty());
        EXPECT_FALSE(row.keys.empty());
        EXPECT_NE(row.build, nullptr) << row.name;
        EXPECT_EQ(find_plot(row.name), &row);
        // A row's keys agree with its behaviour: amplitudes and range.
        const std::string keys = " " + std::string(row.keys) + " ";
        EXPECT_EQ(keys.find(" theta0 ") != std::string::npos, row.amplitudes != amplitude_policy::none) << row.name;
        EXPECT_EQ(keys.find(" range ") != std::string::npos, row.range != range_kind::none) << row.name;
        // Every name is in the lists that messages and help are made from.
        EXPECT_NE(plot_names().find(std::string(row.name)), std::string::npos) << row.name;
        EXPECT_EQ(plot_names(true).find(std::string(row.name)) != std::string::npos,
                  row.amplitudes != amplitude_policy::none)
            << row.name;
    }
    EXPECT_EQ(find_plot("nonesuch"), nullptr);
    EXPECT_EQ(plot_names(true, "or"), "trajectory, phase, convergence, spectrum or pendulum");
    // A panel without plot = names every kind, the drawing too.
    try {
        parse_spec("[[panel]]\ntheta0 = 1\n", "x.toml");
        FAIL() << "no plot accepted";
    } catch (const spec_error& e) {
        EXPECT_NE(std::string(e.what()).find("pendulum"), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(Spec, StyleFileIsRelativeToTheSpec) {
    const std::string panel = "\n[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";
    EXPECT_EQ(figures::parse_spec("[figure]\nstyle = \"house.toml\"" + panel, "docs/figs/a.toml").style,
              "docs/figs/house.toml");
    EXPECT_EQ(figures::parse_spec("[figure]\nstyle = \"styles/../house.toml\"" + panel, "docs/figs/a.toml").style,
              "docs/figs/house.toml");
    EXPECT_EQ(figures::parse_spec("[figure]\nstyle = \"house.toml\"" + panel, "a.toml").style, "house.toml");
    EXPECT_EQ(figures::parse_spec(panel, "a.toml").style, "");
    // A style file outside the spec's directory is refused (tests/test_hostile_inputs.cpp).
    for (const char* bad : {"\"slides\"", "\".toml\"", "3", "\"../house.toml\"", "\"/etc/house.toml\""}) {
        try {
            figures::parse_spec(std::string("[figure]\nstyle = ") + bad + panel, "a.toml");
            ADD_FAILURE() << "style = " << bad << " accepted";
        } catch (const figures::spec_error& e) {
            EXPECT_NE(std::string(e.what()).find("a.toml:2:9:"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("style"), std::string::npos) << e.what();
        }
    }
}

namespace {

using figures::build_figure;

TEST(SpecStarts, PhaseOfEnergiesInAllRegimesWrapsAtTheEdges) {
    const auto f = parse_spec("[[panel]]\nplot = \"phase\"\nenergy = [0.5, 2, \"2.5\"]\nseparatrix = false\n", "p.toml");
    const auto& p = f.panels.front();
    ASSERT_EQ(p.starts.size(), 3u);
    EXPECT_EQ(p.starts[1].motion.kind(), pendulum::regime::separatrix);
    EXPECT_EQ(p.starts[2].motion.kind(), pendulum::regime::rotation);
    ASSERT_EQ(p.methods.size(), 1u);  // exact, the one method for every regime
    const auto fig = build_figure(f);
    const auto& panel = fig.panels.front();
    EXPECT_EQ(panel.x.min, -pi);
    EXPECT_EQ(panel.x.max, pi);
    // The libration's closed orbit, then two branches each for the separatrix and the rotation,
    // the second without a legend entry; every branch runs from -pi to pi without turning back,
    // so nothing is drawn across the panel.
    ASSERT_EQ(panel.data.size(), 5u);
    EXPECT_NE(panel.data[0].label.markup.find("libration"), std::string::npos);
    EXPECT_NE(panel.data[3].label.markup.find("rotation"), std::string::npos);
    EXPECT_TRUE(panel.data[4].label.markup.empty());
    for (std::size_t i = 1; i < 5; ++i) {
        const auto& s = panel.data[i];
        EXPECT_EQ(s.x.front(), -pi);
        EXPECT_EQ(s.x.back(), pi);
        for (std::size_t k = 1; k < s.x.size(); ++k) EXPECT_GT(s.x[k], s.x[k - 1]);
        // Energy: (theta'/w0)^2/2 + 1 - cos(theta) = E.
        const double E = i < 3 ? 2.0 : 2.5;
        for (std::size_t k = 0; k < s.x.size(); k += 37) {
            EXPECT_NEAR(s.y[k] * s.y[k] / 2 + 1 - std::cos(s.x[k]), E, 1e-13);
        }
    }
}

TEST(SpecStarts, BadStartsSayWhatWorks) {
    EXPECT_NE(problems_of("[[panel]]\nplot = \"phase\"\nenergy = [2.5]\nmethods = [\"lowest\"]\n").find("librations only"),
              std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"phase\"\nenergy = [-1]\n").find("must be > 0"), std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"phase\"\nomega0 = [1]\n").find("needs theta0"), std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"trajectory\"\nenergy = 2\n").find("t/T0"), std::string::npos);
    EXPECT_NE(problems_of("[[panel]]\nplot = \"trajectory\"\nenergy = [1, 3]\n").find("one start"), std::string::npos);
    EXPECT_EQ(problems_of("[[panel]]\nplot = \"trajectory\"\nenergy = 2\ntime = \"t/T0\"\n"), "accepted");
    EXPECT_EQ(problems_of("[[panel]]\nplot = \"trajectory\"\ntheta0 = 0\nomega0 = 1.5\nmethods = [\"exact\", \"second\"]\n"),
              "accepted");
}

TEST(SpecStarts, TrajectoryOfARotationRises) {
    const auto f = parse_spec("[[panel]]\nplot = \"trajectory\"\ntheta0 = 0\nomega0 = 2.2\nrange = [0, 2]\n", "t.toml");
    const auto fig = build_figure(f);
    const auto& s = fig.panels.front().data.front();
    for (std::size_t k = 1; k < s.y.size(); ++k) EXPECT_GT(s.y[k], s.y[k - 1]);
    EXPECT_NEAR(s.y.back(), 4 * pi, 1e-13);
}

}  // namespace
