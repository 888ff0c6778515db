// SPDX-License-Identifier: GPL-3.0-or-later
// The method table: names, N, dispatch to the core.
#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/period_formulas.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

using namespace pendulum;

TEST(Methods, EveryNameIsUniqueAndRoundTrips) {
    std::set<std::string> seen;
    for (const auto& row : method_table()) {
        EXPECT_TRUE(seen.insert(std::string(row.name)).second) << row.name;
        EXPECT_FALSE(row.description.empty()) << row.name;
        EXPECT_NE(row.period, nullptr) << row.name;
        // A motion method other than exact has a Fourier solution; a period formula has none.
        EXPECT_EQ(row.solution != nullptr, row.has_motion() && row.role != method_role::exact) << row.name;
        const std::string text = row.min_n < 0 ? std::string(row.name) : std::string(row.name) + ":" + std::to_string(row.max_n);
        EXPECT_EQ(parse_method(text).text(), text);
    }
}

TEST(Methods, DispatchToTheCore) {
    const double t = 2.0;
    EXPECT_EQ(method_period(parse_method("exact"), t), period_ratio(t));
    EXPECT_EQ(method_period(parse_method("lowest"), t), lowest_order(t).period_ratio());
    EXPECT_EQ(method_period(parse_method("second"), t), second_order(t).period_ratio());
    EXPECT_EQ(method_period(parse_method("order:6"), t), iterated(t, 6).period_ratio());
    EXPECT_EQ(method_period(parse_method("agm:2"), t), period_agm(t, 2));
    EXPECT_EQ(method_period(parse_method("series:7"), t), period_series(t, 7));
    EXPECT_EQ(method_period(parse_method("ganley"), t), period_ganley(t));
    EXPECT_EQ(method_solution(parse_method("first"), t).coefficients, first_order(t).coefficients);
    EXPECT_EQ(method_solution(parse_method("order:3"), t).coefficients, iterated(t, 3).coefficients);
}

TEST(Methods, BadNamesAndOrdersAreErrorsThatTeach) {
    const auto message = [](const std::string& text) {
        try {
            parse_method(text);
        } catch (const domain_error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message("lowst").find("methods: exact, harmonic"), std::string::npos) << message("lowst");
    EXPECT_NE(message("order").find("needs N"), std::string::npos);
    EXPECT_NE(message("order:201").find("0..200"), std::string::npos);
    EXPECT_NE(message("order:-1").find("0..200"), std::string::npos);
    EXPECT_NE(message("order:6x").find("whole number"), std::string::npos);
    EXPECT_NE(message("order:").find("whole number"), std::string::npos);
    EXPECT_NE(message("agm:0").find("1..10"), std::string::npos);
    EXPECT_NE(message("lowest:2").find("takes no :N"), std::string::npos);
    EXPECT_EQ(message(""), "unknown method ''; methods: " + method_names());
}

TEST(Methods, PeriodOnlyMethodsHaveNoMotion) {
    EXPECT_THROW(method_solution(parse_method("kidd-fogg"), 1.0), domain_error);
    EXPECT_THROW(method_solution(parse_method("exact"), 1.0), domain_error);
    EXPECT_FALSE(parse_method("denman").has_motion());
    EXPECT_TRUE(parse_method("order:2").has_motion());
}

}  // namespace
