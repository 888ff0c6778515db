// SPDX-License-Identifier: GPL-3.0-or-later
// The command line with figure specs, themes and the method table: show, render and data
// of spec files, plot, list, eval --method, trajectory --method NAME:N.
#include "process.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;

fs::path scratch(const std::string& name) { return test_support::temp_dir("specs-" + name); }
using test_support::files_in;

TEST(SpecCommands, ShownSpecRendersTheSameBytes) {
    const auto dir = scratch("show");
    const auto shown = run_cli("show fig2");
    ASSERT_EQ(shown.status, 0) << shown.err;
    EXPECT_NE(shown.out.find("plot = \"trajectory\""), std::string::npos);
    std::ofstream(dir / "x.toml") << shown.out;
    const auto a = run_cli("render x.toml -f png,pdf,svg --dpi 60", dir);
    ASSERT_EQ(a.status, 0) << a.err;
    const auto b = run_cli("render fig2 -f png,pdf,svg --dpi 60", dir);
    ASSERT_EQ(b.status, 0) << b.err;
    for (const char* ext : {".png", ".pdf", ".svg"}) {
        EXPECT_EQ(slurp(dir / (std::string("x") + ext)), slurp(dir / (std::string("trajectory-lowest") + ext))) << ext;
    }
    // data of the spec file is the figure's data.
    EXPECT_EQ(run_cli("data x.toml", dir).out, run_cli("data fig2").out);
    fs::remove_all(dir);
}

TEST(SpecCommands, ATeachersSpec) {
    const auto dir = scratch("teacher");
    std::ofstream(dir / "swing.toml") << "[figure]\ntitle = \"Large swings\"\n[pendulum]\nlength_m = 0.5\n"
                                         "[[panel]]\nplot = \"trajectory\"\ntheta0 = \"170deg\"\n"
                                         "methods = [\"exact\", \"harmonic\", \"order:6\"]\ntime = \"t/s\"\nrange = [0, 3]\n";
    const auto r = run_cli("render swing.toml --theme slides -f png --dpi 30", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "swing.png"));
    const auto data = run_cli("data swing.toml", dir);
    ASSERT_EQ(data.status, 0) << data.err;
    EXPECT_NE(data.out.find("\na,order 6,"), std::string::npos);
    EXPECT_NE(data.out.find("\na,exact,3,"), std::string::npos);  // to 3 s
    fs::remove_all(dir);
}

TEST(SpecCommands, BadSpecIsExit2WithEveryProblemAndNoFile) {
    const auto dir = scratch("bad");
    std::ofstream(dir / "bad.toml") << "[[panel]]\nplot = \"trajectory\"\ntheta0 = \"170deg\"\n"
                                       "metods = [\"exact\"]\n";
    const auto r = run_cli("render bad.toml -f png", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("bad.toml:4:1: unknown key 'metods' in a trajectory panel; did you mean methods?"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("bad.toml:1:1: a trajectory panel needs methods"), std::string::npos) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"bad.toml"}));
    const auto missing = run_cli("render nothing.toml", dir);
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.err.find("cannot read spec file 'nothing.toml'"), std::string::npos) << missing.err;
    std::ofstream(dir / "period.toml") << "[[panel]]\nplot = \"convergence\"\ntheta0 = 1\n";
    const auto clash = run_cli("render period period.toml", dir);
    EXPECT_EQ(clash.status, 2);
    EXPECT_NE(clash.err.find("two different figures are named 'period'"), std::string::npos) << clash.err;
    fs::remove_all(dir);
}

TEST(SpecCommands, PlotMakesAOnePanelFigure) {
    const auto dir = scratch("plot");
    auto r = run_cli("plot trajectory --theta0 170deg --methods exact,harmonic,order:6 --range 0,3 -f png --dpi 30 "
                     "-o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("plot period --methods exact,kidd-fogg,agm:2 --y error-log --name formulas -f svg -o '" +
                dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"trajectory.png", "formulas.svg"}));
    r = run_cli("plot trajectory --theta0 1 --methods exact,kidd-fogg -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("method kidd-fogg gives a period only; plot 'trajectory' needs a law of motion"),
              std::string::npos)
        << r.err;
    r = run_cli("plot spectrm --theta0 1 -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("did you mean spectrum?"), std::string::npos) << r.err;
    EXPECT_EQ(files_in(dir).size(), 2u);
    fs::remove_all(dir);
}

TEST(SpecCommands, ListShowsEveryTable) {
    const auto r = run_cli("list");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* want : {"phase-portrait", "spectrum", "period-formulas", "period-error", "kidd-fogg", "agm:N",
                             "series:N (N = 1..20)", "order:N (N = 0..200)", "convergence", "keys: theta0 methods"}) {
        EXPECT_NE(r.out.find(want), std::string::npos) << want;
    }
    const auto theme = run_cli("show --theme slides-dark");
    EXPECT_NE(theme.out.find("base = \"slides\""), std::string::npos);
    EXPECT_EQ(run_cli("show --theme dark").status, 2);
    EXPECT_EQ(run_cli("show").status, 2);
}

TEST(SpecCommands, EvalMethodsAndTrajectoryNames) {
    const auto r = run_cli("eval --theta0 pi/2 --method kidd-fogg,agm:1 --method series:2");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto header = r.out.substr(0, r.out.find('\n'));
    EXPECT_NE(header.find(",period_kidd-fogg,period_agm:1,period_series:2"), std::string::npos) << header;
    // 1/sqrt(cos(pi/4)) and 2/(1 + cos(pi/4)).
    EXPECT_NE(r.out.find(",1.189207115002721,1.17157287525381"), std::string::npos) << r.out;
    const auto bad = run_cli("eval --theta0 1 --method kid-fogg");
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("--method 'kid-fogg': unknown method"), std::string::npos) << bad.err;
    EXPECT_EQ(run_cli("trajectory --theta0 1 --method order:6 --at 0.3").out,
              run_cli("trajectory --theta0 1 --method order --order 6 --at 0.3").out);
    const auto period_only = run_cli("trajectory --theta0 1 --method ganley --at 0.3");
    EXPECT_EQ(period_only.status, 2);
    EXPECT_NE(period_only.err.find("gives a period only"), std::string::npos) << period_only.err;
}

TEST(SpecCommands, ThemesFromTheCommandLine) {
    const auto dir = scratch("themes");
    std::ofstream(dir / "big.toml") << "base = \"slides\"\ntick_font_pt = 20\n";
    std::ofstream(dir / "big22.toml") << "base = \"slides\"\ntick_font_pt = 20\nlabel_font_pt = 22\n";
    const auto render = [&](const std::string& theme) {
        const auto r = run_cli("render fig1 --force --theme " + theme + " -f png --dpi 20", dir);
        EXPECT_EQ(r.status, 0) << theme << ": " << r.err;
        return slurp(dir / "c1-lowest.png");
    };
    const std::string plain = render("big.toml");
    ASSERT_FALSE(plain.empty());
    // The key changes the figure...
    const std::string set = render("big.toml --set label_font_pt=22");
    EXPECT_TRUE(set != plain) << "--set label_font_pt=22 changed nothing";
    // ... as the same key in the style file does, and nothing else: the same bytes.
    EXPECT_TRUE(set == render("big22.toml")) << "--set differs from the style file's label_font_pt = 22";
    EXPECT_TRUE(set == render("slides --set tick_font_pt=20 --set label_font_pt=22")) << "two --set differ";
    // The value the theme already has changes nothing.
    EXPECT_TRUE(render("big.toml --set label_font_pt=16") == plain) << "--set of the theme's own value changed the figure";
    const auto r = run_cli("render fig1 --theme big.toml --set label_fnt_pt=22 -f png --dpi 20", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("did you mean label_font_pt?"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

}  // namespace

namespace {

TEST(SpecCommands, ReadmeTablesAreMadeFromTheTables) {
    const std::string readme = slurp(fs::path(PENDULUM_TEST_DATA) / ".." / ".." / "README.md");
    const std::string begin = "<!-- BEGIN list --markdown -->\n";
    const std::string end = "<!-- END list --markdown -->";
    const auto a = readme.find(begin);
    const auto b = readme.find(end);
    ASSERT_NE(a, std::string::npos);
    ASSERT_NE(b, std::string::npos);
    const auto r = run_cli("list --markdown");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(readme.substr(a + begin.size(), b - a - begin.size()), r.out)
        << "run 'pendulum-figures list --markdown' and paste its output into the README";
}

}  // namespace

namespace {

TEST(SpecCommands, AMethodsOwnColour) {
    const auto dir = scratch("colour");
    std::ofstream(dir / "c.toml") << "[[panel]]\nplot = \"trajectory\"\ntheta0 = 1\n"
                                     "methods = [\"exact\", { method = \"harmonic\", color = \"#d55e00\" }]\n";
    const auto r = run_cli("render c.toml -f svg", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir / "c.svg");
    // The curve and its legend sample, in the paper theme whose palette is black only.
    EXPECT_NE(svg.find("rgb(83.529412%,36.862745%,0%)"), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace

namespace {

TEST(SpecCommands, EvalPeriodInSeconds) {
    const auto r = run_cli("eval --theta0 170deg --length 0.5 --format json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto at = r.out.find("\"T_s\": ");
    ASSERT_NE(at, std::string::npos) << r.out;
    // 2 pi sqrt(L/g) T/T0, with T/T0 at 170 degrees from the 80-digit references' formula.
    const double t_s = std::stod(r.out.substr(at + 7));
    EXPECT_NEAR(t_s, 2 * 3.141592653589793 * std::sqrt(0.5 / 9.80665) * 2.4393627196738827, 1e-14);
    EXPECT_EQ(run_cli("eval --theta0 1 --length 0").status, 2);
    EXPECT_EQ(run_cli("eval --theta0 1 --length 1 --g -9.8").status, 2);
    EXPECT_EQ(run_cli("eval --theta0 1").out.find("T_s"), std::string::npos);
}

}  // namespace
