// SPDX-License-Identifier: GPL-3.0-or-later
// Themes are style files: the built-in ones, a user's file on a base, --set, and bad files.
#include "figures/spec.hpp"
#include "figures/themes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using figures::load_theme;

std::string problems_of(const std::string& name, const std::vector<std::string>& sets = {}) {
    try {
        load_theme(name, sets);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "accepted";
}

fs::path write_file(const std::string& name, const std::string& text) {
    const auto path = fs::temp_directory_path() / ("pendulum-theme-" + std::to_string(::getpid()) + "-" + name);
    std::ofstream(path) << text;
    return path;
}

TEST(Themes, BuiltInThemes) {
    EXPECT_EQ(figures::theme_names(), "paper, slides, slides-dark");
    const auto paper = load_theme("paper");
    EXPECT_EQ(paper.name, "paper");
    EXPECT_EQ(paper.font_family, "CMU Serif, DejaVu Math TeX Gyre");
    EXPECT_EQ(paper.palette.size(), 1u);
    EXPECT_EQ(paper.fixed_width_cm, 0);
    EXPECT_EQ(paper.dpi, 300);
    ASSERT_EQ(paper.styles.count("exact"), 1u);
    EXPECT_EQ(paper.styles.at("exact").marker, plot::marker_style::open_circle);
    EXPECT_EQ(paper.styles.at("harmonic").line, plot::line_style::dotted);
    const auto slides = load_theme("slides");
    EXPECT_EQ(slides.tick_font_pt, 14);
    EXPECT_EQ(slides.palette.size(), 7u);
    EXPECT_DOUBLE_EQ(slides.palette[1].b, 0xb2 / 255.0);
    EXPECT_EQ(slides.fixed_width_cm, 25.4);
    // Keys a theme does not set come from the paper theme.
    EXPECT_EQ(slides.styles.at("polynomial").line, plot::line_style::dotted);
    const auto dark = load_theme("slides-dark");
    EXPECT_EQ(dark.tick_font_pt, 14);  // from its base, slides
    EXPECT_DOUBLE_EQ(dark.background.r, 0x1e / 255.0);
    EXPECT_DOUBLE_EQ(dark.foreground.g, 0xe8 / 255.0);
    EXPECT_DOUBLE_EQ(dark.palette[0].r, 1.0);
    for (const auto& t : figures::builtin_themes()) EXPECT_FALSE(t.description.empty()) << t.name;
}

TEST(Themes, AUsersStyleFileAndSets) {
    const auto path = write_file("journal.toml", "# 9 pt type in an 8.6 cm column\nbase = \"paper\"\n"
                                                 "tick_font_pt = 9\nlabel_font_pt = 9\npanel_width_cm = 8.6\n"
                                                 "[styles]\nlowest = { line = \"dashed\" }\n");
    const auto t = load_theme(path.string(), {"legend_font_pt=9.5", "font_family=DejaVu Serif", "palette=[\"#112233\"]"});
    EXPECT_EQ(t.name, "pendulum-theme-" + std::to_string(::getpid()) + "-journal");
    EXPECT_EQ(t.tick_font_pt, 9);
    EXPECT_EQ(t.panel_width_cm, 8.6);
    EXPECT_EQ(t.legend_font_pt, 9.5);
    EXPECT_EQ(t.font_family, "DejaVu Serif");
    EXPECT_DOUBLE_EQ(t.palette[0].r, 0x11 / 255.0);
    EXPECT_EQ(t.styles.at("lowest").line, plot::line_style::dashed);
    EXPECT_EQ(t.styles.at("exact").marker, plot::marker_style::open_circle);  // from paper
    fs::remove(path);
}

TEST(Themes, BadStyleFilesAndSets) {
    const auto path = write_file("bad.toml", "base = \"slide\"\n");
    EXPECT_NE(problems_of(path.string()).find("bad.toml:1:8: 'base' must be a built-in theme"), std::string::npos)
        << problems_of(path.string());
    std::ofstream(path) << "tick_font_pt = -1\ncolour = 2\nforeground = \"black\"\npalette = []\n"
                           "[styles]\nexact = { line = \"wavy\" }\n";
    const std::string got = problems_of(path.string());
    for (const char* want : {"bad.toml:1:16: 'tick_font_pt' = -1 is out of range",
                             "bad.toml:2:1: unknown key 'colour' in a style file",
                             "bad.toml:3:14: 'foreground' must be a colour \"#rrggbb\"",
                             "bad.toml:4:11: 'palette' must be a list of colours",
                             "'line' = \"wavy\" is not one of solid, dashed, dotted, dash-dot, dash-dot-dot, none"}) {
        EXPECT_NE(got.find(want), std::string::npos) << "missing: " << want << "\nin:\n" << got;
    }
    fs::remove(path);
    EXPECT_NE(problems_of("slide").find("did you mean slides?"), std::string::npos);
    EXPECT_NE(problems_of("missing.toml").find("cannot read style file 'missing.toml'"), std::string::npos);
    EXPECT_NE(problems_of("paper", {"tick_font_pt"}).find("must be KEY=VALUE"), std::string::npos);
    EXPECT_NE(problems_of("paper", {"tick_fnt_pt=3"}).find("did you mean tick_font_pt?"), std::string::npos);
    EXPECT_NE(problems_of("paper", {"dpi=1e9"}).find("'dpi' = 1e+09 is out of range; allowed from 10 to 2400"), std::string::npos);
}

}  // namespace
