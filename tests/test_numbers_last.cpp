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

}  // namespace
