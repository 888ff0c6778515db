// SPDX-License-Identifier: GPL-3.0-or-later
// Animations: the frame plan, GIF, PDF pages and PNG sequences, one frame with --at, a
// Beamer document that plays the PDF, and bad input.
#include "figures/animation.hpp"
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/plot_builders.hpp"
#include "figures/spec_build.hpp"
#include "figures/themes.hpp"
#include "pendulum/exact.hpp"
#include "plot/frames.hpp"
#include "plot/workers.hpp"
#include "process.hpp"

#include <gif_lib.h>
#include <sched.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::run_command;
using test_support::slurp;
using test_support::temp_dir;

/// Frames, size, loop and total delay of a GIF, decoded with giflib.
struct gif_facts {
    int frames = 0;
    int width = 0;
    int height = 0;
    int total_delay = 0;  // hundredths of a second
    bool loops = false;
};

gif_facts read_gif(const std::string& bytes) {
    struct source {
        const std::string* data;
        std::size_t pos = 0;
    } src{&bytes};
    int error = 0;
    GifFileType* gif = DGifOpen(&src, [](GifFileType* g, GifByteType* buf, int n) {
        auto* s = static_cast<source*>(g->UserData);
        n = std::min<int>(n, static_cast<int>(s->data->size() - s->pos));
        std::memcpy(buf, s->data->data() + s->pos, static_cast<std::size_t>(n));
        s->pos += static_cast<std::size_t>(n);
        return n;
    }, &error);
    gif_facts f;
    if (!gif) return f;
    if (DGifSlurp(gif) == GIF_OK) {
        f.frames = gif->ImageCount;
        f.width = gif->SWidth;
        f.height = gif->SHeight;
        for (int i = 0; i < gif->ImageCount; ++i) {
            GraphicsControlBlock gcb;
            if (DGifSavedExtensionToGCB(gif, i, &gcb) == GIF_OK) f.total_delay += gcb.DelayTime;
        }
    }
    DGifCloseFile(gif, &error);
    f.loops = bytes.find("NETSCAPE2.0") != std::string::npos;
    return f;
}

/// An animation as a theme draws it: its build options, frame plan and still base figure.
struct animated_build {
    plot::theme theme;
    figures::build_options options;
    figures::animation_plan plan;
    plot::figure base;
};

animated_build build_animated(const figures::entry& e, std::string_view theme_name) {
    animated_build b{figures::load_theme(std::string(theme_name)), {}, {}, {}};
    b.options = figures::sized_by({}, b.theme);
    b.options.animated = true;
    b.plan = figures::plan_animation(e, b.options);
    b.base = figures::build(e, b.options);
    return b;
}

TEST(Animation, FramesOfTheSwing) {
    const auto& swing = figures::find("swing");
    ASSERT_TRUE(swing.spec.animation);
    const auto plan = figures::plan_animation(swing, {});
    // Three exact periods of a 1 m pendulum at 170 degrees, 25 frames per second (the
    // default), the last frame within a step before their end; then half a second of cross-fade.
    const double period_s = 2 * std::numbers::pi * std::sqrt(1.0 / 9.80665) *
                            pendulum::period_ratio(170 * std::numbers::pi / 180);
    EXPECT_EQ(plan.motion_frames, static_cast<int>(std::ceil(3 * period_s * 25)));
    EXPECT_EQ(plan.frames, plan.motion_frames + 13);
    EXPECT_NEAR(plan.time(plan.motion_frames - 1), 3 * plan.reference_period, plan.step);
    EXPECT_LT(plan.time(plan.motion_frames - 1), 3 * plan.reference_period);
    EXPECT_NEAR(plan.step * plan.seconds_per_unit, 1.0 / 25, 1e-15);
    // The separatrix has no [pendulum]: a 1 m pendulum's time.
    EXPECT_NEAR(figures::plan_animation(figures::find("separatrix"), {}).seconds_per_unit,
                std::sqrt(1.0 / 9.80665), 1e-15);
}

TEST(Animation, GifPdfAndPngSequence) {
    const auto dir = temp_dir("animation");
    auto r = run_cli("render swing --theme slides -f gif,pdf,png --frames 2..13 --dpi 16 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::set<std::string> expected = {"swing.gif", "swing.pdf"};
    for (int i = 2; i <= 13; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "swing-%04d.png", i);
        expected.insert(name);
    }
    EXPECT_EQ(files_in(dir), expected);
    const std::string gif = slurp(dir / "swing.gif");
    const auto facts = read_gif(gif);
    EXPECT_EQ(facts.frames, 12);
    EXPECT_EQ(facts.width, 160);  // 25.4 cm at 16 dpi
    EXPECT_EQ(facts.height, 90);
    EXPECT_TRUE(facts.loops);
    // 25 frames per second: 12 delays of 4 hundredths, the true 0.48 s.
    EXPECT_EQ(facts.total_delay, 48);
    const auto pages = run_command("pdfinfo '" + (dir / "swing.pdf").string() + "'");
    EXPECT_NE(pages.out.find("Pages:           12"), std::string::npos) << pages.out;
    // The same frames again: the same bytes.
    r = run_cli("render swing --theme slides -f gif --frames 2..13 --dpi 16 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir / "swing.gif"), gif);
    fs::remove_all(dir);
}

TEST(Animation, OneFrameAt) {
    const auto dir = temp_dir("animation-at");
    const auto r = run_cli("render swing --at 0.25 -f svg,png,pdf --dpi 20 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"swing.svg", "swing.png", "swing.pdf"}));
    // The clock shows the time asked for: a quarter of the exact period of the spec's 1 m
    // pendulum released at 170 degrees, in seconds, and no other time.
    const double period_s = 2 * std::numbers::pi * std::sqrt(1.0 / 9.80665) *
                            pendulum::period_ratio(170 * std::numbers::pi / 180);
    char clock[32];
    std::snprintf(clock, sizeof clock, "t = %.2f s", 0.25 * period_s);
    const auto text = run_command("pdftotext '" + (dir / "swing.pdf").string() + "' -");
    ASSERT_EQ(text.status, 0) << "pdftotext (poppler-utils): " << text.err;
    EXPECT_NE(text.out.find(clock), std::string::npos) << "no '" << clock << "' in:\n" << text.out;
    EXPECT_EQ(text.out.find("t = "), text.out.rfind("t = ")) << text.out;
    fs::remove_all(dir);
}

TEST(Animation, BeamerPlaysThePdf) {
    if (run_command("kpsewhich animate.sty beamer.cls").out.find("animate.sty") == std::string::npos) {
        // CI installs what make deps lists: there a missing package is a failure, not a skip.
        const char* ci = std::getenv("CI");
        if (ci && std::string(ci) == "true") FAIL() << "animate.sty is missing (make deps installs texlive-latex-extra)";
        GTEST_SKIP() << "animate.sty (texlive-latex-extra) is not installed";
    }
    const auto dir = temp_dir("beamer");
    auto r = run_cli("render separatrix -f pdf --frames 1..6 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::ofstream(dir / "talk.tex") << "\\documentclass{beamer}\n\\usepackage{animate}\n\\begin{document}\n"
                                       "\\begin{frame}\n\\animategraphics[loop,autoplay,width=\\linewidth]{30}{separatrix}{}{}\n"
                                       "\\end{frame}\n\\end{document}\n";
    r = run_command("cd '" + dir.string() + "' && pdflatex -interaction=nonstopmode -halt-on-error talk.tex");
    EXPECT_EQ(r.status, 0) << r.out.substr(r.out.size() > 2000 ? r.out.size() - 2000 : 0);
    EXPECT_TRUE(fs::exists(dir / "talk.pdf"));
    fs::remove_all(dir);
}

TEST(Animation, SameBytesForAnyNumberOfJobs) {
    // The GIF is encoded in parts, as many as the workers keep busy: the parts join into the
    // bytes of one encoder whatever their number. So do the PNG frames and still figures.
    std::map<std::string, std::string> first;
    for (const std::string jobs : {"--jobs 1", "--jobs 2", "--jobs 7", "", "--jobs 3"}) {
        const auto dir = temp_dir("animation-jobs");
        const std::string env = jobs.empty() ? "PENDULUM_FIGURES_JOBS=2 " : "";
        auto r = run_command("cd '" + dir.string() + "' && " + env + "'" + PENDULUM_EXE + "' render swing --theme slides " +
                             "-f gif,png --frames 3..40 --dpi 16 " + jobs + " && '" + PENDULUM_EXE +
                             "' render fig7 fig2 -f png,pdf --dpi 30 " + jobs);
        ASSERT_EQ(r.status, 0) << jobs << ": " << r.err;
        std::map<std::string, std::string> files;
        for (const auto& name : files_in(dir)) files[name] = slurp(dir / name);
        EXPECT_EQ(files.size(), 38u + 1 + 4) << jobs;
        if (first.empty()) {
            first = files;
        } else {
            EXPECT_TRUE(files == first) << jobs << " wrote other bytes than --jobs 1";
        }
        fs::remove_all(dir);
    }
    EXPECT_EQ(read_gif(first["swing.gif"]).frames, 38);
    for (const std::string bad : {"--jobs 0", "--jobs 1025", "--jobs x"}) {
        const auto r = run_cli("render swing -f gif --frames 1..2 --dpi 16 -o /nonexistent " + bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.err.find("--jobs"), std::string::npos) << r.err;
    }
    const auto r = run_command("PENDULUM_FIGURES_JOBS=two '" + std::string(PENDULUM_EXE) + "' plot period --methods exact -o /tmp");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("PENDULUM_FIGURES_JOBS='two': the number of workers"), std::string::npos) << r.err;
}

TEST(Workers, OnePerCpuOfTheAffinityMask) {
    // What taskset -c 0 does to the program: only CPU 0 is allowed, so one worker.
    cpu_set_t saved;
    ASSERT_EQ(sched_getaffinity(0, sizeof saved, &saved), 0);
    EXPECT_EQ(plot::usable_cpus(), static_cast<unsigned>(CPU_COUNT(&saved)));
    cpu_set_t one;
    CPU_ZERO(&one);
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
        if (CPU_ISSET(cpu, &saved)) {
            CPU_SET(cpu, &one);
            break;
        }
    }
    ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
    const unsigned narrowed = plot::usable_cpus();
    const unsigned workers = plot::worker_count(0, 100);
    ASSERT_EQ(sched_setaffinity(0, sizeof saved, &saved), 0);
    EXPECT_EQ(narrowed, 1u);
    EXPECT_EQ(workers, 1u);
    // --jobs wins over the mask, and there are never more workers than tasks.
    EXPECT_EQ(plot::worker_count(5, 100), 5u);
    EXPECT_EQ(plot::worker_count(5, 3), 3u);
    EXPECT_EQ(plot::worker_count(0, 0), 1u);
}

TEST(Workers, FewerForLargeFrames) {
    // Each worker holds a frame: at 3840 x 2160 (32 MiB of ARGB32) one, at 1280 x 720 all.
    const std::size_t uhd = std::size_t{3840} * 2160 * 4;
    const std::size_t hd = std::size_t{1280} * 720 * 4;
    EXPECT_EQ(plot::workers_for_frames(2, uhd), 1u);
    EXPECT_EQ(plot::workers_for_frames(16, uhd), 1u);
    EXPECT_EQ(plot::workers_for_frames(2, hd), 2u);
    EXPECT_EQ(plot::workers_for_frames(64, hd), 13u);
    EXPECT_EQ(plot::workers_for_frames(4, std::size_t{1} << 30), 1u);
    for (unsigned w : {1u, 2u, 7u, 64u}) {
        EXPECT_LE(plot::workers_for_frames(w, hd) * hd, std::size_t{48} << 20) << w;
        EXPECT_GE(plot::workers_for_frames(w, 1), 1u);
    }
}

TEST(Animation, PngFramesAreTheFramesDrawnWhole) {
    // A PNG frame, drawn into a worker's reused buffers, has the bytes of that frame's figure
    // rendered as a still PNG, in every animation and theme, at a resolution where
    // anti-aliasing shows any difference in what is drawn or in what order.
    int checked = 0;
    for (const auto& e : figures::catalog()) {
        if (!e.spec.animation) continue;
        for (const auto& theme_row : figures::builtin_themes()) {
            const auto [theme, options, plan, base] = build_animated(e, theme_row.name);
            const double dpi = 150;
            plot::argb_image image;
            std::vector<unsigned char> rows;
            for (const int i : {0, plan.frames / 3, plan.frames - 1}) {
                const auto f = figures::animation_frame(e, options, plan, base, plan.time(i));
                plot::render_rgb24(image, f, theme, dpi);
                EXPECT_TRUE(plot::png_of_pixels(image, dpi, rows) == plot::render(f, theme, "png", plot::output_options{dpi}))
                    << e.id << " in " << theme_row.name << ", frame " << i;
                ++checked;
            }
        }
    }
    EXPECT_GE(checked, 3 * 3 * 3);
}

TEST(Animation, BadInputIsExit2AndWritesNothing) {
    const auto dir = temp_dir("animation-bad");
    const auto spec = [&](const std::string& animation, const std::string& panel) {
        std::ofstream(dir / "a.toml") << "[animation]\n" << animation << "\n[[panel]]\n" << panel << "\n";
    };
    const std::string pendulum = "plot = \"pendulum\"\ntheta0 = \"1\"\nmethods = [\"exact\"]";
    const std::pair<std::string, std::string> cases[] = {
        {"fps = 0", "'fps' = 0 is out of range; allowed from 1 to 120"},
        {"fps = 121", "'fps' = 121 is out of range"},
        {"periods = 0", "'periods' = 0 is out of range; allowed above 0"},
        {"periods = -1", "'periods' = -1 is out of range"},
        {"duration_s = 3", "duration_s needs a [pendulum] table"},
        {"periods = 1000", "would have"},
        {"periods = 1\nduration_s = 3", "takes periods or duration_s, not both"},
    };
    for (const auto& [animation, why] : cases) {
        spec(animation, pendulum);
        const auto r = run_cli("render a.toml -f gif", dir);
        EXPECT_EQ(r.status, 2) << animation;
        EXPECT_NE(r.err.find(why), std::string::npos) << animation << ": " << r.err;
        EXPECT_EQ(files_in(dir), (std::set<std::string>{"a.toml"})) << animation;
    }
    spec("periods = 1", "plot = \"pendulum\"\nmethods = [\"exact\"]");
    auto r = run_cli("render a.toml -f gif", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("a pendulum panel needs theta0"), std::string::npos) << r.err;
    for (const char* frames : {"0..5", "5..3", "1..100000", "x"}) {
        r = run_cli(std::string("render swing -f gif --frames ") + frames, dir);
        EXPECT_EQ(r.status, 2) << frames;
        EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
    }
    r = run_cli("render fig1 --frames 1..3", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("apply to animations"), std::string::npos) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"a.toml"}));
    fs::remove_all(dir);
}

/// The bobs of a pendulum panel in one frame: for each start and method, the places of its
/// motion streak (oldest first) and of the bob itself.
struct frame_bobs {
    std::vector<std::vector<std::pair<double, double>>> streaks;
    std::vector<std::pair<double, double>> bobs;
    std::vector<int> colors;
};

frame_bobs bobs_of(const plot::panel& panel) {
    frame_bobs out;
    std::vector<std::pair<double, double>> streak;
    for (const auto& s : panel.data) {
        if (!s.overlay || s.marker == plot::marker_style::none || s.marker_scale != figures::bob_marker_scale) continue;
        if (s.alpha < 1) {
            streak.emplace_back(s.x.at(0), s.y.at(0));
            continue;
        }
        out.streaks.push_back(streak);
        out.bobs.emplace_back(s.x.at(0), s.y.at(0));
        out.colors.push_back(s.color);
        streak.clear();
    }
    return out;
}

double distance(std::pair<double, double> a, std::pair<double, double> b) {
    return std::hypot(a.first - b.first, a.second - b.second);
}

TEST(Animation, NoStrobingInAnyBuiltinAnimationOrTheme) {
    // For every frame of every built-in animation with a pendulum, in every theme: the bob's
    // jump since the previous frame, against the bob's diameter, and the gaps of the motion
    // streak that bridges it, which must begin where the previous frame's bob was.
    int animations = 0;
    for (const auto& e : figures::catalog()) {
        if (!e.spec.animation) continue;
        std::vector<std::size_t> drawings;
        for (std::size_t i = 0; i < e.spec.panels.size(); ++i) {
            if (e.spec.panels[i].plot->drawing) drawings.push_back(i);
        }
        if (drawings.empty()) continue;
        ++animations;
        for (const auto& theme_row : figures::builtin_themes()) {
            const auto [theme, options, plan, base] = build_animated(e, theme_row.name);
            // The bob's diameter in rod lengths, at least: the shorter side of the panel's cell
            // (of a figure of fixed size, its share of it) holds the drawing's 2.4 rod lengths,
            // and the plot area inside it is smaller still.
            double width_cm = base.panel_width_cm;
            double height_cm = base.panel_aspect * base.panel_width_cm;
            if (theme.fixed_width_cm > 0) width_cm = theme.fixed_width_cm / base.cols;
            if (theme.fixed_height_cm > 0) height_cm = theme.fixed_height_cm / base.rows;
            const double side_pt = std::min(width_cm, height_cm) / 2.54 * 72;
            const double diameter = 2 * theme.marker_radius_pt * figures::bob_marker_scale * 2.4 / side_pt;
            double worst_jump = 0;
            double worst_gap = 0;
            frame_bobs last;
            for (int i = 0; i < plan.frames; ++i) {
                const auto f = figures::animation_frame(e, options, plan, base, plan.time(i));
                for (std::size_t d : drawings) {
                    const auto now = bobs_of(f.panels[d]);
                    ASSERT_FALSE(now.bobs.empty()) << e.id;
                    if (i == 0) {
                        for (const auto& streak : now.streaks) EXPECT_TRUE(streak.empty()) << e.id << ": nothing before the release";
                        last = now;
                        continue;
                    }
                    ASSERT_EQ(now.bobs.size(), last.bobs.size()) << e.id;
                    for (std::size_t b = 0; b < now.bobs.size(); ++b) {
                        worst_jump = std::max(worst_jump, distance(last.bobs[b], now.bobs[b]) / diameter);
                        // The streak: from the previous frame's bob, through its faint bobs, to this one.
                        std::vector<std::pair<double, double>> chain = {last.bobs[b]};
                        chain.insert(chain.end(), now.streaks[b].begin(), now.streaks[b].end());
                        chain.push_back(now.bobs[b]);
                        if (!now.streaks[b].empty()) {
                            EXPECT_LT(distance(now.streaks[b].front(), last.bobs[b]), 1e-9) << e.id << " frame " << i;
                        }
                        for (std::size_t k = 1; k < chain.size(); ++k) {
                            worst_gap = std::max(worst_gap, distance(chain[k - 1], chain[k]) / diameter);
                        }
                    }
                    last = now;
                }
            }
            std::cout << e.id << " in " << theme_row.name << ": " << plan.frames << " frames, bob diameter "
                      << diameter << " rod lengths; largest jump per frame " << worst_jump
                      << " diameters, largest gap in its streak " << worst_gap << " diameters\n";
            // Neighbouring bobs overlap by half their diameter at least: one continuous smear.
            EXPECT_LE(worst_gap, 0.5) << e.id << " in " << theme_row.name;
        }
    }
    EXPECT_GE(animations, 2);
}

TEST(Animation, StreakBridgesTheFrameAndFades) {
    // A bob swinging through the bottom at 2 w0 (170 degrees) moves 0.21 rod lengths in a
    // frame of 0.104 w0 t (1/30 s of a 1 m pendulum).
    const pendulum::exact_solution exact(170 * std::numbers::pi / 180);
    const auto theta = [&](double t) { return exact.theta_at_fraction(t / (4 * exact.quarter_period())); };
    const double bottom = exact.quarter_period();
    const double step = 1.0 / 30 / std::sqrt(1.0 / 9.80665);
    const auto streak = figures::motion_streak(theta, bottom, step);
    ASSERT_GE(streak.size(), 10u);
    EXPECT_NEAR(streak.front().angle, theta(bottom - step), 1e-12);
    for (std::size_t k = 1; k < streak.size(); ++k) {
        EXPECT_LE(2 * std::sin(std::fabs(streak[k].angle - streak[k - 1].angle) / 2), figures::streak_spacing * 1.01);
        EXPECT_GT(streak[k].alpha, streak[k - 1].alpha);
    }
    EXPECT_LT(streak.back().alpha, 1);
    // At rest, still figures and the first frame: no streak.
    EXPECT_TRUE(figures::motion_streak(theta, bottom, 0).empty());
    EXPECT_TRUE(figures::motion_streak(theta, 0, step).empty());
    EXPECT_TRUE(figures::motion_streak([](double) { return 0.3; }, 5, step).empty());
}

TEST(Animation, OverTheTopSwingsCreepsAndRotates) {
    const auto& e = figures::find("over-the-top");
    ASSERT_TRUE(e.spec.animation);
    figures::build_options options;
    options.animated = true;
    const auto plan = figures::plan_animation(e, options);
    // Two periods of the libration at E = 1.6, T/T0 = 2 K(0.8)/pi, in a 1 m pendulum's time.
    const double period = pendulum::motion::from_energy(1.6).period();
    EXPECT_NEAR(plan.reference_period, period, 1e-12);
    EXPECT_EQ(plan.motion_frames, static_cast<int>(std::ceil(2 * period * std::sqrt(1.0 / 9.80665) * 25 - 1e-9)));
    EXPECT_EQ(plan.frames, plan.motion_frames + 13);  // a cross-fade of half a second
    const auto base = figures::build(e, options);
    double highest[3] = {-2, -2, -2};
    double lowest_after_top[3] = {2, 2, 2};
    bool passed_top = false;
    for (int i = 0; i < plan.frames; ++i) {
        const auto f = figures::animation_frame(e, options, plan, base, plan.time(i));
        const auto now = bobs_of(f.panels[0]);
        ASSERT_EQ(now.bobs.size(), 3u);
        EXPECT_EQ(now.colors, (std::vector<int>{0, 1, 2}));
        for (int b = 0; b < 3; ++b) {
            highest[b] = std::max(highest[b], now.bobs[static_cast<std::size_t>(b)].second);
            if (highest[b] > 0.999) lowest_after_top[b] = std::min(lowest_after_top[b], now.bobs[static_cast<std::size_t>(b)].second);
        }
        // The rotation goes past the top: its bob shows on the left of the pivot after it.
        if (now.bobs[2].second > 0.9 && now.bobs[2].first < 0) passed_top = true;
        // A moving point on each orbit of the phase portrait, in the same colours.
        std::vector<int> dots;
        for (const auto& s : f.panels[1].data) {
            if (s.overlay && s.marker == plot::marker_style::filled_circle) dots.push_back(s.color);
        }
        EXPECT_EQ(dots, (std::vector<int>{0, 1, 2}));
    }
    // E = 1.6 turns back where 1 - cos(theta) = 1.6: y = 0.6.
    EXPECT_NEAR(highest[0], 0.6, 0.01);
    // E = 2 creeps towards the top and never reaches it; E = 2.6 goes over it and comes round again.
    EXPECT_GT(highest[1], 0.99);
    EXPECT_LT(highest[1], 1.0);
    EXPECT_GT(highest[2], 0.999);
    EXPECT_LT(lowest_after_top[2], -0.99);
    EXPECT_TRUE(passed_top);
    // Its words: what each pendulum does.
    const auto d = figures::describe(e, figures::build(e));
    for (const char* fact : {"E = 1.6 mgL swings between two turning points (libration)",
                             "E = 2 mgL creeps up towards the top and never quite reaches it (separatrix)",
                             "E = 2.6 mgL goes over the top, round and round (rotation)"}) {
        EXPECT_NE(d.text.find(fact), std::string::npos) << fact << " in\n" << d.text;
    }
}

TEST(Animation, OverTheTopInEveryThemeAndFormat) {
    const auto dir = temp_dir("over-the-top");
    for (const auto& theme : figures::builtin_themes()) {
        const auto r = run_cli("render over-the-top --theme " + std::string(theme.name) +
                                   " -f gif,pdf,png,mp4,webm --frames 20..23 --dpi 16 -o '" + dir.string() + "'");
        ASSERT_EQ(r.status, 0) << theme.name << ": " << r.err;
        EXPECT_EQ(files_in(dir), (std::set<std::string>{"over-the-top.gif", "over-the-top.pdf", "over-the-top.mp4",
                                                        "over-the-top.webm", "over-the-top-0020.png",
                                                        "over-the-top-0021.png", "over-the-top-0022.png",
                                                        "over-the-top-0023.png"}))
            << theme.name;
        EXPECT_EQ(read_gif(slurp(dir / "over-the-top.gif")).frames, 4) << theme.name;
        for (const auto& f : fs::directory_iterator(dir)) fs::remove(f.path());
    }
    fs::remove_all(dir);
}

TEST(Animation, SeveralStartsInOnePendulumPanel) {
    // The isochronism demonstration: released together at 10 and 170 degrees, each its own
    // colour and legend entry, each swinging with its own period.
    const auto spec = figures::parse_spec("[animation]\nperiods = 1\n[[panel]]\nplot = \"pendulum\"\n"
                                          "theta0 = [\"10deg\", \"170deg\"]\nmethods = [\"exact\"]\n",
                                          "isochronism.toml");
    ASSERT_EQ(spec.panels[0].theta0.size(), 2u);
    const auto f = figures::build_figure(spec);
    std::vector<std::string> labels;
    std::vector<int> colors;
    for (const auto& s : f.panels[0].data) {
        if (s.label.empty()) continue;
        labels.push_back(s.label.markup);
        colors.push_back(s.color);
    }
    EXPECT_EQ(labels, (std::vector<std::string>{"<i>\u03d1</i><sub>0</sub> = 10\u00b0",
                                                "<i>\u03d1</i><sub>0</sub> = 170\u00b0"}));
    EXPECT_EQ(colors, (std::vector<int>{0, 1}));
    // Half a period of the 10 degree pendulum later, it is at -10 degrees while the 170
    // degree one (T = 2.4 T0) is still on its way down, on the side it was released from.
    auto moving = f;
    for (auto& p : moving.panels) std::erase_if(p.data, [](const plot::series& s) { return s.marker_scale == figures::bob_marker_scale; });
    const double half = 0.5 * 4 * pendulum::exact_solution(10 * std::numbers::pi / 180).quarter_period();
    figures::add_frame_state(moving, spec, spec.panels, half);
    const auto now = bobs_of(moving.panels[0]);
    ASSERT_EQ(now.bobs.size(), 2u);
    EXPECT_NEAR(now.bobs[0].first, -std::sin(10 * std::numbers::pi / 180), 1e-9);
    const double theta170 = pendulum::exact_solution(170 * std::numbers::pi / 180)
                                .theta_at_fraction(half / (4 * pendulum::exact_solution(170 * std::numbers::pi / 180).quarter_period()));
    EXPECT_NEAR(now.bobs[1].first, std::sin(theta170), 1e-9);
    EXPECT_GT(now.bobs[1].first, 0);
}

TEST(Animation, BadCombinationsAreExit2AndSayWhatWorks) {
    const auto dir = temp_dir("combinations");
    const std::pair<std::string, std::string> cases[] = {
        {"plot period --x energy --methods exact,lowest", "use methods = [\"exact\"]"},
        {"plot period --x energy --range -1,4", "give energies from 0 up"},
        {"plot period --x energy --y error-log", "y = \"value\""},
        {"plot period --x energy --angle-unit deg", "leave out angle_unit"},
        {"plot period --x time", "'x' = \"time\""},
        {"plot pendulum --energy 2.6 --methods exact,lowest", "describes librations only"},
        {"plot pendulum --energy -1", "energy"},
        {"plot trajectory --energy 2.5 --methods exact,harmonic --time t/T0", "describes librations only"},
        {"plot phase --energy 3 --trail 0.3", "does not apply to plot 'phase'"},
        {"plot trajectory --energy 2 --time t/T", "has no period T"},
    };
    for (const auto& [command, why] : cases) {
        const auto r = run_cli(command + " -f svg", dir);
        EXPECT_EQ(r.status, 2) << command;
        EXPECT_NE(r.err.find(why), std::string::npos) << command << ": " << r.err;
    }
    EXPECT_EQ(files_in(dir), std::set<std::string>{});
    for (const char* good : {"plot phase --energy 0.5,1.5,2,2.5,3 --angle-unit deg -f svg",
                             "plot trajectory --theta0 0 --omega0 2.2 -f svg",
                             "plot period --x energy -f svg", "plot pendulum --energy 1.6,2,2.6 -f svg"}) {
        const auto r = run_cli(good, dir);
        EXPECT_EQ(r.status, 0) << good << ": " << r.err;
    }
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"phase.svg", "trajectory.svg", "period.svg", "pendulum.svg"}));
    fs::remove_all(dir);
}

}  // namespace
