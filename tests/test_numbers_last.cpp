// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's reproductions (tests/data/issue_numbers_audit.md) against mpmath, the residual
// digit rule of the data writers, and approximants of states up to the largest double.
#include "process.hpp"
#include "reference.hpp"
#include "reference_rows.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
    // periods). Within 4 ulps of theta0 (of theta about 2 pi n), as the amplitude path is; a
    // backwards start adds half a period to its clock in doubles (offset + 2 K, the offset a
    // double itself): 6 there.
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
        const double allowed = command.find("--omega0 -") != std::string::npos ? 6 : 4;
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

}  // namespace
