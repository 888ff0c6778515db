// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in specs: every one reads and builds, and the paper's figures hold the data
// the catalog computed before they became specs.
#include "figures/builtin.hpp"
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "plot/figure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace figures;

figure_spec parsed(const builtin_spec& b) { return parse_spec(b.text, std::string(b.id) + ".toml"); }

TEST(Builtin, EverySpecReadsAndBuilds) {
    ASSERT_EQ(builtin_specs().size(), 16u);
    for (const auto& b : builtin_specs()) {
        const auto spec = parsed(b);
        EXPECT_EQ(spec.id, b.id);
        EXPECT_FALSE(spec.description.empty()) << b.id;
        EXPECT_TRUE(spec.title.empty()) << b.id << ": a built-in figure draws no title, as in the paper";
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

/// The built figure of a built-in spec.
plot::figure built(const char* id) { return build_figure(parsed(*find_builtin(id))); }

/// Every point of the series `label` of panel `panel` lies on `y(x)`, to 1e-13 of the
/// value or of `scale` (an angle's amplitude), whichever is larger; the series has at least
/// `min_points` points.
void expect_on(const plot::figure& f, std::size_t panel, const std::string& label,
               const std::function<double(double)>& y, double scale = 1e-300, std::size_t min_points = 20) {
    ASSERT_LT(panel, f.panels.size()) << label;
    const plot::series* found = nullptr;
    for (const auto& s : f.panels[panel].data) {
        if (s.label.markup == label) found = &s;
    }
    ASSERT_NE(found, nullptr) << "panel " << panel << " has no series '" << label << "'";
    ASSERT_EQ(found->x.size(), found->y.size()) << label;
    EXPECT_GE(found->x.size(), min_points) << label;
    for (std::size_t i = 0; i < found->x.size(); ++i) {
        const double x = found->x[i];
        const double want = y(x);
        EXPECT_NEAR(found->y[i], want, 1e-13 * std::max(std::abs(want), scale))
            << "panel " << panel << ", " << label << " at x = " << x;
    }
}

constexpr double pi = std::numbers::pi;

TEST(Builtin, PaperFiguresHoldTheCoreLibrarysValues) {
    using namespace pendulum;
    // Fig. 1: c1 against the amplitude.
    const auto fig1 = built("fig1");
    expect_on(fig1, 0, "exact", [](double t) { return exact_solution(t).coefficient(0); });
    expect_on(fig1, 0, "lowest order", [](double t) { return lowest_order(t).coefficients.at(0); });
    expect_on(fig1, 0, "polynomial", [](double t) { return polynomial(t).coefficients.at(0); });
    // Fig. 3: c1' and c3' of the first order.
    const auto fig3 = built("fig3");
    expect_on(fig3, 0, "first order", [](double t) { return first_order(t).coefficients.at(0); });
    expect_on(fig3, 1, "exact", [](double t) { return exact_solution(t).coefficient(1); });
    expect_on(fig3, 1, "first order", [](double t) { return first_order(t).coefficients.at(1); });
    // Fig. 5: c5'' of the second order.
    expect_on(built("fig5"), 2, "second order", [](double t) { return second_order(t).coefficients.at(2); });
    // Fig. 2: theta against t/T (T the exact period) at pi/3, pi/2, 3pi/4 and 9pi/10.
    const auto fig2 = built("fig2");
    const double amplitudes[] = {pi / 3, pi / 2, 3 * pi / 4, 9 * pi / 10};
    for (std::size_t i = 0; i < 4; ++i) {
        const double t0 = amplitudes[i];
        const double w0_T = 2 * pi * period_ratio(t0);
        expect_on(fig2, i, "exact", [&](double s) { return exact_solution(t0).theta_at_fraction(s); }, t0);
        expect_on(fig2, i, "lowest order", [&](double s) { return lowest_order(t0).theta(w0_T * s); }, t0);
        expect_on(fig2, i, "harmonic", [&](double s) { return harmonic(t0).theta(w0_T * s); }, t0);
    }
    // Fig. 7: T/T0 against the amplitude, and the relative error of each order's period in %.
    const auto fig7 = built("fig7");
    expect_on(fig7, 0, "exact", [](double t) { return period_ratio(t); });
    expect_on(fig7, 0, "lowest order", [](double t) { return lowest_order(t).period_ratio(); });
    expect_on(fig7, 0, "second order", [](double t) { return second_order(t).period_ratio(); });
    // The error without cancellation (the core library's, checked against mpmath in
    // test_precision): the doubles' difference T_1/T - 1 is off by 6e-8 of itself near 0.
    expect_on(fig7, 1, "first order", [](double t) {
        const auto e = method_period_error(parse_method("first"), t);
        EXPECT_EQ(e.what, period_error::kind::value) << t;
        return 100 * e.value;
    });
}

}  // namespace

TEST(Describe, EveryBuiltinFigureInWords) {
    for (const auto& e : figures::catalog()) {
        const auto built = figures::build(e);
        const auto d = figures::describe(e, built);
        EXPECT_EQ(d.alt.rfind(e.description(), 0), 0u) << e.id << ": " << d.alt;
        std::size_t plots = 0;
        for (const auto& p : built.panels) plots += p.frameless ? 0 : 1;
        std::size_t against = 0;
        for (std::size_t pos = 0; (pos = d.text.find(" against ", pos)) != std::string::npos; ++pos) ++against;
        EXPECT_EQ(against, plots) << e.id << ": one 'Y against X' per plotted panel\n" << d.text;
        if (built.panels.size() > 1) {
            EXPECT_NE(d.text.find("Panel (b)"), std::string::npos) << e.id << "\n" << d.text;
        }
        // Spoken, not drawn: no markup, no Greek letters.
        for (const char* drawn : {"<", "\u03d1", "\u03c0"}) EXPECT_EQ(d.text.find(drawn), std::string::npos) << e.id << "\n" << d.text;
    }
    // The facts a reader needs: axes and ranges, where the approximations leave the exact
    // curve, where the paper's claims are crossed.
    const struct {
        const char* id;
        const char* fact;
    } facts[] = {
        {"c1-lowest", "c1 against theta0, theta0 from 0 to pi"},
        {"c1-lowest", "Leaving the exact curve by more than 1 % of the c1 axis: lowest order at theta0 = 0.5"},
        {"period", "T/T0 against theta0"},
        {"period", "relative error (%) from -20 to 2"},
        {"period-error", "first crossed by lowest order at theta0 = 0.4"},
        {"period-error", "on a logarithmic scale"},
        {"trajectory-second", "Second order stays on the exact curve"},
        {"swing", "An animation over 3 periods"},
        {"over-the-top", "E = 2.6 mgL goes over the top, round and round (rotation)"},
        {"phase-portrait", "against theta, theta from -pi to pi"},
        // Each orbit's shape and extent, not only its name; the separatrix's too.
        {"phase-portrait", "Closed curves around the origin"},
        {"phase-portrait", "theta0 = pi/2: theta +-pi/2, dtheta/d(omega0t) +-1.41"},
        {"phase-portrait", "Separatrix meets dtheta/d(omega0t) = 0 at theta = -pi and pi and reaches 2 at theta = 0"},
        {"separatrix", "Separatrix meets dtheta/d(omega0t) = 0"},
        {"separatrix", "An animation over 1 period of"},
        // The drawing: what it shows, how each pendulum looks, where they start.
        {"swing", "is a drawing, seen from the side, of 3 pendulums"},
        // The rods as the default theme draws them: the paper theme's dotted harmonic.
        {"swing", "exact (solid rod, filled bob), harmonic (dotted rod, open bob)"},
        {"swing", "released from rest at theta0 = 170 degrees"},
        {"swing", "fading trail of its last 0.3 periods"},
        // A curve that leaves the axes is described as far as they show it.
        {"period", "T/T0 from 1 to 3"},
        // Lines as the default theme draws them (its named styles), ranges said as read.
        {"trajectory-lowest", "lowest order (solid line), and harmonic (dotted line)"},
        {"c1-lowest", "polynomial (dotted line)"},
        {"regimes", "theta from 0 to pi."},
        // Several starts in one drawing, each with what it does.
        {"over-the-top", "of 3 pendulums of one length"},
        {"over-the-top", "E = 2 mgL creeps up towards the top and never quite reaches it (separatrix)"},
    };
    for (const auto& f : facts) {
        const auto& e = figures::find(f.id);
        const auto d = figures::describe(e, figures::build(e));
        EXPECT_NE((d.alt + "\n" + d.text).find(f.fact), std::string::npos) << f.id << ": no '" << f.fact << "' in\n" << d.text;
    }
}
