// SPDX-License-Identifier: GPL-3.0-or-later
// Loops without a jump: an animation's last frame runs on into its first (whole periods of
// every drawn motion), or cross-fades into it, or holds; GIF frame rates that play evenly.
#include "figures/animation.hpp"
#include "figures/catalog.hpp"
#include "figures/spec_build.hpp"
#include "figures/spec.hpp"
#include "pendulum/methods.hpp"
#include "plot/gif.hpp"
#include "plot/output.hpp"
#include "process.hpp"

#include <gif_lib.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;
using test_support::temp_dir;

constexpr double pi = std::numbers::pi;

figures::entry entry_of(const std::string& toml, const std::string& id) {
    figures::entry e;
    e.id = id;
    e.source = toml;
    e.spec = figures::parse_spec(toml, id + ".toml");
    return e;
}

/// One bob an animation draws: its panel, its angle at w0 t from the core (not the drawing).
struct bob {
    std::string name;
    bool drawing = false;
    std::function<double(double)> theta;
};

/// Every moving bob, dot or cursor's motion of the animation, from the motions the panels start.
std::vector<bob> bobs_of(const figures::entry& e) {
    std::vector<bob> out;
    for (const auto& p : figures::panels_of(e)) {
        if (!p.plot->add_frame || p.plot->range == figures::range_kind::times) continue;
        std::vector<std::pair<std::string, pendulum::motion>> motions;
        for (const auto& a : p.theta0) motions.emplace_back(a.text, pendulum::motion::from_amplitude(a.theta0()));
        for (const auto& s : p.starts) motions.emplace_back(s.label, s.motion);
        for (const auto& [name, motion] : motions) {
            for (const auto& m : p.methods) {
                bob b{e.id + " " + std::string(p.plot->name) + " " + name + " " + m.method.text(), p.plot->drawing, {}};
                if (m.method.is_exact()) {
                    b.theta = [motion](double t) { return motion.theta(t); };
                } else {
                    b.theta = [motion, s = pendulum::method_solution(m.method, motion.amplitude())](double t) {
                        return motion.libration_center() + s.theta(motion.libration_clock(t));
                    };
                }
                out.push_back(std::move(b));
            }
        }
    }
    return out;
}

/// The angle from a to b the short way round (a rotation's angle is unwrapped).
double turn(double a, double b) { return std::remainder(b - a, 2 * pi); }

/// Across the seam (last frame of the motion to the first) every bob moves no more than its
/// largest move from one frame to the next.
void expect_seamless(const figures::entry& e, const figures::animation_plan& plan) {
    ASSERT_EQ(plan.loop, figures::loop_mode::periods) << e.id;
    ASSERT_TRUE(plan.seamless) << e.id;
    ASSERT_EQ(plan.frames, plan.motion_frames) << e.id;
    for (const auto& b : bobs_of(e)) {
        // Every frame draws its own time (a drawing's trail reaches into the loop before).
        const auto at = [&](int i) { return b.theta(plan.time(i)); };
        double largest = 0;
        for (int i = 0; i + 1 < plan.motion_frames; ++i) largest = std::max(largest, std::fabs(turn(at(i), at(i + 1))));
        const double seam = std::fabs(turn(at(plan.motion_frames - 1), at(0)));
        EXPECT_LE(seam, largest * (1 + 1e-9)) << b.name << ": " << seam << " rad across the seam, "
                                              << largest << " at most between frames";
    }
}

/// A cross-fade: frames after the motion's, the first frame fading in over them, more in each.
void expect_crossfade(const figures::entry& e, const figures::animation_plan& plan) {
    ASSERT_EQ(plan.loop, figures::loop_mode::crossfade) << e.id;
    ASSERT_GT(plan.frames, plan.motion_frames + 1) << e.id;
    EXPECT_EQ(plan.fade_in(plan.motion_frames - 1), 0.0);
    for (int i = plan.motion_frames; i < plan.frames; ++i) {
        EXPECT_GT(plan.fade_in(i), plan.fade_in(i - 1)) << e.id << " frame " << i;
        EXPECT_LT(plan.fade_in(i), 1.0);
        // The motion runs on under the fade.
        EXPECT_DOUBLE_EQ(plan.time(i), i * plan.step);
    }
    // The last frame is mostly the first: what is left of the motion has at most a frame's share.
    const int fade = plan.frames - plan.motion_frames;
    EXPECT_NEAR(plan.fade_in(plan.frames - 1), fade / (fade + 1.0), 1e-12);
    // The blended frames exist: the last one draws the first frame's moving parts faded in.
    figures::build_options o;
    o.animated = true;
    const plot::figure base = figures::build(e, o);
    const plot::figure last = figures::planned_frame(e, o, plan, base, plan.frames - 1);
    const plot::figure first = figures::planned_frame(e, o, plan, base, 0);
    std::size_t faded = 0;
    std::size_t moving = 0;
    for (std::size_t k = 0; k < last.panels.size(); ++k) {
        for (const auto& s : first.panels[k].data) moving += s.overlay ? 1 : 0;
        for (const auto& s : last.panels[k].data) {
            if (s.id.ends_with(":fade-in")) {
                ++faded;
                EXPECT_TRUE(s.label.markup.empty()) << "a faded-in copy adds no legend entry";
            }
        }
    }
    EXPECT_GT(faded, 0u) << e.id;
    EXPECT_EQ(faded, moving) << e.id << ": every moving part of the first frame fades in";
}

TEST(Loops, EveryBuiltInAnimationLoopsWithoutAJump) {
    int animations = 0;
    for (const auto& e : figures::catalog()) {
        if (!e.spec.animation) continue;
        ++animations;
        const auto plan = figures::plan_animation(e, {});
        EXPECT_TRUE(plan.note.empty()) << e.id << ": a built-in says how it loops: " << plan.note;
        if (plan.loop == figures::loop_mode::periods) {
            expect_seamless(e, plan);
        } else {
            expect_crossfade(e, plan);
        }
    }
    EXPECT_EQ(animations, 3);
}

TEST(Loops, TheBuiltInsCrossFadeWhereTheirPeriodsNeverMeet) {
    // swing's exact, harmonic and lowest-order periods at 170 degrees (4.894, 2.006 and
    // 4.123 s for 1 m) meet within a frame in no loop of up to 10,000 frames; over-the-top
    // and separatrix draw the separatrix (no period) and six incommensurate orbits.
    std::string why;
    const auto swing = figures::drawn_periods(figures::panels_of(figures::find("swing")), why);
    ASSERT_EQ(swing.size(), 3u);
    const auto plan = figures::plan_animation(figures::find("swing"), {});
    EXPECT_FALSE(figures::common_loop_frames(swing, plan.step, figures::max_frames));
    EXPECT_EQ(plan.loop, figures::loop_mode::crossfade);
    EXPECT_FALSE(plan.seamless);
    // Three exact periods of the 1 m pendulum at 25 frames per second, then half a second of fade.
    EXPECT_EQ(plan.motion_frames, static_cast<int>(std::ceil(3 * swing[0] / plan.step - 1e-9)));
    EXPECT_EQ(plan.frames - plan.motion_frames, 13);
    EXPECT_TRUE(figures::drawn_periods(figures::panels_of(figures::find("over-the-top")), why).empty());
    EXPECT_NE(why.find("separatrix"), std::string::npos) << why;
}

TEST(Loops, OneAmplitudeLoopsOnItsOwnPeriod) {
    // Released at 170 degrees, the exact pendulum alone: 4.894 s for 1 m, 123 frames at 25
    // fps (the 123rd frame's end, 4.92 s, is within a frame after the period's).
    const auto e = entry_of("[pendulum]\nlength_m = 1.0\n[animation]\n[[panel]]\nplot = \"pendulum\"\n"
                            "theta0 = \"170deg\"\nmethods = [\"exact\"]\ntrail = 0.3\n",
                            "one");
    const auto plan = figures::plan_animation(e, {});
    EXPECT_TRUE(plan.note.empty()) << plan.note;
    EXPECT_EQ(plan.motion_frames, 123);
    EXPECT_DOUBLE_EQ(plan.history, 123 * plan.step);
    expect_seamless(e, plan);
}

TEST(Loops, TwoAmplitudesLoopOnTheirCommonMultiple) {
    // plot pendulum --theta0 10deg,170deg --methods exact as a spec: the periods 2.0102 s and
    // 4.8944 s (mpmath: tests/data/loops_reference.py, loops_reference.csv) meet within a frame first after 2815 frames.
    const auto e = entry_of("[animation]\n[[panel]]\nplot = \"pendulum\"\n"
                            "theta0 = [\"10deg\", \"170deg\"]\nmethods = [\"exact\"]\n",
                            "two");
    const auto plan = figures::plan_animation(e, {});
    EXPECT_EQ(plan.motion_frames, 2815);
    expect_seamless(e, plan);
    std::string why;
    const auto periods = figures::drawn_periods(figures::panels_of(e), why);
    ASSERT_EQ(periods.size(), 2u);
    const double seconds = 1 / std::sqrt(9.80665);
    EXPECT_NEAR(periods[0] * seconds, 2.01023589, 1e-8);
    EXPECT_NEAR(periods[1] * seconds, 4.89436003, 1e-8);
    // One frame fewer does not fit: 2815 is the smallest.
    EXPECT_FALSE(figures::loop_fits(periods, plan.step, 2814));
    EXPECT_TRUE(figures::loop_fits(periods, plan.step, 2815));
}

TEST(Loops, LoopFitsAtItsBoundaries) {
    // A period of 10 steps: 10 frames end it exactly, 11 within one step after; 9 and 12 do not.
    const std::vector<double> t{1.0};
    EXPECT_FALSE(figures::loop_fits(t, 0.1, 9));
    EXPECT_TRUE(figures::loop_fits(t, 0.1, 10));
    EXPECT_TRUE(figures::loop_fits(t, 0.1, 11));
    EXPECT_FALSE(figures::loop_fits(t, 0.1, 12));
    EXPECT_EQ(figures::common_loop_frames(t, 0.1, 10).value_or(-1), 10);
    EXPECT_FALSE(figures::common_loop_frames(t, 0.1, 9));
    EXPECT_EQ(figures::common_loop_frames({1.0, 1.5}, 0.1, 100).value_or(-1), 30);
}

TEST(Loops, ExplicitLengthIsKeptAndTheModeSaysWhatHappensAtTheSeam) {
    const std::string head = "[pendulum]\nlength_m = 1.0\n[animation]\nperiods = 3\n";
    const std::string panel = "[[panel]]\nplot = \"pendulum\"\ntheta0 = \"170deg\"\nmethods = [\"exact\", \"harmonic\"]\n";
    // No loop given: it cannot be seamless, so it cross-fades and says so.
    auto plan = figures::plan_animation(entry_of(head + panel, "x"), {});
    EXPECT_EQ(plan.loop, figures::loop_mode::crossfade);
    EXPECT_NE(plan.note.find("cannot loop without a jump"), std::string::npos) << plan.note;
    EXPECT_NE(plan.note.find("it ends on a cross-fade"), std::string::npos) << plan.note;
    // loop = "periods" asked for: the length is kept and the note says it jumps.
    plan = figures::plan_animation(entry_of(head + "loop = \"periods\"\n" + panel, "x"), {});
    EXPECT_EQ(plan.loop, figures::loop_mode::periods);
    EXPECT_EQ(plan.frames, plan.motion_frames);
    EXPECT_NE(plan.note.find("jumps back to its start"), std::string::npos) << plan.note;
    // loop = "hold": a second of the last frame, no note.
    plan = figures::plan_animation(entry_of(head + "loop = \"hold\"\n" + panel, "x"), {});
    EXPECT_EQ(plan.loop, figures::loop_mode::hold);
    EXPECT_TRUE(plan.note.empty());
    EXPECT_EQ(plan.frames - plan.motion_frames, 25);
    EXPECT_EQ(plan.time(plan.frames - 1), plan.time(plan.motion_frames - 1));
    EXPECT_EQ(plan.fade_in(plan.frames - 1), 0.0);
    // Three exact periods of the exact pendulum alone are seamless.
    plan = figures::plan_animation(
        entry_of(head + "[[panel]]\nplot = \"pendulum\"\ntheta0 = \"170deg\"\nmethods = [\"exact\"]\n", "x"), {});
    EXPECT_TRUE(plan.seamless);
    EXPECT_TRUE(plan.note.empty());
}

TEST(Loops, LoopKeyIsOneOfItsRows) {
    for (const auto& row : figures::loop_rows) {
        const auto spec = figures::parse_spec("[animation]\nloop = \"" + std::string(row.name) +
                                                  "\"\n[[panel]]\nplot = \"pendulum\"\ntheta0 = \"1\"\n"
                                                  "methods = [\"exact\"]\n",
                                              "ok.toml");
        ASSERT_TRUE(spec.animation->loop);
        EXPECT_EQ(*spec.animation->loop, row.mode);
    }
    try {
        (void)figures::parse_spec("[animation]\nloop = \"crossfad\"\n[[panel]]\nplot = \"pendulum\"\ntheta0 = \"1\"\n"
                                  "methods = [\"exact\"]\n",
                                  "bad.toml");
        FAIL() << "loop = \"crossfad\" was taken";
    } catch (const figures::spec_error& err) {
        EXPECT_NE(std::string(err.what()).find("'loop' = \"crossfad\" is not one of periods, crossfade, hold; "
                                               "did you mean crossfade?"),
                  std::string::npos)
            << err.what();
    }
}

TEST(Loops, TooManyFramesWithTheSeamIsRefused) {
    // 10,000 frames of motion are allowed; a cross-fade's 13 more are not.
    const std::string panel = "[[panel]]\nplot = \"pendulum\"\ntheta0 = \"1\"\nmethods = [\"exact\"]\n";
    const auto plan = figures::plan_animation(
        entry_of("[pendulum]\nlength_m = 1.0\n[animation]\nduration_s = 400\nloop = \"periods\"\n" + panel, "x"), {});
    EXPECT_EQ(plan.frames, 10000);
    try {
        (void)figures::plan_animation(
            entry_of("[pendulum]\nlength_m = 1.0\n[animation]\nduration_s = 400\nloop = \"crossfade\"\n" + panel, "x"), {});
        FAIL() << "10,013 frames were planned";
    } catch (const figures::bad_input& err) {
        EXPECT_EQ(std::string(err.what()),
                  "animation 'x' would have 10013 frames with its loop = \"crossfade\"; at most 10000 (lower fps, "
                  "periods or duration_s, or raise speed)");
    }
}

/// The delays of a GIF's frames, in hundredths of a second, read back with giflib.
std::vector<int> gif_delays(const fs::path& file) {
    int error = 0;
    GifFileType* gif = DGifOpenFileName(file.c_str(), &error);
    std::vector<int> out;
    if (!gif) return out;
    if (DGifSlurp(gif) == GIF_OK) {
        for (int i = 0; i < gif->ImageCount; ++i) {
            GraphicsControlBlock gcb;
            out.push_back(DGifSavedExtensionToGCB(gif, i, &gcb) == GIF_OK ? gcb.DelayTime : -1);
        }
    }
    DGifCloseFile(gif, &error);
    return out;
}

TEST(Loops, GifRatesPlayEvenly) {
    EXPECT_EQ(plot::gif_playback_rate(25), 25);
    EXPECT_DOUBLE_EQ(plot::gif_playback_rate(30), 100.0 / 3);
    EXPECT_EQ(plot::gif_playback_rate(50), 50);
    EXPECT_EQ(plot::gif_playback_rate(20), 20);
    EXPECT_DOUBLE_EQ(plot::gif_playback_rate(24), 100.0 / 4);
    EXPECT_EQ(plot::gif_playback_rate(1), 1);
    EXPECT_EQ(plot::rate_text(100.0 / 3), "33.33");
    EXPECT_EQ(plot::rate_text(25), "25");
    // The table's rows: a GIF plays at its rate, a video at the spec's.
    EXPECT_TRUE(plot::find_format("gif").playback_rate);
    EXPECT_FALSE(plot::find_format("mp4").playback_rate);
    EXPECT_FALSE(plot::find_format("webm").playback_rate);
}

TEST(Loops, GifDelaysReadBackAreEqual) {
    const auto dir = temp_dir("loops-gif");
    const std::string panel = "[[panel]]\nplot = \"pendulum\"\ntheta0 = \"170deg\"\nmethods = [\"exact\"]\n";
    std::ofstream(dir / "even.toml") << "[pendulum]\nlength_m = 1.0\n[animation]\nperiods = 0.2\n" << panel;
    std::ofstream(dir / "thirty.toml") << "[pendulum]\nlength_m = 1.0\n[animation]\nfps = 30\nperiods = 0.2\n" << panel;
    auto r = run_cli("render even.toml thirty.toml -f gif --dpi 10", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    // The default, 25 frames per second: every delay 4 hundredths.
    const auto even = gif_delays(dir / "even.gif");
    ASSERT_GT(even.size(), 10u);
    for (int d : even) EXPECT_EQ(d, 4);
    // 30 plays at 33.33 (3 hundredths each), and stderr says so.
    const auto thirty = gif_delays(dir / "thirty.gif");
    ASSERT_GT(thirty.size(), 10u);
    for (int d : thirty) EXPECT_EQ(d, 3);
    EXPECT_NE(r.err.find("thirty.gif: 30 frames per second would play unevenly (its frames' delays are whole "
                         "hundredths of a second); it plays at 33.33"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("even.gif: 25"), std::string::npos) << r.err;
    // A video keeps the spec's rate: no note for it.
    r = run_cli("render thirty.toml -f mp4 --dpi 10", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("plays at"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

TEST(Loops, PlotPendulumTwoAmplitudesAsGif) {
    // plot pendulum with two amplitudes: whole periods of both, seamless, every delay 4/100 s.
    const auto dir = temp_dir("loops-plot");
    const auto r = run_cli("plot pendulum --theta0 10deg,170deg --methods exact -f gif --dpi 10 --jobs 2", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("cannot loop"), std::string::npos) << r.err;
    const auto delays = gif_delays(dir / "pendulum.gif");
    EXPECT_EQ(delays.size(), 2815u);
    EXPECT_TRUE(std::all_of(delays.begin(), delays.end(), [](int d) { return d == 4; }));
    fs::remove_all(dir);
}

TEST(Loops, DefaultThatCannotBeSeamlessSaysSoOnStderr) {
    const auto dir = temp_dir("loops-note");
    std::ofstream(dir / "both.toml") << "[pendulum]\nlength_m = 1.0\n[animation]\n[[panel]]\nplot = \"pendulum\"\n"
                                        "theta0 = \"170deg\"\nmethods = [\"exact\", \"harmonic\", \"lowest\"]\n";
    const auto r = run_cli("render both.toml -f png --frames 1..1 --dpi 10", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("pendulum-figures: note: both.png: animation 'both' cannot loop without a jump: the drawn "
                         "motions' periods meet within a frame in no loop of up to 10000 frames; it ends on a "
                         "cross-fade"),
              std::string::npos)
        << r.err;
    fs::remove_all(dir);
}

TEST(Loops, HostileLoopValueIsRefusedWithItsText) {
    // Values reaching a terminal and a shell: refused with exit 2, nothing run or written; a
    // control character is named, not sent.
    const auto dir = temp_dir("loops-hostile");
    const std::string panel = "[[panel]]\nplot = \"pendulum\"\ntheta0 = \"1\"\nmethods = [\"exact\"]\n";
    std::ofstream(dir / "h.toml") << "[animation]\nloop = \"$(touch pwned)\"\n" << panel;
    std::ofstream(dir / "e.toml") << "[animation]\nloop = \"hold\\u001b[31m\"\n" << panel;
    auto r = run_cli("render h.toml -f gif --dpi 10", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("h.toml:2:8: 'loop' = \"$(touch pwned)\" is not one of periods, crossfade, hold"),
              std::string::npos)
        << r.err;
    r = run_cli("render e.toml -f gif --dpi 10", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("'loop' has the control character U+001B"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "an escape reached the terminal";
    EXPECT_FALSE(fs::exists(dir / "pwned"));
    EXPECT_FALSE(fs::exists(dir / "h.gif"));
    EXPECT_FALSE(fs::exists(dir / "e.gif"));
    fs::remove_all(dir);
}

TEST(Loops, OneLegendPerAnimation) {
    // over-the-top: the pendulum and the phase portrait draw the same three starts in the same
    // colours and lines; the legend shows each once, with the fuller label, and the rays.
    const auto& e = figures::find("over-the-top");
    figures::build_options o;
    o.animated = true;
    const auto plan = figures::plan_animation(e, o);
    const auto base = figures::build(e, o);
    std::vector<double> unfaded;
    for (const int i : {0, plan.motion_frames - 1, plan.frames - 1}) {
        const auto f = figures::planned_frame(e, o, plan, base, i);
        std::vector<std::string> first;
        std::vector<double> alphas;
        for (const auto& s : f.panels[0].data) {
            if (s.label.empty()) continue;
            first.push_back(s.label.markup);
            alphas.push_back(s.alpha);
        }
        EXPECT_EQ(first, (std::vector<std::string>{"turning points", "<i>E</i> = 1.6\u2009<i>mgL</i>, libration",
                                                   "<i>E</i> = 2\u2009<i>mgL</i>, separatrix",
                                                   "<i>E</i> = 2.6\u2009<i>mgL</i>, rotation",
                                                   "paths of the last 0.15 periods"}))
            << "frame " << i;
        // A cross-fade fades the drawing, not its legend: its glyphs as in the first frame.
        if (unfaded.empty()) unfaded = alphas;
        EXPECT_EQ(alphas, unfaded) << "frame " << i;
        for (const auto& s : f.panels[1].data) EXPECT_TRUE(s.label.empty()) << s.label.markup << " in (b), frame " << i;
    }
}

TEST(Loops, PlotsAgainstTimeStartTheirCursorAgain) {
    // A trajectory alone: its cursor runs along its range and starts again; the length stays
    // one period (no loop of 5000 frames in which the cursor leaves the plot), with no note.
    const auto e = entry_of("[animation]\n[[panel]]\nplot = \"trajectory\"\ntheta0 = \"170deg\"\n"
                            "methods = [\"exact\", \"harmonic\"]\n",
                            "t");
    std::string why;
    EXPECT_TRUE(figures::drawn_periods(figures::panels_of(e), why).empty());
    EXPECT_TRUE(why.empty()) << why;
    const auto plan = figures::plan_animation(e, {});
    EXPECT_EQ(plan.loop, figures::loop_mode::periods);
    EXPECT_TRUE(plan.note.empty()) << plan.note;
    EXPECT_EQ(plan.motion_frames, static_cast<int>(std::ceil(plan.reference_period / plan.step - 1e-9)));
    EXPECT_EQ(plan.frames, plan.motion_frames);
}

TEST(Loops, AnIterationsPeriodIsNotSolvedToPlan) {
    // Planning solves nothing: an iteration's period is its solution (order:200 near pi takes
    // minutes, which the render's cost check refuses first), so it counts as none known.
    const auto e = entry_of("[animation]\n[[panel]]\nplot = \"pendulum\"\ntheta0 = \"0.999pi\"\n"
                            "methods = [\"exact\", \"order:200\"]\n",
                            "it");
    std::string why;
    EXPECT_TRUE(figures::drawn_periods(figures::panels_of(e), why).empty());
    EXPECT_EQ(why, "the motion of order:200 has no period known before it is solved");
    const auto plan = figures::plan_animation(e, {});
    EXPECT_EQ(plan.loop, figures::loop_mode::crossfade);
    EXPECT_NE(plan.note.find(why), std::string::npos) << plan.note;
}

}  // namespace
