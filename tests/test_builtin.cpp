// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in specs: every one reads and builds, and the paper's figures hold the data
// the catalog computed before they became specs.
#include "figures/builtin.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace figures;

figure_spec parsed(const builtin_spec& b) { return parse_spec(b.text, std::string(b.id) + ".toml"); }

TEST(Builtin, EverySpecReadsAndBuilds) {
    ASSERT_EQ(builtin_specs().size(), 14u);
    for (const auto& b : builtin_specs()) {
        const auto spec = parsed(b);
        EXPECT_EQ(spec.id, b.id);
        EXPECT_FALSE(spec.title.empty()) << b.id;
        const auto f = build_figure(spec);
        EXPECT_EQ(f.panels.size(), spec.panels.size()) << b.id;
        for (const auto& p : f.panels) {
            EXPECT_FALSE(p.data.empty()) << b.id;
            for (const auto& s : p.data) EXPECT_EQ(s.x.size(), s.y.size()) << b.id;
        }
    }
    EXPECT_EQ(find_builtin("fig6"), find_builtin("trajectory-second"));
    EXPECT_EQ(find_builtin("nope"), nullptr);
}

TEST(Builtin, PaperFilesAndSizes) {
    const auto names = [](const char* id) {
        std::vector<std::string> v;
        for (const auto& p : parsed(*find_builtin(id)).panels) v.push_back(p.paper_file);
        return v;
    };
    EXPECT_EQ(names("fig1"), (std::vector<std::string>{"Fig.C1.Lowest"}));
    EXPECT_EQ(names("fig2").back(), "Fig.Comparison.LowestD");
    EXPECT_EQ(names("fig6").front(), "Fig.Lamb.4a");
    EXPECT_EQ(names("fig7"), (std::vector<std::string>{"Fig.Comparison.PeriodA", "Fig.Comparison.PeriodB"}));
    EXPECT_EQ(parsed(*find_builtin("fig5")).panel_width_cm, 4.3);
    EXPECT_EQ(parsed(*find_builtin("fig6")).panel_width_cm, 4.2);
    EXPECT_EQ(names("convergence"), (std::vector<std::string>{""}));
}

}  // namespace
