// SPDX-License-Identifier: GPL-3.0-or-later
// The pendulum panel's teaching overlays: energy bars, velocity and acceleration arrows and
// the period timer, from the exact motion; and plot's options for them.
#include "figures/animation.hpp"
#include "figures/catalog.hpp"
#include "figures/pendulum_overlays.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "pendulum/motion.hpp"
#include "plot/frames.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using std::numbers::pi;
using namespace test_support;

/// A spec read from TOML text, as a figure entry.
figures::entry entry_of(const std::string& toml) {
    figures::entry e;
    e.id = "overlays";
    e.source = toml;
    e.spec = figures::parse_spec(toml, "overlays.toml");
    return e;
}

/// The messages of a spec's problems, one a line ("" when it reads).
std::string problems_of(const std::string& toml) {
    try {
        (void)figures::parse_spec(toml, "overlays.toml");
    } catch (const figures::spec_error& e) {
        std::string out;
        for (const auto& p : e.problems()) out += p.what + "\n";
        return out;
    }
    return "";
}

/// The series of a panel with that id, or nullptr.
const plot::series* find(const plot::panel& p, const std::string& id) {
    for (const auto& s : p.data) {
        if (s.id == id) return &s;
    }
    return nullptr;
}

/// The height of an energy bar's outline (its top less its base).
double bar_height(const plot::panel& p, const std::string& id) {
    const auto* s = find(p, id);
    if (!s) return std::nan("");
    return s->y.at(2) - s->y.at(0);
}

/// An animation as a theme draws it: its build options, frame plan and still base figure.
struct animated_build {
    plot::theme theme;
    figures::build_options options;
    figures::animation_plan plan;
    plot::figure base;
};

animated_build build_animated(const figures::entry& e, const std::string& theme_name) {
    animated_build b{figures::load_theme(theme_name), {}, {}, {}};
    b.options = figures::sized_by({}, b.theme);
    b.options.animated = true;
    b.plan = figures::plan_animation(e, b.options);
    b.base = figures::build(e, b.options);
    return b;
}

const std::string swing_170 = R"([animation]
fps = 25
periods = 1
[[panel]]
plot = "pendulum"
theta0 = ["170deg"]
methods = ["exact"]
energy_bars = true
arrows = ["velocity", "acceleration"]
timer = true
)";

}  // namespace

TEST(Overlays, KeysAreReadAndBadValuesNamed) {
    const auto e = entry_of(swing_170);
    const auto& p = e.spec.panels.at(0);
    EXPECT_TRUE(p.energy_bars);
    EXPECT_TRUE(p.velocity_arrows);
    EXPECT_TRUE(p.acceleration_arrows);
    EXPECT_TRUE(p.timer);
    const std::string head = "[[panel]]\nplot = \"pendulum\"\ntheta0 = [\"1\"]\nmethods = [\"exact\"]\n";
    EXPECT_NE(problems_of(head + "energy_bars = 1\n").find("'energy_bars' must be true or false"), std::string::npos);
    EXPECT_NE(problems_of(head + "timer = \"yes\"\n").find("'timer' must be true or false"), std::string::npos);
    EXPECT_NE(problems_of(head + "arrows = \"velocity\"\n").find("'arrows' must be a list"), std::string::npos);
    EXPECT_NE(problems_of(head + "arrows = [\"speed\"]\n").find("is not one of"), std::string::npos);
    EXPECT_NE(problems_of(head + "arrows = [\"velocity\", \"velocity\"]\n").find("names \"velocity\" twice"),
              std::string::npos);
    // Two kinds, each once: accepted; an empty list draws none.
    EXPECT_EQ(problems_of(head + "arrows = [\"acceleration\", \"velocity\"]\n"), "");
    EXPECT_NE(problems_of(head + "arrows = []\n").find("'arrows' is an empty list"), std::string::npos);
    // The overlays belong to the pendulum drawing only.
    EXPECT_NE(problems_of("[[panel]]\nplot = \"phase\"\ntheta0 = [\"1\"]\nenergy_bars = true\n").find("energy_bars"),
              std::string::npos);
}

TEST(Overlays, EnergiesMatchTheMpmathReferenceAt170Degrees) {
    // tests/data/overlays_energy_170.py: theta by mpmath's sn, theta' by its numerical derivative.
    std::ifstream in(std::string(PENDULUM_TEST_DATA) + "/overlays_energy_170.csv");
    ASSERT_TRUE(in);
    const auto motion = pendulum::motion::from_amplitude(pendulum::parse_amplitude("170deg"));
    std::string line;
    std::getline(in, line);
    int rows = 0;
    while (std::getline(in, line)) {
        std::stringstream cells(line);
        std::vector<double> v;
        for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
        ASSERT_EQ(v.size(), 5u);
        const auto e = figures::energies_at(motion, v[0]);
        EXPECT_NEAR(e.kinetic, v[2], 1e-12) << "w0 t = " << v[0];
        EXPECT_NEAR(e.potential, v[3], 1e-12) << "w0 t = " << v[0];
        EXPECT_NEAR(e.total, v[4], 1e-15);
        EXPECT_NEAR(e.kinetic + e.potential, e.total, 1e-13);
        ++rows;
    }
    EXPECT_EQ(rows, 8);
}

TEST(Overlays, BarsSumToTheTotalInEveryFrame) {
    // From the drawn figure model: the kinetic and potential bars' heights add up to the
    // total bar's, in every frame, in every theme; the total bar is drawn once (it stays).
    for (const auto& row : figures::builtin_themes()) {
        const auto e = entry_of(swing_170);
        const auto b = build_animated(e, std::string(row.name));
        const auto& base = b.base.panels.at(0);
        ASSERT_NE(find(base, "energy:total:1"), nullptr);
        EXPECT_EQ(find(base, "energy:kinetic:1"), nullptr);
        const double total = bar_height(base, "energy:total:1");
        EXPECT_NEAR(total, figures::energy_bars_height, 1e-12);
        for (int i = 0; i < b.plan.frames; ++i) {
            const auto f = figures::animation_frame(e, b.options, b.plan, b.base, b.plan.time(i));
            const auto& p = f.panels.at(0);
            const double sum = bar_height(p, "energy:kinetic:1") + bar_height(p, "energy:potential:1");
            ASSERT_NEAR(sum, total, 1e-12) << row.name << ", frame " << i;
        }
    }
}

TEST(Overlays, BarsSumToTheTotalInPixels) {
    // The slides theme's kinetic bar is orange (#d55e00), the potential bar blue (#0072b2),
    // the total bar black, right of both. At the release (at rest) the kinetic bar is a flat
    // outline: its thickness is the line's. In every drawn frame, kinetic + potential less
    // one line's thickness is the total's height within a pixel.
    const auto e = entry_of(R"([figure]
legend = "none"
[animation]
fps = 10
[[panel]]
plot = "pendulum"
theta0 = ["170deg"]
methods = ["exact"]
energy_bars = true
)");
    const auto b = build_animated(e, "slides");
    struct extent {
        int top = 1 << 30;
        int bottom = -1;
        int right = -1;
        int height() const { return bottom - top + 1; }
    };
    const auto measure = [&](int i) {
        const auto f = figures::animation_frame(e, b.options, b.plan, b.base, b.plan.time(i));
        plot::argb_image image;
        plot::render_rgb24(image, f, b.theme, 96);
        extent k, p, t;
        const auto near = [](const unsigned char* px, int r, int g, int bl) {
            return std::abs(px[2] - r) < 40 && std::abs(px[1] - g) < 40 && std::abs(px[0] - bl) < 40;
        };
        const auto grow = [](extent& x, int row, int col) {
            x.top = std::min(x.top, row);
            x.bottom = std::max(x.bottom, row);
            x.right = std::max(x.right, col);
        };
        for (int pass = 0; pass < 2; ++pass) {
            for (int row = 0; row < image.height; ++row) {
                for (int col = image.width / 2; col < image.width; ++col) {
                    const unsigned char* px = &image.data[row * image.stride + col * 4];
                    if (pass == 0 && near(px, 0xd5, 0x5e, 0x00)) grow(k, row, col);
                    if (pass == 0 && near(px, 0x00, 0x72, 0xb2)) grow(p, row, col);
                    if (pass == 1 && p.right >= 0 && col > p.right + 2 && near(px, 0, 0, 0)) grow(t, row, col);
                }
            }
        }
        return std::array<extent, 3>{k, p, t};
    };
    const auto rest = measure(0);
    const int line = rest[0].height();
    ASSERT_GT(line, 0);
    ASSERT_LT(line, 8);
    EXPECT_NEAR(rest[1].height(), rest[2].height(), 1);
    for (const int i : {b.plan.frames / 8, b.plan.frames / 4, b.plan.frames / 3, b.plan.frames / 2}) {
        const auto m = measure(i);
        EXPECT_NEAR(m[0].height() + m[1].height() - line, m[2].height(), 1.0) << "frame " << i;
    }
}

TEST(Overlays, ArrowsPointTheRightWay) {
    const auto motion = pendulum::motion::from_amplitude(pendulum::parse_amplitude("170deg"));
    const double quarter = motion.period() / 4;
    // Released at rest at +170 degrees: at the top of the swing the velocity is 0 and the
    // acceleration is along the path, towards the bottom (decreasing theta).
    const auto top = figures::vectors_at(motion, 0.0);
    EXPECT_EQ(std::hypot(top.vx, top.vy), 0.0);
    const double a = motion.theta(0.0);
    EXPECT_GT(top.ax * -std::cos(a) + top.ay * -std::sin(a), 0.0);
    // Along the path only: no centripetal part at rest.
    EXPECT_NEAR(top.ax * std::sin(a) - top.ay * std::cos(a), 0.0, 1e-15);
    EXPECT_NEAR(std::hypot(top.ax, top.ay), std::sin(a), 1e-15);
    // At the bottom a quarter period later: moving left at the largest speed, accelerated
    // straight up towards the pivot by theta'^2 = 2 E.
    const auto bottom = figures::vectors_at(motion, quarter);
    EXPECT_LT(bottom.vx, 0.0);
    EXPECT_NEAR(bottom.vx, -figures::largest_speed(motion), 1e-12);
    EXPECT_NEAR(bottom.vy, 0.0, 1e-12);
    EXPECT_NEAR(bottom.ax, 0.0, 1e-12);
    EXPECT_NEAR(bottom.ay, 2 * motion.energy(), 1e-12);
    // At the other turning point, half a period: at rest, pushed back to the right.
    const auto other = figures::vectors_at(motion, 2 * quarter);
    EXPECT_NEAR(std::hypot(other.vx, other.vy), 0.0, 1e-12);
    // Near the top on the left, the way back to the bottom is left and down, increasing theta.
    const double back = motion.theta(2 * quarter);
    EXPECT_LT(other.ax, 0.0);
    EXPECT_GT(other.ax * std::cos(back) + other.ay * std::sin(back), 0.0);

    // In the drawing: the velocity arrow has no length (and no head) at the release; the
    // acceleration arrow starts on the bob.
    const auto e = entry_of(swing_170);
    const auto b = build_animated(e, "paper");
    const auto f0 = figures::animation_frame(e, b.options, b.plan, b.base, 0.0);
    const auto* v = find(f0.panels[0], "arrow:velocity:1");
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->x[0], v->x[1]);
    EXPECT_EQ(v->y[0], v->y[1]);
    EXPECT_EQ(find(f0.panels[0], "arrowhead:velocity:1"), nullptr);
    const auto* acc = find(f0.panels[0], "arrow:acceleration:1");
    ASSERT_NE(acc, nullptr);
    EXPECT_NEAR(acc->x[0], std::sin(a), 1e-15);
    EXPECT_GT(acc->x[1], acc->x[0]);
    EXPECT_NE(v->label.markup.find("velocity <i>v</i> (longest 1.99 <i>ω</i><sub>0</sub><i>L</i>)"), std::string::npos)
        << v->label.markup;
    EXPECT_NE(acc->label.markup.find("acceleration <i>a</i> (longest"), std::string::npos);
}

TEST(Overlays, ArrowsStayInThePanelAndTheLongestIsScaledOnce) {
    // A rotation, a libration near the top and a launch from the bottom in one panel: every
    // arrow tip of every frame stays inside the drawing's 1.2 rod lengths; the longest arrow
    // of the whole motion is longest_arrow.
    const auto e = entry_of(R"([animation]
fps = 25
periods = 2
[[panel]]
plot = "pendulum"
energy = [0.5, 1.9, 3.5]
arrows = ["velocity", "acceleration"]
)");
    const auto b = build_animated(e, "paper");
    double longest_v = 0;
    double longest_a = 0;
    for (int i = 0; i < b.plan.frames; ++i) {
        const auto f = figures::animation_frame(e, b.options, b.plan, b.base, b.plan.time(i));
        for (const auto& s : f.panels[0].data) {
            if (s.id.rfind("arrow", 0) != 0) continue;
            for (std::size_t k = 0; k < s.x.size(); ++k) {
                ASSERT_LE(std::hypot(s.x[k], s.y[k]), 1.2) << s.id << ", frame " << i;
            }
            if (s.id.rfind("arrow:", 0) != 0) continue;
            const double length = std::hypot(s.x[1] - s.x[0], s.y[1] - s.y[0]);
            ASSERT_LE(length, figures::longest_arrow + 1e-12);
            (s.id.find("velocity") != std::string::npos ? longest_v : longest_a) =
                std::max(s.id.find("velocity") != std::string::npos ? longest_v : longest_a, length);
        }
    }
    // The rotation at E = 3.5 passes the bottom at its largest speed, sqrt(7): within a frame of it.
    EXPECT_GT(longest_v, 0.95 * figures::longest_arrow);
    EXPECT_GT(longest_a, 0.9 * figures::longest_arrow);
}

TEST(Overlays, TimerShowsTheMeasuredPeriodOnceCompleted) {
    for (const char* angle : {"10deg", "90deg", "170deg", "179.9deg"}) {
        const auto m = pendulum::motion::from_amplitude(pendulum::parse_amplitude(angle));
        const auto period = figures::measured_period(m);
        ASSERT_TRUE(period) << angle;
        EXPECT_NEAR(*period, m.period(), 1e-12 * m.period()) << angle;
    }
    const auto rotation = pendulum::motion::from_energy(3.0);
    ASSERT_TRUE(figures::measured_period(rotation));
    EXPECT_NEAR(*figures::measured_period(rotation), rotation.period(), 1e-12 * rotation.period());
    EXPECT_FALSE(figures::measured_period(pendulum::motion::from_energy(2.0)));
    // 90 degrees: T = 1.1803 T0.
    const auto e = entry_of(R"([animation]
[[panel]]
plot = "pendulum"
theta0 = ["90deg"]
methods = ["exact"]
timer = true
)");
    const auto m = pendulum::motion::from_amplitude(pendulum::parse_amplitude("90deg"));
    const std::vector<figures::overlay_start> starts{{m, "90"}};
    const double t = m.period();
    EXPECT_EQ(figures::timer_text(e.spec, starts, 0.5 * t), "timer 0.5902 <i>T</i><sub>0</sub>");
    EXPECT_EQ(figures::timer_text(e.spec, starts, t), "<i>T</i> = 1.1803 <i>T</i><sub>0</sub>");
    EXPECT_EQ(figures::timer_text(e.spec, starts, 1.5 * t), "<i>T</i> = 1.1803 <i>T</i><sub>0</sub>");
    // The frame nearest the completion shows it: less than half a frame before, not more.
    const double step = 0.1;
    EXPECT_EQ(figures::timer_text(e.spec, starts, t - 0.49 * step, step), "<i>T</i> = 1.1803 <i>T</i><sub>0</sub>");
    EXPECT_EQ(figures::timer_text(e.spec, starts, t - 0.51 * step, step).rfind("timer ", 0), 0u);
    // In seconds with a [pendulum] table: 1 m at 9.80665 m/s^2, T0 = 2.00641 s.
    const auto physical = entry_of("[pendulum]\nlength_m = 1\n" + e.source);
    EXPECT_EQ(figures::timer_text(physical.spec, starts, t), "<i>T</i> = 2.368 s");
    // The timer in a frame, under the clock when both are shown.
    const auto clocked = entry_of("[animation]\nclock = true\n[[panel]]\nplot = \"pendulum\"\ntheta0 = [\"90deg\"]\nmethods = [\"exact\"]\ntimer = true\n");
    const auto b = build_animated(clocked, "paper");
    const auto last = figures::animation_frame(clocked, b.options, b.plan, b.base, b.plan.time(b.plan.frames - 1));
    EXPECT_NE(last.panels[0].overlay_label.markup.find("<i>T</i>     <i>T</i> = 1.1803"), std::string::npos)
        << last.panels[0].overlay_label.markup;
}

TEST(Overlays, PlotOptionsDrawTheOverlays) {
    const auto dir = temp_dir("overlays-plot");
    const auto ok = run_cli("plot pendulum --methods exact --theta0 170deg --energy-bars --arrows velocity,acceleration --timer -f png,svg -o " +
                            dir.string());
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"pendulum.png", "pendulum.svg"}));
    EXPECT_NE(slurp(dir / "pendulum.svg").find("Bars on the right show each pendulum"), std::string::npos);
    const auto bad = run_cli("plot pendulum --methods exact --theta0 170deg --arrows speed -f png -o " + dir.string());
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("'arrows' = \"speed\" is not one of"), std::string::npos) << bad.err;
    const auto twice = run_cli("plot pendulum --methods exact --theta0 170deg --arrows velocity,velocity -f png -o " + dir.string());
    EXPECT_EQ(twice.status, 2);
    EXPECT_NE(twice.err.find("twice"), std::string::npos) << twice.err;
    // A hostile value stays one string of the spec: TOML's quotes escaped, no key injected.
    const auto hostile = run_cli("plot pendulum --methods exact --theta0 1 --arrows 'velocity\"] timer = true [x' -f png -o " +
                                 dir.string());
    EXPECT_EQ(hostile.status, 2);
    EXPECT_NE(hostile.err.find("is not one of"), std::string::npos) << hostile.err;
    const auto newline = run_cli("plot pendulum --methods exact --theta0 1 --arrows \"$(printf 'velocity\\ntimer = true')\" "
                                 "-f png -o " + dir.string());
    EXPECT_EQ(newline.status, 2);
    EXPECT_NE(newline.err.find("control character"), std::string::npos) << newline.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"pendulum.png", "pendulum.svg"}));
    const auto phase = run_cli("plot phase --theta0 1 --energy-bars -f png -o " + dir.string());
    EXPECT_EQ(phase.status, 2);
    EXPECT_NE(phase.err.find("energy_bars"), std::string::npos) << phase.err;
}

TEST(Overlays, LaunchFromTheBottomIsOneCommand) {
    // The third teaching task: a launch from the bottom with a given speed, animated with energy bars.
    const auto dir = temp_dir("overlays-launch");
    const auto r = run_cli("plot pendulum --theta0 0 --omega0 1.9 --energy-bars -f gif --name launch -o " + dir.string());
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"launch.gif"}));
}

TEST(Overlays, Omega0InRadiansPerSecondNeedsALength) {
    // w0 = sqrt(9.80665 / 1) rad/s: 2 rad/s is 2 / 3.1315571... w0.
    const double w0 = std::sqrt(9.80665);
    const auto given = run_cli("trajectory --theta0 0 --omega0 2rad/s --length 1 --at 0,0.25");
    ASSERT_EQ(given.status, 0) << given.err;
    char same[64];
    std::snprintf(same, sizeof same, "%.17g", 2 / w0);
    const auto plain = run_cli(std::string("trajectory --theta0 0 --omega0 ") + same + " --at 0,0.25");
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_EQ(given.out, plain.out);
    // With a space, and with --g.
    EXPECT_EQ(run_cli("trajectory --theta0 0 --omega0 '2 rad/s' --length 1 --at 0").status, 0);
    EXPECT_EQ(run_cli("trajectory --theta0 0 --omega0 2rad/s --length 1 --g 1.62 --at 0").status, 0);
    const auto alone = run_cli("trajectory --theta0 0 --omega0 2rad/s --at 0");
    EXPECT_EQ(alone.status, 2);
    EXPECT_NE(alone.err.find("--omega0 '2rad/s': a velocity in rad/s needs the pendulum's --length"), std::string::npos)
        << alone.err;
    // The length's limits: 1e6 m accepted, above refused.
    EXPECT_EQ(run_cli("trajectory --theta0 0 --omega0 2rad/s --length 1e6 --at 0").status, 0);
    const auto far = run_cli("trajectory --theta0 0 --omega0 2rad/s --length 1.000001e6 --at 0");
    EXPECT_EQ(far.status, 2);
    EXPECT_NE(far.err.find("--length 1000001: a length in metres above 0 and at most 1e6"), std::string::npos) << far.err;
    // A plain --length without seconds or rad/s is still refused outside t/s.
    const auto stray = run_cli("trajectory --theta0 1 --length 1 --at 0");
    EXPECT_EQ(stray.status, 2);
    EXPECT_NE(stray.err.find("--length goes with --time t/s, --at in seconds"), std::string::npos) << stray.err;

    // eval: the same conversion; its omega0 column is in units of w0.
    const auto ev = run_cli("eval --theta0 0 --omega0 2rad/s --length 1");
    ASSERT_EQ(ev.status, 0) << ev.err;
    EXPECT_NE(ev.out.find("\n0,0.6386599135621175,"), std::string::npos) << ev.out;
    EXPECT_EQ(run_cli("eval --theta0 0 --omega0 2rad/s").status, 2);

    // plot: the same conversion, into the panel's title as units of w0.
    const auto dir = temp_dir("overlays-omega0");
    const auto p = run_cli("plot pendulum --theta0 0 --omega0 2rad/s --length 1 -f svg -o " + dir.string());
    EXPECT_EQ(p.status, 0) << p.err;
    const auto svg = slurp(dir / "pendulum.svg");
    EXPECT_NE(svg.find("(0) = 0.63865"), std::string::npos);
    const auto q = run_cli("plot pendulum --theta0 0 --omega0 2rad/s -f svg -o " + dir.string());
    EXPECT_EQ(q.status, 2);
    EXPECT_NE(q.err.find("needs the pendulum's --length"), std::string::npos) << q.err;
    const auto bad = run_cli("plot pendulum --theta0 0 --omega0 xrad/s --length 1 -f svg -o " + dir.string());
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("--omega0 'xrad/s'"), std::string::npos) << bad.err;
}

TEST(Overlays, AtTakesSeconds) {
    const auto seconds = run_cli("trajectory --theta0 1 --time t/s --length 0.5 --at 10");
    const auto given = run_cli("trajectory --theta0 1 --length 0.5 --at 10s");
    ASSERT_EQ(seconds.status, 0) << seconds.err;
    ASSERT_EQ(given.status, 0) << given.err;
    // The same angle: theta in the last column of the one row.
    const auto theta = [](const std::string& out) { return std::stod(out.substr(out.rfind(',') + 1)); };
    EXPECT_NEAR(theta(seconds.out), theta(given.out), 1e-12);
    const auto alone = run_cli("trajectory --theta0 1 --at 10s");
    EXPECT_EQ(alone.status, 2);
    EXPECT_NE(alone.err.find("--at in seconds (10s) needs the pendulum's --length"), std::string::npos) << alone.err;
    const auto bad = run_cli("trajectory --theta0 1 --length 1 --at 1xs");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("--at '1xs'"), std::string::npos) << bad.err;
}

TEST(Overlays, ListsFromFilesEverywhereAndInEveryHelp) {
    for (const char* command : {"plot", "trajectory", "eval", "render", "data"}) {
        const auto help = run_cli(std::string(command) + " --help");
        EXPECT_NE(help.out.find("--theta0 @FILE"), std::string::npos) << command;
        EXPECT_NE(help.out.find("--theta0 - from standard input"), std::string::npos) << command;
    }
    for (const char* command : {"plot", "trajectory", "eval"}) {
        const auto help = run_cli(std::string(command) + " --help");
        EXPECT_NE(help.out.find("w0 = sqrt(g/L)"), std::string::npos) << command;
    }
    const auto dir = temp_dir("overlays-file");
    std::ofstream(dir / "angles.txt") << "# two\n10deg\n170deg\n";
    const auto r = run_cli("plot pendulum --methods exact --theta0 @angles.txt -f svg -o " + dir.string(), dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "pendulum.svg").find("170"), std::string::npos);
    const auto missing = run_cli("plot pendulum --methods exact --theta0 @none.txt -f svg -o " + dir.string(), dir);
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.err.find("none.txt"), std::string::npos) << missing.err;
}

TEST(Overlays, RenderAtTakesSecondsWithAPendulumTable) {
    // swing has [pendulum] length_m = 1: --at 1s is the frame at t/T = 1 s / T.
    const auto dir = temp_dir("overlays-render-at");
    const auto& swing = figures::find("swing");
    const auto plan = figures::plan_animation(swing, {});
    const double t_over_T = 1.0 / (plan.seconds_per_unit * plan.reference_period);
    char at[64];
    std::snprintf(at, sizeof at, "%.17g", t_over_T);
    const auto s = run_cli("render swing --at 1s -f svg -o " + dir.string());
    ASSERT_EQ(s.status, 0) << s.err;
    const std::string by_seconds = slurp(dir / "swing.svg");
    const auto p = run_cli(std::string("render swing --force --at ") + at + " -f svg -o " + dir.string());
    ASSERT_EQ(p.status, 0) << p.err;
    EXPECT_EQ(slurp(dir / "swing.svg"), by_seconds);
    // separatrix has no [pendulum]: seconds are refused, naming it.
    const auto none = run_cli("render separatrix --at 1s -f svg -o " + dir.string());
    EXPECT_EQ(none.status, 2);
    EXPECT_NE(none.err.find("--at 1s: a time in seconds needs the animation's [pendulum] table"), std::string::npos)
        << none.err;
    const auto two = run_cli("render swing over-the-top --at 1s -f svg -o " + dir.string());
    EXPECT_EQ(two.status, 2);
    EXPECT_NE(two.err.find("goes with one animation"), std::string::npos) << two.err;
    // The bound of t/T holds for seconds too: 1e6 T accepted is the limit, more refused.
    const auto far = run_cli("render swing --at 1e12s -f svg -o " + dir.string());
    EXPECT_EQ(far.status, 2);
    EXPECT_NE(far.err.find("at most 1e6"), std::string::npos) << far.err;
}
