// The built-in specs: every one reads and builds, and the paper's figures hold the data
// the catalog computed before they became specs.
#include "figures/builtin.hpp"
#include "figures/catalog.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace figures;

figure_spec parsed(const builtin_spec& b) { return parse_spec(b.text, std::string(b.id) + ".toml"); }

TEST(Builtin, EverySpecReadsAndBuilds) {
    ASSERT_EQ(builtin_specs().size(), 12u);
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

TEST(Builtin, ThePapersFiguresHoldTheCatalogsData) {
    for (const auto& e : catalog()) {
        const auto* b = find_builtin(e.id);
        ASSERT_NE(b, nullptr) << e.id;
        EXPECT_EQ(b->alias, e.alias);
        const auto spec = parsed(*b);
        const auto want = build(e);
        const auto got = build_figure(spec);
        EXPECT_EQ(got.rows, want.rows) << e.id;
        EXPECT_EQ(got.cols, want.cols) << e.id;
        EXPECT_EQ(got.panel_width_cm, want.panel_width_cm) << e.id;
        EXPECT_EQ(got.panel_aspect, want.panel_aspect) << e.id;
        EXPECT_EQ(got.shared_legend, want.shared_legend) << e.id;
        ASSERT_EQ(got.panels.size(), want.panels.size()) << e.id;
        std::vector<std::string> paper_files;
        for (const auto& p : spec.panels) {
            if (!p.paper_file.empty()) paper_files.push_back(p.paper_file);
        }
        EXPECT_EQ(paper_files, e.paper_files) << e.id;
        for (std::size_t i = 0; i < got.panels.size(); ++i) {
            const auto& g = got.panels[i];
            const auto& w = want.panels[i];
            const std::string where = e.id + " panel " + std::to_string(i);
            EXPECT_EQ(g.x.label, w.x.label) << where;
            EXPECT_EQ(g.y.label, w.y.label) << where;
            EXPECT_EQ(g.x.min, w.x.min) << where;
            EXPECT_EQ(g.x.max, w.x.max) << where;
            EXPECT_EQ(g.y.min, w.y.min) << where;
            EXPECT_EQ(g.y.max, w.y.max) << where;
            EXPECT_EQ(g.x.ticks, w.x.ticks) << where;
            EXPECT_EQ(g.y.ticks, w.y.ticks) << where;
            EXPECT_EQ(g.x.kind, w.x.kind) << where;
            EXPECT_EQ(g.y.kind, w.y.kind) << where;
            EXPECT_EQ(g.x.max_ticks, w.x.max_ticks) << where;
            EXPECT_EQ(g.y.max_ticks, w.y.max_ticks) << where;
            EXPECT_EQ(g.y.round_limits, w.y.round_limits) << where;
            EXPECT_EQ(g.y.margin, w.y.margin) << where;
            ASSERT_EQ(g.data.size(), w.data.size()) << where;
            for (std::size_t k = 0; k < g.data.size(); ++k) {
                const auto& gs = g.data[k];
                const auto& ws = w.data[k];
                const std::string series = where + " series " + std::to_string(k);
                if (e.id != "convergence") EXPECT_EQ(gs.label, ws.label) << series;
                EXPECT_EQ(gs.line, ws.line) << series;
                EXPECT_EQ(gs.marker, ws.marker) << series;
                EXPECT_EQ(gs.color, ws.color) << series;
                EXPECT_EQ(gs.x, ws.x) << series;
                ASSERT_EQ(gs.y.size(), ws.y.size()) << series;
                for (std::size_t j = 0; j < gs.y.size(); ++j) {
                    if (std::isnan(ws.y[j])) {
                        EXPECT_TRUE(std::isnan(gs.y[j])) << series << " point " << j;
                    } else {
                        EXPECT_EQ(gs.y[j], ws.y[j]) << series << " point " << j;
                    }
                }
            }
        }
    }
}

}  // namespace
