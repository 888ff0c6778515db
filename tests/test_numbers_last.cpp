// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's reproductions (tests/data/issue_numbers_audit.md) against mpmath, the residual
// digit rule of the data writers, and approximants of states up to the largest double.
#include "figures/figure_data.hpp"
#include "pendulum/written_mp.hpp"
#include "process.hpp"
#include "reference.hpp"
#include "reference_rows.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

using test_support::rows::number;
using test_support::rows::split_at;
using test_support::rows::ulp;

/// The fields of a command's one-row CSV answer by their column name.
std::map<std::string, std::string> fields_of(const std::string& out) {
    const auto lines = split_at(out, '\n');
    std::map<std::string, std::string> by_name;
    if (lines.size() < 2) return by_name;
    const auto names = split_at(lines[0], ',');
    const auto values = split_at(lines[1], ',');
    for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) by_name[names[i]] = values[i];
    return by_name;
}

/// The distance of `got` from the reference `want` in ulps of `want` (an exact zero wants an
/// exact zero: any other value is infinitely far).
double ulps_off(const std::string& got, const std::string& want) {
    const double g = number(got);
    const double w = number(want);
    if (w == 0) return g == 0 ? 0 : INFINITY;
    return std::fabs(g - w) / ulp(w);
}

TEST(NumbersAudit, EveryReproductionWithinFourUlpsOrRefused) {
    // numbers_audit.csv (make_numbers_audit.py): every reproduction of the audit whose truth
    // is a printed field, the inputs as written, by mpmath at 2400 bits.
    const auto rows = test_support::read_reference_text("numbers_audit.csv");
    ASSERT_GE(rows.size(), 50u);
    std::map<std::string, test_support::run_result> runs;
    double worst = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& args = rows[i].at(0);
        const std::string& field = rows[i].at(1);
        const std::string& want = rows[i].at(2);
        if (!runs.count(args)) runs[args] = test_support::run_cli(args);
        const auto& r = runs[args];
        if (want.rfind("exit2:", 0) == 0) {
            EXPECT_EQ(r.status, 2) << args;
            EXPECT_NE(r.err.find(want.substr(6)), std::string::npos) << args << ": " << r.err;
            continue;
        }
        ASSERT_EQ(r.status, 0) << args << ": " << r.err;
        const auto fields = fields_of(r.out);
        ASSERT_TRUE(fields.count(field)) << args << ": no field " << field << " in " << r.out;
        const std::string& got = fields.at(field);
        if (field == "regime") {
            EXPECT_EQ(got, want) << args;
            continue;
        }
        const double u = ulps_off(got, want);
        EXPECT_LE(u, 4) << args << " " << field << ": got " << got << ", want " << want;
        worst = std::max(worst, u);
    }
    std::cout << "worst " << worst << " ulps over " << runs.size() << " commands\n";
}

/// The rows of a command's CSV answer after its header, each split at commas.
std::vector<std::vector<std::string>> answer_rows(const std::string& out) {
    std::vector<std::vector<std::string>> rows;
    const auto lines = split_at(out, '\n');
    for (std::size_t i = 1; i < lines.size(); ++i) {
        if (!lines[i].empty()) rows.push_back(split_at(lines[i], ','));
    }
    return rows;
}

TEST(StateApproximants, EveryMethodToTheLargestDouble) {
    // state_approximant_long.csv (make_state_approximant_long.py): approximants of librations
    // from a state or an energy, every method, at times up to the largest double either way,
    // the phase formed from the exact w/w0 at the exact amplitude of the numbers as written
    // (the state's amplitude rounded to a double moved theta by its whole amplitude after 1e15
    // periods). Within 4 ulps of theta0 (of theta about 2 pi n), as the amplitude path is,
    // forwards and backwards: the start's clock is F(psi | k) from the numbers as written, in
    // MPFR (written_clock; the double offset took a backwards start to 5 ulps).
    const auto rows = test_support::read_reference_text("state_approximant_long.csv");
    ASSERT_GE(rows.size(), 350u);
    // One command per start, method and unit, with every time of the file in its --at list.
    std::map<std::string, std::vector<std::size_t>> by_command;
    std::vector<std::string> order;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& args = rows[i].at(0);
        const std::string command = args.substr(0, args.find(" --at "));
        if (!by_command.count(command)) order.push_back(command);
        by_command[command].push_back(i);
    }
    double worst = 0;
    for (const auto& command : order) {
        std::string times;
        for (std::size_t i : by_command[command]) {
            const std::string& args = rows[i].at(0);
            times += (times.empty() ? "" : ",") + args.substr(args.find(" --at ") + 6);
        }
        const auto r = test_support::run_cli(command + " --at " + times);
        ASSERT_EQ(r.status, 0) << command << ": " << r.err;
        const auto got = answer_rows(r.out);
        ASSERT_EQ(got.size(), by_command[command].size()) << command;
        const double allowed = 4;
        for (std::size_t j = 0; j < got.size(); ++j) {
            const auto& row = rows[by_command[command][j]];
            const double want = number(row.at(2));
            const double size = std::max(number(row.at(1)), std::fabs(want));
            const double u = std::fabs(number(got[j].at(1)) - want) / ulp(size);
            EXPECT_LE(u, allowed) << row.at(0) << ": got " << got[j].at(1) << ", want " << row.at(2);
            worst = std::max(worst, u);
        }
    }
    std::cout << "worst " << worst << " ulps of theta0 over " << rows.size() - 1 << " points, " << order.size()
              << " commands\n";
}

TEST(DifferenceDigits, TheRuleAtEveryBoundary) {
    // difference_digits.csv (make_difference_digits.py): a - b deserves
    // floor(log10(|a - b| / (2^-52 max(|a|, |b|)))) digits, 1 to 17, 17 where nothing cancels;
    // at 10^n units of the terms' rounding n digits, half a unit less n - 1.
    const auto rows = test_support::read_reference_text("difference_digits.csv");
    ASSERT_GE(rows.size(), 38u);
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const double a = number(rows[i].at(0));
        const double b = number(rows[i].at(1));
        EXPECT_EQ(figures::difference_digits(a - b, std::max(std::fabs(a), std::fabs(b))), std::stoi(rows[i].at(2)))
            << "a = " << rows[i].at(0) << ", b = " << rows[i].at(1);
    }
}

/// The y cells of series `id` in a long CSV answer of `data`.
std::vector<std::string> long_y(const std::string& out, const std::string& id) {
    std::vector<std::string> ys;
    for (const auto& line : split_at(out, '\n')) {
        const auto f = split_at(line, ',');
        if (f.size() >= 5 && f[4] == id) ys.push_back(f[3]);
    }
    return ys;
}

/// The cells of column `name` in a wide CSV answer, nan padding dropped.
std::vector<std::string> wide_column_cells(const std::string& out, const std::string& name) {
    const auto lines = split_at(out, '\n');
    const auto header = split_at(lines.at(0), ',');
    const auto at = std::find(header.begin(), header.end(), name);
    std::vector<std::string> cells;
    if (at == header.end()) return cells;
    const auto column = static_cast<std::size_t>(at - header.begin());
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto f = split_at(lines[i], ',');
        if (column < f.size() && f[column] != "nan") cells.push_back(f[column]);
    }
    return cells;
}

/// The numbers of the "y" array of the JSON series `id` of `data -f json`.
std::vector<std::string> json_y(const std::string& out, const std::string& id) {
    const auto series = out.find("{\"id\":\"" + id + "\"");
    const auto from = out.find("\"y\":[", series);
    if (series == std::string::npos || from == std::string::npos) return {};
    const auto to = out.find(']', from);
    return split_at(out.substr(from + 5, to - from - 5), ',');
}

TEST(DifferenceDigits, ResidualColumnsPrintTheDigitsTheyDeserveInEveryFormat) {
    // residual_digits.csv (make_difference_digits.py): measured T/T0 at 1 rad on a residual
    // panel; each residual printed with the digits the rule gives it (a measurement 13 units
    // of rounding from T/T0 one digit, a far one 15), and those digits are the true residual's
    // (mpmath) in long CSV, wide CSV and JSON alike.
    const auto rows = test_support::read_reference_text("residual_digits.csv");
    std::string ys;
    std::string xs;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        ys += (ys.empty() ? "" : ", ") + rows[i].at(0);
        xs += (xs.empty() ? "" : ", ") + std::string("1.0");
    }
    const auto dir = test_support::temp_dir("numbers-residual-digits");
    std::ofstream(dir / "r.toml") << "[[panel]]\nplot = \"period\"\ny = \"residual\"\nmethods = [\"exact\", \"lowest\"]\n"
                                  << "[[panel.data]]\nx = [" << xs << "]\nx_unit = \"rad\"\ny = [" << ys
                                  << "]\ny_unit = \"T/T0\"\n";
    const auto spec = "'" + (dir / "r.toml").string() + "'";
    const auto long_run = test_support::run_cli("data " + spec);
    ASSERT_EQ(long_run.status, 0) << long_run.err;
    const auto wide_run = test_support::run_cli("data --layout wide " + spec);
    ASSERT_EQ(wide_run.status, 0) << wide_run.err;
    const auto json_run = test_support::run_cli("data -f json " + spec);
    ASSERT_EQ(json_run.status, 0) << json_run.err;
    const auto in_long = long_y(long_run.out, "data:1");
    const auto in_wide = wide_column_cells(wide_run.out, "a_data_1_y");
    const auto in_json = json_y(json_run.out, "data:1");
    ASSERT_EQ(in_long.size(), rows.size() - 1) << long_run.out;
    EXPECT_EQ(in_wide, in_long) << wide_run.out;
    EXPECT_EQ(in_json, in_long) << json_run.out;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::string& got = in_long[i - 1];
        EXPECT_EQ(number(got), number(rows[i].at(2))) << "y = " << rows[i].at(0) << ": got " << got << ", want "
                                                      << rows[i].at(2) << " (" << rows[i].at(1) << " digits)";
        // No more digits than the rule's: the shortest text of the n-digit rounding.
        const std::string mantissa = got.substr(0, got.find('e'));
        std::size_t significant = 0;
        bool leading = true;
        for (char c : mantissa) {
            if (c < '0' || c > '9') continue;
            if (leading && c == '0') continue;
            leading = false;
            ++significant;
        }
        EXPECT_LE(significant, static_cast<std::size_t>(std::stoi(rows[i].at(1)))) << got;
    }
    std::filesystem::remove_all(dir);
}

TEST(SeparatrixCeiling, AGapOnlyTheCeilingSeesIsRefusedNotTheSeparatrix) {
    // A gap is decided where 32768 and 65536 bits agree on it (down to about 2^-32700 of its
    // terms, about 1e-9843): 1e-9800 is; 1e-9900 (seen at 65536 bits only) and 1e-19800 (below
    // 2^-65528, seen by neither) are exit 2 naming the ceiling, never silently the separatrix.
    for (const std::string args : {"--theta0 2pi/3+1e-19800 --omega0 1", "--theta0 2pi/3 --omega0 1+1e-19800",
                                   "--theta0 0 --omega0 2-1e-19800", "--energy 2+1e-19800",
                                   "--theta0 2pi/3+1e-9900 --omega0 1"}) {
        const auto r = test_support::run_cli("eval " + args);
        EXPECT_EQ(r.status, 2) << args << ": " << r.out;
        EXPECT_NE(r.err.find("within 65536 bits"), std::string::npos) << args << ": " << r.err;
        EXPECT_EQ(r.out.find("separatrix"), std::string::npos) << args << ": " << r.out;
    }
    // 1e-9800 is decided (a rotation) and then refused for what doubles cannot hold (2 k' below
    // the smallest normal double), not for the ceiling.
    const auto decided = test_support::run_cli("eval --theta0 2pi/3+1e-9800 --omega0 1");
    EXPECT_EQ(decided.status, 2);
    EXPECT_NE(decided.err.find("2 - E = -8.66025403784438"), std::string::npos) << decided.err;
    EXPECT_NE(decided.err.find("below the smallest normal double"), std::string::npos) << decided.err;
    EXPECT_EQ(decided.err.find("within 65536 bits"), std::string::npos) << decided.err;
}

TEST(SeparatrixCeiling, InputsExactlyOnTheSeparatrixStayTheSeparatrix) {
    // E = 2 proved from the numbers as written (theta = b pi with a rational cosine, omega
    // rational, omega^2 = 2 (1 + cos theta); or the energy 2), at once, without the ceiling.
    for (const std::string args :
         {"--theta0 2pi/3 --omega0 1", "--theta0 120deg --omega0 1", "--theta0 -2pi/3 --omega0 -1",
          "--theta0 4pi/3 --omega0 1", "--theta0 0 --omega0 2", "--theta0 2pi --omega0 -2", "--theta0 pi/2 --omega0 '1.4142135623730951*1'",
          "--theta0 '(2/3)pi' --omega0 '0.5*2*3/3'", "--energy 2", "--energy 4/2", "--energy 2.000"}) {
        const auto r = test_support::run_cli("eval " + args);
        const bool irrational = args.find("1.4142135623730951") != std::string::npos;
        ASSERT_EQ(r.status, 0) << args << ": " << r.err;
        // pi/2 with the double nearest sqrt(2) is just off it (E = 2 + 1.9e-16): a rotation.
        EXPECT_NE(r.out.find(irrational ? "rotation" : "separatrix"), std::string::npos) << args << ": " << r.out;
    }
    // pi/3 with omega 1 is E = 1: the exact rule does not call every multiple of pi the separatrix.
    const auto off = test_support::run_cli("eval --theta0 pi/3 --omega0 1");
    EXPECT_NE(off.out.find("libration"), std::string::npos) << off.out << off.err;
    // At rest at the top is the unstable equilibrium, refused as amplitude mode refuses pi.
    const auto top = test_support::run_cli("eval --theta0 pi --omega0 0");
    EXPECT_EQ(top.status, 2);
    EXPECT_NE(top.err.find("pi"), std::string::npos) << top.err;
}

}  // namespace

// The exact value of a number as written stays within max_exact_bits on the way: three
// factors of 1e-99999 (996,573 bits of denominator) are exact, a fourth is only MPFR's, so a
// 1000-byte product of 110 of them is decided (refused at the ceiling) in a fraction of a
// second instead of 12 s of GMP multiplications; a sum that cancels exactly is still the
// separatrix.
TEST(NumbersLast, ExactValuesStayWithinTheirBits) {
    const std::string three = "1+1e-99999*1e-99999*1e-99999";
    EXPECT_TRUE(pendulum::exact_written(pendulum::written_number::angle(three)).has_value());
    EXPECT_FALSE(pendulum::exact_written(pendulum::written_number::angle(three + "*1e-99999")).has_value());
    std::string product = "1e-99999";
    for (int i = 1; i < 110; ++i) product += "*1e-99999";
    const auto r = test_support::run_cli("eval --theta0 '2pi/3+" + product + "' --omega0 1");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("cannot be decided from the numbers as written within 65536 bits"), std::string::npos) << r.err;
    const auto same = test_support::run_cli("eval --theta0 '2pi/3+1e-99999-1e-99999' --omega0 1");
    EXPECT_EQ(same.status, 0) << same.err;
    EXPECT_NE(same.out.find(",separatrix,"), std::string::npos) << same.out;
}
