// SPDX-License-Identifier: GPL-3.0-or-later
// Teaching, the rest: one glyph per method in every panel of an animation, energies with
// their unit, the trail's legend entry, room for the clock above the drawing, plot --set of
// figure keys, trajectory ranges in seconds and velocities in rad/s from a file.
#include "figures/animation.hpp"
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/spec.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "plot/frames.hpp"
#include "plot/render.hpp"
#include "animation_builtins.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace test_support;

/// A spec read from TOML text, as a figure entry.
figures::entry entry_of(const std::string& toml, const std::string& id = "teaching") {
    figures::entry e;
    e.id = id;
    e.source = toml;
    e.spec = figures::parse_spec(toml, id + ".toml");
    return e;
}

/// What a legend entry looks like: line, marker and colour.
struct glyph {
    plot::line_style line;
    plot::marker_style marker;
    int color;
    std::optional<std::array<double, 3>> rgb;
    bool operator==(const glyph&) const = default;
};

glyph glyph_of(const plot::series& s) {
    std::optional<std::array<double, 3>> rgb;
    if (s.rgb_color) rgb = std::array<double, 3>{s.rgb_color->r, s.rgb_color->g, s.rgb_color->b};
    return {s.line, s.marker, s.color, rgb};
}

/// A legend label up to its first ", " ("E = 1.6 mgL, libration" names the start "E = 1.6 mgL").
std::string entry_name(const std::string& label) { return label.substr(0, label.find(", ")); }

/// A figure's pixels as render_rgb24 draws them, one 0xRRGGBB each.
struct pixels {
    int w = 0;
    int h = 0;
    std::vector<std::uint32_t> v;
};

pixels render(const plot::figure& f, const plot::theme& th) {
    plot::argb_image image;
    plot::render_rgb24(image, f, th, th.dpi);
    pixels out{image.width, image.height, {}};
    out.v.resize(static_cast<std::size_t>(out.w) * out.h);
    for (int y = 0; y < out.h; ++y) {
        for (int x = 0; x < out.w; ++x) {
            const unsigned char* px = image.data.data() + static_cast<std::size_t>(y) * image.stride + 4 * x;
            out.v[static_cast<std::size_t>(y) * out.w + x] = px[0] | (px[1] << 8) | (px[2] << 16);
        }
    }
    return out;
}

}  // namespace

// 1. One method, one glyph: in every built-in animation and theme, a legend label names the
// same glyph in every panel, and a one-start drawing's rod takes its method's themed line.
TEST(TeachingRest, OneGlyphPerMethodInEveryPanel) {
    const auto animations = builtin_animations();
    ASSERT_GE(animations.size(), 2U);
    for (const auto& row : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(row.name);
        const auto options = animated_options(th);
        for (const auto* e : animations) {
            const auto plan = figures::plan_animation(*e, options);
            const auto base = figures::build(*e, options);
            const auto themed = plot::with_theme_styles(base, th);
            std::map<std::string, glyph> seen;
            int compared = 0;
            for (const auto& panel : themed.panels) {
                for (const auto& s : panel.data) {
                    if (s.label.empty() || s.id.starts_with("key:trail") || s.id.starts_with("energy") ||
                        s.id.starts_with("arrow")) {
                        continue;
                    }
                    const auto [it, fresh] = seen.emplace(entry_name(s.label.markup), glyph_of(s));
                    if (fresh) continue;
                    ++compared;
                    EXPECT_TRUE(it->second == glyph_of(s))
                        << e->id << " in " << row.name << ": '" << s.label.markup << "' is drawn two ways";
                }
            }
            // swing and over-the-top show their methods or starts in two panels.
            if (e->id == "swing" || e->id == "over-the-top") {
                EXPECT_GT(compared, 0) << e->id << ": no label in two panels";
            }
            // The rods in a frame: the key's themed line (solid for none), in its colour.
            const auto frame = plot::with_theme_styles(figures::planned_frame(*e, options, plan, base, 3), th);
            for (const auto& panel : frame.panels) {
                for (const auto& rod : panel.data) {
                    if (!rod.id.starts_with("rod:")) continue;
                    // Its key: of its method, in its colour (several starts: one colour each).
                    const auto key = std::find_if(panel.data.begin(), panel.data.end(), [&](const plot::series& k) {
                        return k.id.starts_with("key:") && k.id.ends_with(":" + rod.id.substr(4)) && k.color == rod.color;
                    });
                    ASSERT_NE(key, panel.data.end()) << e->id << ": no key for " << rod.id;
                    EXPECT_EQ(rod.line, key->line == plot::line_style::none ? plot::line_style::solid : key->line)
                        << e->id << " in " << row.name << ": " << rod.id;
                    EXPECT_EQ(rod.color, key->color) << rod.id;
                }
            }
            // One legend: no label twice in a frame.
            std::map<std::string, int> labels;
            for (const auto& panel : frame.panels) {
                for (const auto& s : panel.data) {
                    if (!s.label.empty()) ++labels[entry_name(s.label.markup)];
                }
            }
            for (const auto& [label, n] : labels) EXPECT_EQ(n, 1) << e->id << ": '" << label << "' " << n << " times";
        }
    }
}

// The paper theme's dotted harmonic: the harmonic rod of swing is dotted in paper, as its
// line in the trajectory panel (it was a solid rod).
TEST(TeachingRest, SwingHarmonicRodIsDottedInPaper) {
    const plot::theme th = figures::load_theme("paper");
    const auto options = animated_options(th);
    const auto& e = figures::find("swing");
    const auto plan = figures::plan_animation(e, options);
    const auto frame = plot::with_theme_styles(figures::planned_frame(e, options, plan, figures::build(e, options), 5), th);
    int rods = 0;
    for (const auto& s : frame.panels.at(0).data) {
        if (s.id == "rod:harmonic") {
            ++rods;
            EXPECT_EQ(s.line, plot::line_style::dotted);
            EXPECT_EQ(s.marker, plot::marker_style::none);
        }
        if (s.id == "rod:exact") {
            ++rods;
            EXPECT_EQ(s.line, plot::line_style::solid);  // the theme's exact has no line: the rod stays solid
            EXPECT_EQ(s.marker, plot::marker_style::none);
        }
    }
    EXPECT_EQ(rods, 2);
}

// 2. Energies carry their unit in titles, legends and descriptions.
TEST(TeachingRest, EnergiesHaveTheirUnit) {
    const auto& e = figures::find("over-the-top");
    const auto& p = e.spec.panels.at(0);
    ASSERT_EQ(p.starts.size(), 3U);
    EXPECT_EQ(p.starts[0].label, "<i>E</i> = 1.6\u2009<i>mgL</i>");
    EXPECT_EQ(p.starts[1].label, "<i>E</i> = 2\u2009<i>mgL</i>");
    const auto built = figures::build(e, {});
    const auto d = figures::describe(e, built);
    EXPECT_NE(d.text.find("E = 1.6 mgL swings between two turning points"), std::string::npos) << d.text;
    EXPECT_EQ(d.text.find("E = 2.6 goes"), std::string::npos) << d.text;
    EXPECT_NE(d.alt.find("mgL"), std::string::npos) << d.alt;
    // A plot's energies alike, in its legend.
    const auto dir = temp_dir("teaching-energy");
    const auto r = run_cli("plot phase --energy 1.5,2.5 -f svg --set svg_text=text --name e", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "e.svg").find("mgL"), std::string::npos);
}

// 3. The trail has its legend entry: how far back it reaches.
TEST(TeachingRest, TrailHasALegendEntry) {
    // 0.3 of the exact period at 170 degrees of a 1 m pendulum, 4.89436 s (tests/data/loops_reference.csv,
    // mpmath): 1.468 s, shown as 1.47 s.
    const auto swing = figures::build(figures::find("swing"), {});
    const auto& a = swing.panels.at(0).data;
    const auto key = std::find_if(a.begin(), a.end(), [](const plot::series& s) { return s.id == "key:trail"; });
    ASSERT_NE(key, a.end());
    EXPECT_EQ(key->label.markup, "path of the last 1.47 s");
    EXPECT_TRUE(key->x.empty());
    const auto over = figures::build(figures::find("over-the-top"), {});
    const auto& b = over.panels.at(0).data;
    const auto key2 = std::find_if(b.begin(), b.end(), [](const plot::series& s) { return s.id == "key:trail"; });
    ASSERT_NE(key2, b.end());
    EXPECT_EQ(key2->label.markup, "paths of the last 0.15 periods");
    // Without a [pendulum] table: in periods; no trail, no entry.
    const auto plain = figures::build(entry_of("[[panel]]\nplot = \"pendulum\"\ntheta0 = \"1\"\nmethods = [\"exact\"]\ntrail = 1\n"), {});
    bool found = false;
    for (const auto& s : plain.panels.at(0).data) found = found || (s.id == "key:trail" && s.label.markup == "path of the last 1 period");
    EXPECT_TRUE(found);
    const auto none = figures::build(entry_of("[[panel]]\nplot = \"pendulum\"\ntheta0 = \"1\"\nmethods = [\"exact\"]\n"), {});
    for (const auto& s : none.panels.at(0).data) EXPECT_NE(s.id, "key:trail");
}

/// The clock's box in every frame of the built-in animations holds no ink of the drawing.
void expect_clock_off_drawing(const std::string& theme, const std::vector<std::string>& sizes) {
    for (const auto& row : figures::builtin_themes()) {
        if (row.name != theme) continue;
        for (const std::string& size : sizes) {
            std::vector<std::string> sets;
            if (!size.empty()) sets.push_back("size_px=" + size);
            const plot::theme th = figures::load_theme(row.name, sets);
            const auto options = animated_options(th);
            for (const auto* e : builtin_animations()) {
                const auto plan = figures::plan_animation(*e, options);
                const auto base = figures::build(*e, options);
                for (int i : {0, plan.frames / 3, plan.frames - 1}) {
                    auto with = figures::planned_frame(*e, options, plan, base, i);
                    auto without = with;
                    for (auto& p : without.panels) p.overlay_label = {};
                    const pixels a = render(with, th);
                    const pixels b = render(without, th);
                    ASSERT_EQ(a.v.size(), b.v.size());
                    // The clock's box: where the two differ.
                    int x0 = a.w, y0 = a.h, x1 = -1, y1 = -1;
                    for (int y = 0; y < a.h; ++y) {
                        for (int x = 0; x < a.w; ++x) {
                            const auto k = static_cast<std::size_t>(y) * a.w + x;
                            if (a.v[k] == b.v[k]) continue;
                            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
                        }
                    }
                    ASSERT_GE(x1, 0) << e->id << ": no clock drawn";
                    // Without the clock, that box is background only.
                    const std::uint32_t bg = b.v[0];
                    int ink = 0;
                    for (int y = y0; y <= y1; ++y) {
                        for (int x = x0; x <= x1; ++x) ink += b.v[static_cast<std::size_t>(y) * b.w + x] != bg;
                    }
                    EXPECT_EQ(ink, 0) << e->id << " in " << row.name << " " << size << ", frame " << i << ": "
                                      << ink << " pixels of the drawing in the clock's box (" << x0 << "," << y0
                                      << ")-(" << x1 << "," << y1 << ")";
                }
            }
        }
    }
}

// 6. The clock's line over the drawing: its box holds no ink of the drawing, in the slides
// themes at their size, at 1920x1080 and at 640x360.
TEST(TeachingRest, ClockKeepsOffTheDrawing) {
    expect_clock_off_drawing("slides", {"", "1920x1080", "640x360"});
    expect_clock_off_drawing("slides-dark", {"", "1920x1080", "640x360"});
}

// In the paper theme too (161 to 1351 pixels of the drawing were in the clock's box at 300 dpi
// while the clock was drawn inside the drawing's area): the clock now has a line of its own
// above the drawing (plot::panel::overlay_line).
TEST(TeachingRest, ClockKeepsOffTheDrawingInPaper) { expect_clock_off_drawing("paper", {"", "1920x1080"}); }

// 4. plot --set takes the figure keys columns, legend and title.
TEST(TeachingRest, PlotSetTakesFigureKeys) {
    const auto dir = temp_dir("teaching-set");
    // columns: 1..6 as in a spec; 6 accepted, 7 refused with the spec's message.
    auto r = run_cli("plot pendulum --theta0 10deg,170deg --methods exact --apart --set columns=1 -f svg --name c1", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    r = run_cli("plot period --methods exact --set columns=6 -f svg --name c6", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    r = run_cli("plot period --methods exact --set columns=7 -f svg --name c7", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("columns"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("6"), std::string::npos) << r.err;
    r = run_cli("plot period --methods exact --set columns=two -f svg --name c7", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--set columns 'two': not a whole number"), std::string::npos) << r.err;
    // legend = none leaves the legend out: the method's name is not in the picture.
    r = run_cli("plot period --methods exact,harmonic --set legend=none --set svg_text=text -f svg --name l0", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("plot period --methods exact,harmonic --set svg_text=text -f svg --name l1", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir / "l1.svg").find(">harmonic<"), std::string::npos);
    EXPECT_EQ(slurp(dir / "l0.svg").find(">harmonic<"), std::string::npos);
    r = run_cli("plot period --methods exact --set legend=sideways -f svg --name l2", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("sideways"), std::string::npos) << r.err;
    // A key given both ways is refused; an unknown key names the keys plot --set takes.
    r = run_cli("plot period --methods exact --set legend=none --legend first -f svg --name l3", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--set legend and --legend both give the figure's legend: give one"), std::string::npos) << r.err;
    r = run_cli("plot period --methods exact --set bogus=1 -f svg --name b", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("unknown key 'bogus'; plot --set takes the figure keys columns, legend, title and"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("font_family"), std::string::npos) << r.err;
    // A style key still goes to the style.
    r = run_cli("plot period --methods exact --set line_width_pt=2 -f svg --name s", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    // Hostile: a terminal's escape in the key or the value is not printed raw.
    r = run_cli("plot period --methods exact --set $'\\e[31mx=1' -f svg --name h", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    r = run_cli("plot period --methods exact --set $'columns=\\e[31m' -f svg --name h", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    r = run_cli("plot period --methods exact --set $'title=a\\e[31mb' -f svg --name h", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "h.svg"));
}

// 5. plot trajectory --range in seconds with --length; --omega0 in rad/s from @FILE.
TEST(TeachingRest, TrajectoryRangeInSeconds) {
    const auto dir = temp_dir("teaching-range");
    auto r = run_cli("plot trajectory --methods exact --theta0 170deg --length 1 --range 0,5s -f svg --name s", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    // The same as --time t/s --range 0,5.
    r = run_cli("plot trajectory --methods exact --theta0 170deg --length 1 --time t/s --range 0,5 -f svg --name t", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir / "s.svg"), slurp(dir / "t.svg"));
    // In t/T0: 5 s of a 1 m pendulum is 5 / (2 pi sqrt(1 / 9.80665)) = 2.4922 T0.
    r = run_cli("plot trajectory --methods exact --theta0 170deg --length 1 --time t/T0 --range 0,5s -f svg --name u", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("plot trajectory --methods exact --theta0 170deg --length 1 --range 0,5s --time t/T -f svg --name v", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--range '0,5s' in seconds goes with --time t/s (the default then) or t/T0, not --time t/T"),
              std::string::npos)
        << r.err;
    r = run_cli("plot trajectory --methods exact --theta0 170deg --range 0,5s -f svg --name w", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--range '0,5s' in seconds needs the pendulum's --length L in metres"), std::string::npos)
        << r.err;
    r = run_cli("plot trajectory --methods exact --theta0 170deg --length 1 --range $'0,5\\e[31ms' -f svg --name x", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    for (const char* name : {"v.svg", "w.svg", "x.svg"}) EXPECT_FALSE(std::filesystem::exists(dir / name)) << name;
}

TEST(TeachingRest, RadPerSecondFromAFile) {
    const auto dir = temp_dir("teaching-rads");
    std::ofstream(dir / "w.txt") << "# launch velocities\n2rad/s, 1.5\n";
    const std::string command = "eval --theta0 0 --length 1";
    const auto listed = run_cli(command + " --omega0 2rad/s,1.5", dir);
    ASSERT_EQ(listed.status, 0) << listed.err;
    const auto read = run_cli(command + " --omega0 @w.txt", dir);
    ASSERT_EQ(read.status, 0) << read.err;
    EXPECT_EQ(read.out, listed.out);
    const auto in = run_command("cd '" + dir.string() + "' && printf '2rad/s,1.5\\n' | '" + std::string(PENDULUM_EXE) +
                                "' " + command + " --omega0 -");
    ASSERT_EQ(in.status, 0) << in.err;
    EXPECT_EQ(in.out, listed.out);
    // trajectory takes one start.
    std::ofstream(dir / "one.txt") << "2rad/s\n";
    const auto direct = run_cli("trajectory --theta0 0 --length 1 --at 0.1 --omega0 2rad/s", dir);
    const auto file = run_cli("trajectory --theta0 0 --length 1 --at 0.1 --omega0 @one.txt", dir);
    ASSERT_EQ(file.status, 0) << file.err;
    EXPECT_EQ(file.out, direct.out);
    // Without a length, the file's rad/s is refused as the option's is.
    const auto bare = run_cli("trajectory --theta0 0 --at 0.1 --omega0 @one.txt", dir);
    EXPECT_EQ(bare.status, 2);
    EXPECT_NE(bare.err.find("a velocity in rad/s needs the pendulum's --length"), std::string::npos) << bare.err;
    // plot alike.
    const auto plot = run_cli("plot trajectory --methods exact --theta0 0 --omega0 @one.txt --length 1 -f svg --name p", dir);
    EXPECT_EQ(plot.status, 0) << plot.err;
}
