// SPDX-License-Identifier: GPL-3.0-or-later
// Every number right on every surface, the last remainder: the precision a start's regime
// needs (doubled up to a stated ceiling), the digits printed on error axes, and describe's
// axis ranges; against numbers_edges.csv (make_numbers_edges.py, mpmath) and the data.
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/figure_data.hpp"
#include "figures/themes.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/start_energy.hpp"
#include "plot/render.hpp"
#include "figures/panel_support.hpp"
#include "process.hpp"
#include "reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

using test_support::run_cli;

std::vector<std::string> split_at(const std::string& text, char sep) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, sep)) out.push_back(item);
    return out;
}

double number(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

/// A CSV's rows as maps from its header's names.
std::vector<std::map<std::string, std::string>> table(const std::string& csv) {
    const auto lines = split_at(csv, '\n');
    std::vector<std::map<std::string, std::string>> rows;
    if (lines.empty()) return rows;
    const auto names = split_at(lines[0], ',');
    for (std::size_t i = 1; i < lines.size(); ++i) {
        if (lines[i].empty()) continue;
        const auto fields = split_at(lines[i], ',');
        std::map<std::string, std::string> row;
        for (std::size_t j = 0; j < names.size() && j < fields.size(); ++j) row[names[j]] = fields[j];
        rows.push_back(row);
    }
    return rows;
}

/// |got - want| in ulps of want.
double ulps(double got, double want) {
    const double scale = std::fabs(want);
    return std::fabs(got - want) / (std::nextafter(scale, INFINITY) - scale);
}

// --- the precision a start needs ---------------------------------------------------------

// Starts only more than 2560 bits could decide were refused (2 - E below 2^-1272 of its terms
// size and less); the precision is now doubled from 128 bits up to the ceiling, 65536, and
// these are computed: each T/T0 (T_rev/T0) within 4 ulps of mpmath at 4000 bits, down to the
// smallest distance from the separatrix a double holds.
TEST(StartPrecision, StartsPast2560BitsAreComputed) {
    const auto rows = test_support::read_reference_text("numbers_edges.csv");
    int checked = 0;
    for (const auto& row : rows) {
        if (row.at(0) != "period") continue;
        const auto r = run_cli(row.at(1));
        ASSERT_EQ(r.status, 0) << row.at(1) << ": " << r.err;
        const auto got = table(r.out).at(0);
        EXPECT_EQ(got.at("regime"), row.at(3)) << row.at(1);
        const std::string& field = row.at(3) == "libration" ? got.at("period_exact") : got.at("revolution_period");
        EXPECT_LE(ulps(number(field), number(row.at(2))), 4.0) << row.at(1) << ": " << field << ", want " << row.at(2);
        ++checked;
    }
    EXPECT_EQ(checked, 5);
}

// The ceiling: 2 - E = 1e-19725 of an energy as written is seen at 65536 bits only (its terms
// less 65527 bits), and refused naming the ceiling; 1e-19726 vanishes at 32768 and 65536 bits,
// and is refused the same way: a gap below what the ceiling resolves is not the separatrix
// (2pi/3 with 1 is, proved exactly: test_numbers_last).
TEST(StartPrecision, TheCeilingIsStatedAndHeld) {
    EXPECT_EQ(pendulum::start_first_bits, 128);
    EXPECT_EQ(pendulum::start_ceiling_bits, 65536);
    const auto seen = run_cli("eval --energy 2-1e-19725");
    EXPECT_EQ(seen.status, 2);
    EXPECT_EQ(seen.out, "");
    EXPECT_NE(seen.err.find("energy = 2-1e-19725: its energy is 2 within 65527 bits of its terms"), std::string::npos)
        << seen.err;
    EXPECT_NE(seen.err.find("cannot be decided from the numbers as written within 65536 bits"), std::string::npos)
        << seen.err;
    const auto below = run_cli("eval --energy 2-1e-19726");
    EXPECT_EQ(below.status, 2);
    EXPECT_EQ(below.out, "");
    EXPECT_NE(below.err.find("cannot be decided from the numbers as written within 65536 bits"), std::string::npos)
        << below.err;
    // E = 0 to every bit up to the ceiling: refused with both energies and the ceiling.
    const auto rest = run_cli("eval --theta0 2pi --omega0 0");
    EXPECT_EQ(rest.status, 2);
    EXPECT_NE(rest.err.find("at 65536 bits and"), std::string::npos) << rest.err;
    EXPECT_NE(rest.err.find("needs more than 65536 bits"), std::string::npos) << rest.err;
}

// A decided start whose motion a double cannot hold is refused, never computed from a 0: 2 k'
// (the distance from the top) at least the smallest normal double, as an amplitude's distance
// from pi must be (2 - E = 2.4755e-616 gives 2.22508e-308, 2.4753e-616 gives 2.22499e-308), on
// both sides of the separatrix; and a libration's amplitude not 0 as a double (2pi + 2.4704e-324
// at rest rounds to 5e-324, 2pi + 2.4703e-324 to 0). Past 2560 bits these printed 2^65 for
// T/T0, exit 1 from agm, or an amplitude of 0.
TEST(StartPrecision, AMotionADoubleCannotHoldIsRefused) {
    for (const char* sign : {"-", "+"}) {
        const auto ok = run_cli(std::string("eval --energy 2") + sign + "2.4755e-616");
        EXPECT_EQ(ok.status, 0) << sign << ok.err;
        const auto no = run_cli(std::string("eval --energy 2") + sign + "2.4753e-616");
        EXPECT_EQ(no.status, 2) << sign << no.out;
        EXPECT_EQ(no.out, "");
        EXPECT_NE(no.err.find("2 k' = 2.2249943820153794e-308"), std::string::npos) << no.err;
        EXPECT_NE(no.err.find("below the smallest normal double, 2.2250738585072014e-308"), std::string::npos) << no.err;
    }
    const auto tiny = run_cli("eval --theta0 2pi+2.4704e-324 --omega0 0");
    ASSERT_EQ(tiny.status, 0) << tiny.err;
    EXPECT_EQ(table(tiny.out).at(0).at("amplitude"), "5e-324");
    const auto zero = run_cli("eval --theta0 2pi+2.4703e-324 --omega0 0");
    EXPECT_EQ(zero.status, 2);
    EXPECT_EQ(zero.out, "");
    EXPECT_NE(zero.err.find("its amplitude is 2.4703e-324, below the smallest double"), std::string::npos) << zero.err;
    const auto far = run_cli("trajectory --theta0 2pi+1e-400 --omega0 0 --at 0.5");
    EXPECT_EQ(far.status, 2);
    EXPECT_NE(far.err.find("its amplitude is 1e-400"), std::string::npos) << far.err;
}

// --- digits on error axes ------------------------------------------------------------------

/// True for an error axis by its label: a relative error, or |T_m/T - 1| (|T_N/T - 1|).
bool error_label(const std::string& label) {
    return label.find("error") != std::string::npos || label.find("\u2212 1|") != std::string::npos ||
           label.find("- 1|") != std::string::npos;
}

/// The significant digits of a number as printed ("0.00123" 3, "1.5e-07" 2, "120" 3).
int significant_digits(const std::string& text) {
    const std::string mantissa = text.substr(0, text.find_first_of("eE"));
    std::string digits;
    for (const char c : mantissa) {
        if (c >= '0' && c <= '9') digits += c;
    }
    const auto first = digits.find_first_not_of('0');
    return first == std::string::npos ? 1 : static_cast<int>(digits.size() - first);
}

/// Every still built-in with its panels' numbers, as `data` makes them with the paper theme.
std::vector<figures::figure_numbers> still_builtins() {
    static const plot::theme paper = figures::load_theme("paper");
    std::vector<figures::figure_numbers> out;
    for (const auto& e : figures::catalog()) {
        if (e.spec.animation) continue;
        out.push_back(figures::numbers_of(e, {}, paper, paper.dpi));
    }
    return out;
}

// The values on an error axis are right to 1e-12 relative (period_error's drawing precision)
// and were printed with 17 digits (period-error's |T_m/T - 1| off by 2.8e-14 of itself showed
// its noise). One rule, figures::printed_digits: an error axis' values get the 12 digits
// they are right to, in every format; every other axis keeps every digit of a double. Every
// still built-in: its error axes found by their labels (Fig. 7(b), period-error,
// period-formulas, convergence), each printed value at most 12 digits and its double's
// rounding to 12 (within 5e-12 of itself); the other axes untouched.
TEST(ErrorAxes, PrintedValuesCarryTheDigitsTheyDeserve) {
    EXPECT_EQ(figures::error_axis_relative, 1e-12);
    int error_panels = 0;
    std::size_t printed = 0;
    for (const auto& n : still_builtins()) {
        for (std::size_t i = 0; i < n.panels.size(); ++i) {
            const auto& p = n.panels[i];
            const bool error = error_label(p.y.label);
            error_panels += error ? 1 : 0;
            for (const auto& s : p.series) {
                EXPECT_EQ(s.y_digits, error ? 12 : 0) << n.id << " " << p.name << " " << s.id << ": " << p.y.label;
                if (!error || s.reference_line) continue;
                for (const double v : s.y) {
                    if (!std::isfinite(v) || v == 0) continue;
                    const std::string text = figures::format_digits(v, s.y_digits);
                    EXPECT_LE(significant_digits(text), 12) << n.id << " " << p.name << ": " << text;
                    EXPECT_LE(std::fabs(number(text) - v), 5e-12 * std::fabs(v)) << n.id << ": " << text;
                    ++printed;
                }
            }
        }
        // Every format: the long and wide CSV and the JSON print what format_digits gives.
        const std::string csv = figures::numbers_csv(n, figures::data_layout::long_rows);
        const std::string wide = figures::numbers_csv(n, figures::data_layout::wide);
        const std::string json = figures::numbers_json(n);
        for (const auto& p : n.panels) {
            for (const auto& s : p.series) {
                if (s.y_digits == 0 || s.y.empty()) continue;
                for (const double v : s.y) {
                    if (!std::isfinite(v)) continue;
                    const std::string text = figures::format_digits(v, s.y_digits);
                    EXPECT_NE(csv.find("," + text + ","), std::string::npos) << n.id << ": " << text;
                    EXPECT_NE(wide.find(text), std::string::npos) << n.id << ": " << text;
                    EXPECT_NE(json.find(text), std::string::npos) << n.id << ": " << text;
                    break;  // one value per series and format is enough to show the path
                }
            }
        }
    }
    EXPECT_GE(error_panels, 4);
    EXPECT_GT(printed, 500u);
}

// A value printed to its digits: rounded once to `digits` significant digits, written shortest,
// every digit of a double where digits is 0 (and for what is not finite).
TEST(ErrorAxes, FormatDigitsRoundsOnceAndWritesShortest) {
    EXPECT_EQ(figures::format_digits(0.0012300000000000001, 12), "0.00123");
    EXPECT_EQ(figures::format_digits(1.2345678901234567, 12), "1.23456789012");
    EXPECT_EQ(figures::format_digits(9.9999999999996e-5, 12), pendulum::format_double(1e-4));  // "1e-04"
    EXPECT_EQ(figures::format_digits(-2.71828182845904523e-200, 12), "-2.71828182846e-200");
    EXPECT_EQ(figures::format_digits(1.2345678901234567, 0), "1.2345678901234567");
    EXPECT_EQ(figures::format_digits(0.1, 12), "0.1");
}

// Tick labels on every error axis, in the paper and slides themes: the fewest decimals that
// show every tick (not every label ending in 0 after its point) and at most 3 significant
// digits (steps 1, 2, 2.5 and 5 times a power of ten), on the linear and the log axes.
TEST(ErrorAxes, TickLabelsCarryNoDigitBeyondTheirStep) {
    int axes = 0;
    for (const char* name : {"paper", "slides"}) {
        const plot::theme theme = figures::load_theme(name);
        for (const auto& e : figures::catalog()) {
            if (e.spec.animation) continue;
            const plot::figure f = plot::with_theme_styles(figures::build(e, figures::sized_by({}, theme)), theme);
            const auto frames = plot::panel_frames(f, theme);
            for (std::size_t i = 0; i < f.panels.size() && i < frames.size(); ++i) {
                if (!error_label(figures::plain_text(f.panels[i].y.label.markup))) continue;
                ++axes;
                bool all_trailing_zero = true;
                bool any_point = false;
                for (const auto& label : frames[i].y_labels) {
                    // The mantissa: before "x10<sup>" or a power's "<sup>" (10^-12 is one digit).
                    const std::string plain = figures::plain_text(label);
                    const std::string mantissa =
                        figures::plain_text(label.substr(0, std::min(label.find("\u00d7"), label.find("<sup>"))));
                    if (mantissa.find('.') != std::string::npos) {
                        any_point = true;
                        all_trailing_zero = all_trailing_zero && mantissa.back() == '0';
                    }
                    EXPECT_LE(significant_digits(mantissa), 3) << e.id << " " << name << ": " << plain;
                }
                EXPECT_FALSE(any_point && all_trailing_zero) << e.id << " " << name << " panel " << i;
            }
        }
    }
    EXPECT_GE(axes, 8);
}

// --- describe's axis ranges ---------------------------------------------------------------

/// The spec file `name` with `text` in a fresh directory.
std::filesystem::path spec_file(const std::string& dir_name, const std::string& text) {
    const auto dir = test_support::temp_dir(dir_name);
    std::ofstream(dir / "spec.toml") << text;
    return dir / "spec.toml";
}

/// x or y of the autoscaled series of `data`'s long CSV, from the smallest to the largest.
std::pair<double, double> data_extent(const std::string& csv, bool y) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& row : table(csv)) {
        const double v = number(row.at(y ? "y" : "x"));
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    return {lo, hi};
}

/// The frame's limits of axis "x" or "y" of the first panel, as `data -f json` gives them.
std::pair<double, double> frame_of(const std::string& json, const std::string& axis) {
    const std::regex limits("\"" + axis + "\":\\{\"label\":\"[^\"]*\",\"unit\":\"[^\"]*\",\"scale\":\"linear\","
                            "\"min\":([^,]+),\"max\":([^}]+)\\}");
    std::smatch m;
    if (!std::regex_search(json, m, limits)) return {NAN, NAN};
    return {number(m[1]), number(m[2])};
}

/// A value as describe speaks it on a pi axis: three digits of its multiple of pi.
std::string spoken_pi(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3gpi", v / M_PI);
    return buf;
}

// An autoscaled panel whose frame reaches well past its data: theta(t) of the amplitude 0.9
// spans +-0.9 (the amplitude, reached at t = 0 and T/2), and its pi axis is laid out to +-pi/2.
// describe says the data's range and then the frame, each as the data and the layout give them.
TEST(DescribeRange, TheDataAndTheFrameAreBothSaid) {
    const auto spec = spec_file("describe-range", "[[panel]]\nplot = \"trajectory\"\ntheta0 = [\"0.9\"]\n"
                                                  "methods = [\"exact\"]\n");
    const auto d = run_cli("describe " + spec.string());
    ASSERT_EQ(d.status, 0) << d.err;
    const auto data = run_cli("data " + spec.string());
    const auto json = run_cli("data " + spec.string() + " -f json");
    ASSERT_EQ(data.status, 0) << data.err;
    const auto [y0, y1] = data_extent(data.out, true);
    EXPECT_EQ(y0, -0.9);  // the turning points, exactly
    EXPECT_EQ(y1, 0.9);
    const auto [f0, f1] = frame_of(json.out, "y");
    EXPECT_EQ(f0, -M_PI / 2);
    EXPECT_EQ(f1, M_PI / 2);
    const std::string want = "theta from " + spoken_pi(y0) + " to " + spoken_pi(y1) + " (its axis from -pi/2 to pi/2)";
    EXPECT_NE(d.out.find(want), std::string::npos) << want << "\n" << d.out;
    // x: the frame is 2.7 % wider than the data (room for the markers): only the data is said.
    const auto [x0, x1] = data_extent(data.out, false);
    const auto [g0, g1] = frame_of(json.out, "x");
    EXPECT_LT(g0, x0);
    EXPECT_GT(g1, x1);
    EXPECT_NE(d.out.find("t/T from 0 to 1, theta"), std::string::npos) << d.out;
    std::filesystem::remove_all(spec.parent_path());
}

// A frame narrower than the data: the range said is the data cut at the axis (y_range
// [-0.5, 0.5] of the same swing: +-0.159pi), and nothing more, as the axis ends at it.
TEST(DescribeRange, DataBeyondTheAxisIsCutAtIt) {
    const auto spec = spec_file("describe-cut", "[[panel]]\nplot = \"trajectory\"\ntheta0 = [\"0.9\"]\n"
                                                "methods = [\"exact\"]\ny_range = [-0.5, 0.5]\n");
    const auto d = run_cli("describe " + spec.string());
    ASSERT_EQ(d.status, 0) << d.err;
    const std::string want = "theta from " + spoken_pi(-0.5) + " to " + spoken_pi(0.5) + ".";
    EXPECT_NE(d.out.find(want), std::string::npos) << want << "\n" << d.out;
    EXPECT_EQ(d.out.find("its axis"), std::string::npos) << d.out;
    std::filesystem::remove_all(spec.parent_path());
}

// The phase plane of the amplitude 0.7: theta' spans +-2 sin(0.35) = +-0.685796 (the speed at
// the bottom, E = 2 sin^2(theta0/2); mpmath: 0.68579561491090270), said to three digits, as the data's
// own extreme: the frame is within 15 % and not named.
TEST(DescribeRange, ThePhysicsOfTheRangeIsRight) {
    const auto spec = spec_file("describe-phase", "[[panel]]\nplot = \"phase\"\ntheta0 = [\"0.7\"]\n"
                                                  "methods = [\"exact\"]\n");
    const auto d = run_cli("describe " + spec.string());
    ASSERT_EQ(d.status, 0) << d.err;
    const auto data = run_cli("data " + spec.string());
    const auto [w0, w1] = data_extent(data.out, true);
    // The bottom is sampled: the extreme is the speed there to the double's rounding.
    EXPECT_NEAR(w1, 0.68579561491090270, 4e-16);
    EXPECT_NEAR(w0, -0.68579561491090270, 4e-16);
    EXPECT_NE(d.out.find("dtheta/d(omega0t) from -0.686 to 0.686."), std::string::npos) << d.out;
    std::filesystem::remove_all(spec.parent_path());
}

}  // namespace
