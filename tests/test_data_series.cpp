// SPDX-License-Identifier: GPL-3.0-or-later
// Measured data in panels ([[panel.data]] and plot --data): reading, units, limits, bad
// cells, paths, the drawing and the outputs.
#include "figures/data_series.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "plot/layout.hpp"
#include "process.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

using namespace test_support;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
}

/// The reference values of tests/data/data_units.csv (make_data_units.py, mpmath).
double reference(const std::string& name) {
    static const std::map<std::string, double> values = [] {
        std::map<std::string, double> m;
        std::istringstream in(slurp(fs::path(PENDULUM_TEST_DATA) / "data_units.csv"));
        std::string line;
        while (std::getline(in, line)) {
            if (line.empty() || line[0] == '#' || line.starts_with("name,")) continue;
            const auto comma = line.find(',');
            m[line.substr(0, comma)] = std::stod(line.substr(comma + 1));
        }
        return m;
    }();
    return values.at(name);
}

/// The spec's problems as one text, or "" when it parses.
std::string problems_of(const std::string& toml, const fs::path& file) {
    try {
        figures::parse_spec(toml, file.string());
    } catch (const figures::spec_error& e) {
        return e.what();
    }
    return "";
}

/// The data series of the built figure's panel.
const plot::series& data_of(const plot::figure& f, std::size_t panel = 0, const std::string& id = "data:1") {
    for (const auto& s : f.panels.at(panel).data) {
        if (s.id == id) return s;
    }
    throw std::runtime_error("no series " + id);
}

plot::figure built(const std::string& toml, const fs::path& file) {
    return figures::build_figure(figures::parse_spec(toml, file.string()));
}

constexpr const char* period_panel = "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";

/// A period panel (T/T0, no [pendulum]) with one data series of the given keys.
std::string period_with(const std::string& data_keys) {
    return std::string(period_panel) + "[[panel.data]]\n" + data_keys;
}

void expect_near_rel(double got, double want) { EXPECT_NEAR(got, want, 1e-14 * std::fabs(want)) << want; }

}  // namespace

// ---------- Reading ----------

TEST(DataSeries, ReadsColumnsByHeaderName) {
    const auto dir = temp_dir("data-header");
    write(dir / "m.csv", "a,theta0,T,dT\n9,10,1.01,0.02\n9,20,1.03,0.03\n");
    const auto f = built(period_with("file = \"m.csv\"\nx = \"theta0\"\nx_unit = \"deg\"\ny = \"T\"\ny_unit = \"T/T0\"\n"
                                     "y_err = \"dT\"\n"),
                         dir / "s.toml");
    const auto& s = data_of(f);
    ASSERT_EQ(s.x.size(), 2u);
    EXPECT_DOUBLE_EQ(s.y[1], 1.03);
    EXPECT_DOUBLE_EQ(s.errors.y_lower[1], 0.03);
    EXPECT_DOUBLE_EQ(s.errors.y_upper[1], 0.03);
    EXPECT_EQ(s.label.markup, "m.csv");  // the file's name where no label is given
}

TEST(DataSeries, ReadsColumnsByNumberTsvAndComments) {
    const auto dir = temp_dir("data-number");
    write(dir / "m.tsv", "# measured on Monday\n\n  # indented comment\nx\ty\tlo\thi\n10\t1.01\t0.01\t0.02\n# mid\n"
                         "20\t1.03\t0.02\t0.04\r\n\n");
    const auto f = built(period_with("file = \"m.tsv\"\nx = 1\nx_unit = \"deg\"\ny = 2\ny_unit = \"T/T0\"\n"
                                     "y_err = [3, \"hi\"]\n"),
                         dir / "s.toml");
    const auto& s = data_of(f);
    ASSERT_EQ(s.x.size(), 2u);
    EXPECT_DOUBLE_EQ(s.y[1], 1.03);
    EXPECT_DOUBLE_EQ(s.errors.y_lower[1], 0.02);
    EXPECT_DOUBLE_EQ(s.errors.y_upper[1], 0.04);
}

TEST(DataSeries, ReadsInlineListsWithLowerUpperErrors) {
    const auto dir = temp_dir("data-inline");
    const auto f = built(period_with("x = [10, 20, 30]\nx_unit = \"deg\"\ny = [1.0, 1.01, 1.02]\ny_unit = \"T/T0\"\n"
                                     "y_err = [[0.1, 0.1, 0.1], [0.2, 0.2, 0.2]]\nx_err = [1, 2, 3]\n"
                                     "label = \"run $A$\"\n"),
                         dir / "s.toml");
    const auto& s = data_of(f);
    EXPECT_EQ(s.x.size(), 3u);
    EXPECT_DOUBLE_EQ(s.errors.y_upper[2], 0.2);
    EXPECT_NEAR(s.errors.x_lower[1], 2 * M_PI / 180, 1e-16);
    EXPECT_NE(s.label.markup.find("<i>A</i>"), std::string::npos);
}

TEST(DataSeries, InlineListsOfUnequalLengthAreRefused) {
    const auto p = problems_of(period_with("x = [10, 20]\nx_unit = \"deg\"\ny = [1.0]\ny_unit = \"T/T0\"\n"), "s.toml");
    EXPECT_NE(p.find("'y' has 1 values and x 2"), std::string::npos) << p;
    const auto q = problems_of(period_with("x = [10, 20]\nx_unit = \"deg\"\ny = [1.0, 1.1]\ny_unit = \"T/T0\"\n"
                                           "y_err = [0.1, -0.1]\n"),
                               "s.toml");
    EXPECT_NE(q.find("'y_err' holds finite numbers >= 0"), std::string::npos) << q;
}

// ---------- Units, against tests/data/data_units.csv (mpmath) ----------

TEST(DataSeries, AnglesConvertToTheAxisUnit) {
    const auto dir = temp_dir("data-angles");
    auto f = built(period_with("x = [30]\nx_unit = \"deg\"\ny = [1.02]\ny_unit = \"T/T0\"\n"), dir / "s.toml");
    expect_near_rel(data_of(f).x[0], reference("deg_to_rad_x"));
    f = built(std::string(period_panel) + "angle_unit = \"deg\"\n[[panel.data]]\nx = [0.5]\nx_unit = \"rad\"\ny = [1.0]\n"
                                          "y_unit = \"T/T0\"\n",
              dir / "s.toml");
    expect_near_rel(data_of(f).x[0], reference("rad_to_deg_axis_x"));
}

TEST(DataSeries, PeriodsConvertWithLengthAndG) {
    const auto dir = temp_dir("data-periods");
    const std::string pendulum = "[pendulum]\nlength_m = 0.5\ng = 9.81\n";
    const auto f = built(pendulum + period_with("x = [10]\nx_unit = \"deg\"\ny = [1.1]\ny_unit = \"T/T0\"\ny_err = [0.1]\n") +
                             "[[panel.data]]\nx = [10]\nx_unit = \"deg\"\ny = [1.5]\ny_unit = \"s\"\n",
                         dir / "s.toml");
    expect_near_rel(data_of(f).y[0], reference("ratio_to_seconds_y"));
    expect_near_rel(data_of(f).errors.y_lower[0], 0.1 * reference("t0_L0.5_g9.81"));
    EXPECT_DOUBLE_EQ(data_of(f, 0, "data:2").y[0], 1.5);
}

TEST(DataSeries, SecondsWithoutPendulumAndUnitsOffTheAxisAreRefused) {
    auto p = problems_of(period_with("x = [10]\nx_unit = \"deg\"\ny = [2.0]\ny_unit = \"s\"\n"), "s.toml");
    EXPECT_NE(p.find("'y_unit' = \"s\" needs a [pendulum] table with length_m"), std::string::npos) << p;
    p = problems_of(period_with("x = [10]\nx_unit = \"deg\"\ny = [2.0]\ny_unit = \"deg\"\n"), "s.toml");
    EXPECT_NE(p.find("'y_unit' = \"deg\" does not fit this axis, which shows a period; give \"s\" or \"T/T0\""),
              std::string::npos)
        << p;
    p = problems_of(period_with("x = [10]\ny = [2.0]\ny_unit = \"T/T0\"\n"), "s.toml");
    EXPECT_NE(p.find("needs x_unit: this axis shows an angle; give \"deg\" or \"rad\""), std::string::npos) << p;
    p = problems_of(period_with("x = [10]\nx_unit = \"furlong\"\ny = [2.0]\ny_unit = \"T/T0\"\n"), "s.toml");
    EXPECT_NE(p.find("'x_unit' = \"furlong\" is not one of"), std::string::npos) << p;
}

TEST(DataSeries, ResidualsFromTheExactPeriodAndFromAnotherMethod) {
    const auto dir = temp_dir("data-residual");
    const std::string head = "[pendulum]\nlength_m = 1.0\ng = 9.80665\n[[panel]]\nplot = \"period\"\ny = \"residual\"\n";
    const std::string data = "[[panel.data]]\nx = [60]\nx_unit = \"deg\"\ny = [2.163]\ny_unit = \"s\"\ny_err = [0.009]\n";
    auto f = built(head + data, dir / "s.toml");
    const auto& s = data_of(f);
    EXPECT_NEAR(s.y[0], reference("residual_exact_y"), 1e-15);
    expect_near_rel(s.errors.y_upper[0], reference("residual_exact_err"));
    EXPECT_NE(f.panels[0].y.label.markup.find("<i>T</i><sub>0</sub>"), std::string::npos);
    f = built(head + "residual_of = \"harmonic\"\n" + data, dir / "s.toml");
    EXPECT_NEAR(data_of(f).y[0], reference("residual_harmonic_y"), 1e-15);
    // The reference's zero line.
    bool zero = false;
    for (const auto& series : f.panels[0].data) zero = zero || (series.y == std::vector<double>{0, 0});
    EXPECT_TRUE(zero);
}

TEST(DataSeries, ResidualOfNeedsAResidualAxisAndAKnownMethod) {
    auto p = problems_of(std::string(period_panel) + "residual_of = \"harmonic\"\n", "s.toml");
    EXPECT_NE(p.find("'residual_of' is the reference of a residual panel"), std::string::npos) << p;
    p = problems_of("[[panel]]\nplot = \"period\"\ny = \"residual\"\nresidual_of = \"harmonc\"\n", "s.toml");
    EXPECT_NE(p.find("did you mean harmonic?"), std::string::npos) << p;
}

TEST(DataSeries, TimesConvertToTheTrajectoryAxis) {
    const auto dir = temp_dir("data-times");
    const std::string head = "[pendulum]\nlength_m = 1.0\ng = 9.80665\n[[panel]]\nplot = \"trajectory\"\ntheta0 = \"90deg\"\n"
                             "methods = [\"exact\"]\n";
    const auto one = [&](const std::string& time, const std::string& unit, double value) {
        const auto f = built(head + time + "[[panel.data]]\nx = [" + std::to_string(value) + "]\nx_unit = \"" + unit +
                                 "\"\ny = [1]\ny_unit = \"rad\"\n",
                             dir / "s.toml");
        return data_of(f).x[0];
    };
    expect_near_rel(one("", "s", 1.5), reference("time_s_to_t_over_T"));
    expect_near_rel(one("", "t/T0", 0.8), reference("time_t0_to_t_over_T"));
    expect_near_rel(one("time = \"t/T0\"\n", "t/T", 0.5), reference("time_T_to_t_over_T0"));
    expect_near_rel(one("time = \"t/s\"\n", "t/T0", 0.25), reference("time_t0_to_seconds"));
}

TEST(DataSeries, PhaseAndCoefficientPanelsTakeData) {
    const auto dir = temp_dir("data-phase");
    auto f = built("[[panel]]\nplot = \"phase\"\ntheta0 = [\"pi/2\"]\nmethods = [\"exact\"]\n[[panel.data]]\nx = [0.5]\n"
                   "x_unit = \"rad\"\ny = [0.9]\n",
                   dir / "s.toml");
    EXPECT_DOUBLE_EQ(data_of(f).y[0], 0.9);
    f = built("[[panel]]\nplot = \"coefficient\"\nmethods = [\"exact\"]\n[[panel.data]]\nx = [90]\nx_unit = \"deg\"\n"
              "y = [0.9]\n",
              dir / "s.toml");
    EXPECT_NEAR(data_of(f).x[0], M_PI / 2, 1e-15);
    const auto p = problems_of("[[panel]]\nplot = \"spectrum\"\ntheta0 = [1]\nmethods = [\"exact\"]\n[[panel.data]]\n"
                               "x = [1]\ny = [1]\n",
                               "s.toml");
    EXPECT_NE(p.find("key 'data' does not apply to plot 'spectrum'"), std::string::npos) << p;
}

// ---------- Limits: N accepted, N + 1 refused ----------

TEST(DataSeries, RowsUpToTheLimit) {
    const auto dir = temp_dir("data-rows");
    std::string rows = "x,y\n";
    for (std::size_t i = 0; i < figures::max_data_rows; ++i) rows += "1,1\n";
    write(dir / "m.csv", rows);
    const std::string spec = period_with("file = \"m.csv\"\nx = \"x\"\nx_unit = \"rad\"\ny = \"y\"\ny_unit = \"T/T0\"\n");
    EXPECT_EQ(problems_of(spec, dir / "s.toml"), "");
    write(dir / "m.csv", rows + "1,1\n");
    const auto p = problems_of(spec, dir / "s.toml");
    EXPECT_NE(p.find("m.csv:100002:1: more than 100000 rows; a data file holds at most 100000"), std::string::npos) << p;
}

TEST(DataSeries, BytesUpToTheLimit) {
    const auto dir = temp_dir("data-bytes");
    std::string text = "x,y\n1,1\n";
    const std::string comment = "#" + std::string(98, 'c') + "\n";
    while (text.size() + comment.size() <= figures::max_data_file_bytes) text += comment;
    text += "#" + std::string(figures::max_data_file_bytes - text.size() - 2, 'c') + "\n";
    ASSERT_EQ(text.size(), figures::max_data_file_bytes);
    write(dir / "m.csv", text);
    const std::string spec = period_with("file = \"m.csv\"\nx = 1\nx_unit = \"rad\"\ny = 2\ny_unit = \"T/T0\"\n");
    EXPECT_EQ(problems_of(spec, dir / "s.toml"), "");
    write(dir / "m.csv", text + "\n");
    const auto p = problems_of(spec, dir / "s.toml");
    EXPECT_NE(p.find("has 1048577 bytes; at most 1048576"), std::string::npos) << p;
}

TEST(DataSeries, InlineValuesUpToTheLimit) {
    std::string values;
    for (std::size_t i = 0; i < figures::max_data_rows; ++i) values += i ? ",1" : "1";
    const auto spec = [&](const std::string& v) {
        return period_with("x = [" + v + "]\nx_unit = \"rad\"\ny = [" + v + "]\ny_unit = \"T/T0\"\n");
    };
    EXPECT_EQ(problems_of(spec(values), "s.toml"), "");
    const auto p = problems_of(spec(values + ",1"), "s.toml");
    EXPECT_NE(p.find("'x' lists 100001 values; at most 100000"), std::string::npos) << p;
}

TEST(DataSeries, SeriesPerPanelUpToTheLimit) {
    std::string spec = period_panel;
    for (std::size_t i = 0; i < figures::max_data_series_per_panel; ++i) {
        spec += "[[panel.data]]\nx = [1]\nx_unit = \"rad\"\ny = [1]\ny_unit = \"T/T0\"\n";
    }
    EXPECT_EQ(problems_of(spec, "s.toml"), "");
    spec += "[[panel.data]]\nx = [1]\nx_unit = \"rad\"\ny = [1]\ny_unit = \"T/T0\"\n";
    const auto p = problems_of(spec, "s.toml");
    EXPECT_NE(p.find("a panel takes at most 8 [[panel.data]] series; this one has 9"), std::string::npos) << p;
}

TEST(DataSeries, ColumnNumbersUpToTheColumns) {
    const auto dir = temp_dir("data-columns");
    write(dir / "m.csv", "a,b,c\n1,2,3\n");
    const auto spec = [](int n) {
        return period_with("file = \"m.csv\"\nx = 1\nx_unit = \"rad\"\ny = " + std::to_string(n) + "\ny_unit = \"T/T0\"\n");
    };
    EXPECT_EQ(problems_of(spec(3), dir / "s.toml"), "");
    const auto p = problems_of(spec(4), dir / "s.toml");
    EXPECT_NE(p.find("m.csv:1:1: 'y' = 4: there is no column 4; the file has 3 (numbered from 1)"), std::string::npos) << p;
}

// ---------- Bad cells: FILE:LINE:COLUMN naming the column ----------

TEST(DataSeries, EachBadCellIsNamedByFileLineAndColumn) {
    const auto dir = temp_dir("data-cells");
    const std::string spec =
        period_with("file = \"m.csv\"\nx = \"theta0\"\nx_unit = \"deg\"\ny = \"T\"\ny_unit = \"T/T0\"\ny_err = \"dT\"\n");
    const std::pair<std::string, std::string> cases[] = {
        {"theta0,T,dT\n10,1.0,0.1\n20,abc,0.1\n", "m.csv:3:4: column 'T': 'abc' is not a number"},
        {"theta0,T,dT\n10, ,0.1\n", "m.csv:2:5: column 'T': an empty cell; each cell is a number"},
        {"theta0,T,dT\n10,nan,0.1\n", "m.csv:2:4: column 'T': 'nan' is not a finite number"},
        {"theta0,T,dT\n10,1e999,0.1\n", "m.csv:2:4: column 'T': '1e999' is not a number"},
        {"theta0,T,dT\n10,1.0,-0.1\n", "m.csv:2:8: column 'dT': an uncertainty is >= 0, got '-0.1'"},
        {"theta0,T,dT\n10,1.0\n", "m.csv:2:7: the row has 2 cells and the header 3: no cell for column 'dT'"},
        {"theta0,T,dT\n10,1.0,0.1,7\n", "m.csv:2:12: the row has 4 cells and the header 3: a cell past the last column 'dT'"},
        {"# c\ntheta0,Tx,dT\n10,1.0,0.1\n", "m.csv:2:1: 'y' = \"T\": no such column in the header; columns: theta0, Tx, dT"},
        {"theta0,T\x01,dT\n10,1.0,0.1\n", "m.csv:1:8: the name of column 2 "},
        {"theta0,T\xff,dT\n10,1.0,0.1\n", "m.csv:1:8: the name of column 2 "},
        {"# only a comment\n", "m.csv: has no header row"},
        {"theta0,T,dT\n", "m.csv:1:1: has a header but no data rows"},
    };
    for (const auto& [text, want] : cases) {
        write(dir / "m.csv", text);
        const auto p = problems_of(spec, dir / "s.toml");
        EXPECT_NE(p.find(dir.string() + "/" + want), std::string::npos) << text << "\n" << p;
    }
}

TEST(DataSeries, HostileCellsAreNotEchoed) {
    const auto dir = temp_dir("data-hostile");
    write(dir / "m.csv", "x,y\n1,\x1b]0;pwned\x07\n");
    const auto r = run_cli("plot period --methods exact --data 'm.csv:x[rad],y[T/T0]' -f png", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("m.csv:2:3: column 'y': is not a number"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
    EXPECT_TRUE(files_in(dir) == std::set<std::string>{"m.csv"});  // nothing partial written
}

// ---------- Paths ----------

TEST(DataSeries, AFileOutsideTheSpecsTreeIsRefused) {
    const auto dir = temp_dir("data-outside");
    fs::create_directories(dir / "spec");
    write(dir / "secret.csv", "x,y\n1,1\n");
    fs::create_symlink(dir / "secret.csv", dir / "spec" / "link.csv");
    const auto spec = [](const std::string& file) {
        return period_with("file = \"" + file + "\"\nx = 1\nx_unit = \"rad\"\ny = 2\ny_unit = \"T/T0\"\n");
    };
    auto p = problems_of(spec("../secret.csv"), dir / "spec" / "s.toml");
    EXPECT_NE(p.find("must stay inside the spec's directory"), std::string::npos) << p;
    p = problems_of(spec((dir / "secret.csv").string()), dir / "spec" / "s.toml");
    EXPECT_NE(p.find("must be a path relative to the spec's directory"), std::string::npos) << p;
    p = problems_of(spec("link.csv"), dir / "spec" / "s.toml");
    EXPECT_NE(p.find("'file' = \"link.csv\" leads out of the spec's directory"), std::string::npos) << p;
    p = problems_of(spec("none.csv"), dir / "spec" / "s.toml");
    EXPECT_NE(p.find("cannot read data file"), std::string::npos) << p;
}

// ---------- Outputs: depfile, legend, PNG, data ----------

TEST(DataSeries, TheDepfileListsTheDataFile) {
    const auto dir = temp_dir("data-depfile");
    fs::copy(fs::path(PENDULUM_TEST_DATA) / ".." / ".." / "examples" / "lab", dir / "lab");
    const auto r = run_cli("render lab/lab.toml -f svg -o . --depfile lab.d", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto d = slurp(dir / "lab.d");
    EXPECT_NE(d.find("lab/measured.csv"), std::string::npos) << d;
}

TEST(DataSeries, TheLegendHasAnEntryWithMarkerAndBar) {
    const auto dir = temp_dir("data-legend");
    const auto f = built(period_with("x = [10, 20]\nx_unit = \"deg\"\ny = [1.0, 1.01]\ny_unit = \"T/T0\"\n"
                                     "y_err = [0.01, 0.01]\nlabel = \"measured\"\n"),
                         dir / "s.toml");
    const auto& s = data_of(f);
    EXPECT_EQ(s.label.markup, "measured");
    EXPECT_EQ(s.data_slot, 0);
    EXPECT_EQ(s.line, plot::line_style::none);
    EXPECT_FALSE(s.errors.empty());
}

TEST(DataSeries, BesideDataTheExactSolutionIsALineUnlessTheSpecSaysOtherwise) {
    const auto dir = temp_dir("data-exact-line");
    const std::string data = "[[panel.data]]\nx = [10, 20]\nx_unit = \"deg\"\ny = [1.0, 1.01]\ny_unit = \"T/T0\"\n";
    const auto exact_of = [](const plot::figure& f) -> const plot::series& { return data_of(f, 0, "exact"); };
    // The themes draw the exact solution with circles; beside measured points it is a line.
    const auto with_data = built(period_with(data.substr(std::string("[[panel.data]]\n").size())), dir / "a.toml");
    EXPECT_EQ(exact_of(with_data).marker, plot::marker_style::none);
    EXPECT_EQ(exact_of(with_data).line, plot::line_style::solid);
    EXPECT_TRUE(exact_of(with_data).style_key.empty());
    // Without data the theme's style stays.
    const auto without = built(period_panel, dir / "b.toml");
    EXPECT_EQ(exact_of(without).style_key, "exact");
    EXPECT_EQ(exact_of(without).marker, plot::marker_style::open_circle);
    // A marker the spec gives is kept.
    const auto own = built("[[panel]]\nplot = \"period\"\nmethods = [{ method = \"exact\", marker = \"circle\" }]\n" + data,
                           dir / "c.toml");
    EXPECT_EQ(exact_of(own).marker, plot::marker_style::open_circle);
    // The other methods keep their theme styles.
    const auto two = built("[[panel]]\nplot = \"period\"\nmethods = [\"exact\", \"harmonic\"]\n" + data, dir / "d.toml");
    EXPECT_EQ(data_of(two, 0, "harmonic").style_key, "harmonic");
}

namespace {

/// Pixels of a PNG near a colour, and the rows they span in a column band.
struct colour_count {
    int pixels = 0;
    int top = 1 << 30;
    int bottom = -1;
};

colour_count count_colour(const fs::path& png, int r, int g, int b) {
    cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
    colour_count c;
    const int w = cairo_image_surface_get_width(s);
    const int h = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const auto* px = reinterpret_cast<const std::uint32_t*>(data + y * stride) + x;
            const int pr = (*px >> 16) & 0xff, pg = (*px >> 8) & 0xff, pb = *px & 0xff;
            if (std::abs(pr - r) + std::abs(pg - g) + std::abs(pb - b) < 40) {
                ++c.pixels;
                c.top = std::min(c.top, y);
                c.bottom = std::max(c.bottom, y);
            }
        }
    }
    cairo_surface_destroy(s);
    return c;
}

}  // namespace

TEST(DataSeries, ThePngHasTheErrorBars) {
    const auto dir = temp_dir("data-png");
    // One point in the middle of a fixed frame, in the slides theme's first data colour.
    const std::string head = std::string(period_panel) + "y_range = [0.5, 1.5]\nrange = [0, 3]\n[[panel.data]]\nx = [1.5]\n"
                                                         "x_unit = \"rad\"\ny = [1.0]\ny_unit = \"T/T0\"\n";
    write(dir / "bars.toml", head + "y_err = [0.3]\n[figure]\nlegend = \"none\"\n");
    write(dir / "plain.toml", head + "[figure]\nlegend = \"none\"\n");
    ASSERT_EQ(run_cli("render bars.toml plain.toml -f png --theme slides --dpi 100", dir).status, 0);
    const auto bars = count_colour(dir / "bars.png", 0xd5, 0x5e, 0x00);
    const auto plain = count_colour(dir / "plain.png", 0xd5, 0x5e, 0x00);
    ASSERT_GT(plain.pixels, 0);
    EXPECT_GT(bars.pixels, plain.pixels + 50);
    // The bar spans 0.6 of the 1.0 the axis shows: more than half the frame's height.
    EXPECT_GT(bars.bottom - bars.top, 4 * (plain.bottom - plain.top));
}

TEST(DataSeries, ResidualsAreInTheDataOutput) {
    const auto dir = temp_dir("data-out");
    fs::copy(fs::path(PENDULUM_TEST_DATA) / ".." / ".." / "examples" / "lab", dir / "lab");
    const auto r = run_cli("data lab/lab.toml", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    // Panel b, the residuals: the first point (10 degrees, 2.014 s).
    const auto at = r.out.find("b,measured,10,");
    ASSERT_NE(at, std::string::npos) << r.out;
    const auto line = r.out.substr(at, r.out.find('\n', at) - at);
    // panel,series,x,y,id,y_err_lower,y_err_upper: y is the residual, the errors its bars.
    std::vector<std::string> cells;
    std::stringstream cut(line);
    for (std::string c; std::getline(cut, c, ',');) cells.push_back(c);
    ASSERT_EQ(cells.size(), 7u) << line;
    // Printed with the digits a difference deserves (figures::difference_digits): within one
    // unit of its last digit.
    const std::string mantissa = cells[3].substr(0, cells[3].find('e'));
    const auto point = mantissa.find('.');
    const int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
    const int exponent = cells[3].find('e') == std::string::npos ? 0 : std::stoi(cells[3].substr(cells[3].find('e') + 1));
    EXPECT_NEAR(std::stod(cells[3]), reference("measured_residual_first"), std::pow(10.0, exponent - decimals)) << line;
    EXPECT_EQ(cells[5], cells[6]) << line;  // a symmetric uncertainty
    EXPECT_GT(std::stod(cells[5]), 0) << line;
}

// ---------- plot --data ----------

TEST(DataSeries, PlotDataIsOneCommand) {
    const auto dir = temp_dir("data-plot");
    fs::copy_file(fs::path(PENDULUM_TEST_DATA) / ".." / ".." / "examples" / "lab" / "measured.csv", dir / "measured.csv");
    auto r = run_cli("plot period --methods exact,harmonic --angle-unit deg --length 1 "
                     "--data 'measured.csv:theta0[deg],T[s],dT' --data 'measured.csv:1[deg],2[s]' -f png",
                     dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(files_in(dir).count("period.png"));
    r = run_cli("plot period --methods exact --data 'measured.csv:theta0[deg],T[s],dT' -f png --name x", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("'y_unit' = \"s\" needs a [pendulum] table"), std::string::npos) << r.err;
    r = run_cli("plot period --methods exact --length 1 --data 'measured.csv:theta0[deg],Tx[s]' -f png --name x", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("measured.csv:3:1: 'y' = \"Tx\": no such column"), std::string::npos) << r.err;
    r = run_cli("plot period --methods exact --data 'measured.csv' -f png --name x", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("give FILE:X[UNIT],Y[UNIT][,YERR]"), std::string::npos) << r.err;
    r = run_cli("plot period --methods exact --g 9.8 -f png --name x", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--g '9.8' needs --length"), std::string::npos) << r.err;
    EXPECT_FALSE(files_in(dir).count("x.png"));
}

// ---------- The plot layer and the themes ----------

TEST(DataSeries, ErrorBarsCountInTheAxisLimits) {
    plot::series s;
    s.x = {1, 2};
    s.y = {1, 1};
    s.line = plot::line_style::none;
    s.marker = plot::marker_style::filled_square;
    const auto plain = plot::axis_ticks(plot::axis{}, {s}, false);
    s.errors.y_lower = {0.5, 0.1};
    s.errors.y_upper = {0.1, 2.0};
    const auto with_bars = plot::axis_ticks(plot::axis{}, {s}, false);
    EXPECT_GT(plain.lo, 0.5);
    EXPECT_LE(with_bars.lo, 0.5);
    EXPECT_GE(with_bars.hi, 3.0);
    s.errors.x_upper = {0, 4};
    s.errors.x_lower = {0, 0};
    EXPECT_GE(plot::axis_ticks(plot::axis{}, {s}, true).hi, 6.0);
}

TEST(DataSeries, ThemeDataStylesAreChecked) {
    const auto dir = temp_dir("data-theme");
    write(dir / "s.toml", period_with("x = [1]\nx_unit = \"rad\"\ny = [1]\ny_unit = \"T/T0\"\n"));
    auto r = run_cli("render s.toml -f png --set 'data_markers=[\"diamond\", \"triangle\"]' "
                     "--set 'data_palette=[\"#123456\"]'",
                     dir);
    EXPECT_EQ(r.status, 0) << r.err;
    r = run_cli("render s.toml -f svg --set 'data_markers=[\"hexagon\"]'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("'data_markers' = \"hexagon\" is not one of square, triangle, diamond, dot"), std::string::npos)
        << r.err;
    r = run_cli("render s.toml -f svg --set 'data_palette=[\"red\"]'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("'data_palette' must be a colour"), std::string::npos) << r.err;
    EXPECT_FALSE(files_in(dir).count("s.svg"));
}

TEST(DataSeries, HostileLabelsAndFileNamesStayText) {
    const auto dir = temp_dir("data-hostile-label");
    // A label is TeX like every other label: a macro the tool does not know is refused.
    auto p = problems_of(period_with("x = [1]\nx_unit = \"rad\"\ny = [1]\ny_unit = \"T/T0\"\n"
                                     "label = \"$\\\\input{/etc/passwd}$\"\n"),
                         dir / "s.toml");
    EXPECT_NE(p.find("'label': "), std::string::npos) << p;
    // A file's name as the default label is text: markup characters are escaped.
    write(dir / "a<b>&c.csv", "x,y\n1,1\n");
    const auto f = built(period_with("file = \"a<b>&c.csv\"\nx = 1\nx_unit = \"rad\"\ny = 2\ny_unit = \"T/T0\"\n"),
                         dir / "s.toml");
    EXPECT_EQ(data_of(f).label.markup, "a&lt;b&gt;&amp;c.csv");
}
