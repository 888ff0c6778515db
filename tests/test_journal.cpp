// SPDX-License-Identifier: GPL-3.0-or-later
// Journal rules: the smallest text of every built-in figure in the paper theme, read back
// from the PDFs it writes; the minimum a theme sets, at its boundary.
#include "figures/catalog.hpp"
#include "figures/spec.hpp"
#include "figures/themes.hpp"
#include "plot/render.hpp"
#include "overlay_texts.hpp"
#include "process.hpp"
#include "still_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace test_support;
namespace fs = std::filesystem;

namespace {

/// The reader of a PDF's text sizes, committed beside this test.
const std::string size_reader = std::string(PENDULUM_TEST_DATA) + "/../pdf_text_sizes.py";

/// The size at final size of every text operator of a PDF, read by pdf_text_sizes.py with
/// Debian's python3 (font size times text matrix times transformation matrix).
std::vector<double> text_sizes(const fs::path& pdf) {
    const run_result r = run_command("/usr/bin/python3 '" + size_reader + "' '" + pdf.string() + "'");
    EXPECT_EQ(r.status, 0) << pdf << ": " << r.err;
    std::vector<double> sizes;
    std::istringstream in(r.out);
    double size = 0;
    std::string text;
    while (in >> size >> text) sizes.push_back(size);
    return sizes;
}

/// What is below the journals' rule in one PDF: text below 8 pt that is not a script
/// (0.7 of a text size of at least 8 pt in the same file), or any text below 6 pt.
std::string small_text(const fs::path& pdf) {
    const std::vector<double> sizes = text_sizes(pdf);
    if (sizes.empty()) return pdf.filename().string() + ": no text read";
    std::vector<double> text;
    for (double s : sizes) {
        if (s >= 8 - 1e-3) text.push_back(s);
    }
    std::string out;
    for (double s : sizes) {
        if (s >= 8 - 1e-3) continue;
        const bool script =
            s >= 6 - 1e-3 && std::any_of(text.begin(), text.end(), [&](double t) { return std::fabs(0.7 * t - s) < 0.01; });
        if (!script) out += " " + std::to_string(s);
    }
    return out.empty() ? "" : pdf.filename().string() + ":" + out;
}

/// The problem load_theme reports for the theme with `sets`, or "".
std::string theme_problem(const std::vector<std::string>& sets) {
    try {
        figures::load_theme("paper", sets);
    } catch (const figures::spec_error& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(JournalText, ThePaperThemeSaysItsMinimum) {
    const plot::theme t = figures::load_theme("paper");
    EXPECT_EQ(t.min_text_pt, 8);
    EXPECT_EQ(t.min_script_pt, 6);
    EXPECT_EQ(plot::text_size_problem(t), "");
    for (const auto& b : figures::builtin_themes()) {
        EXPECT_EQ(plot::text_size_problem(figures::load_theme(b.name)), "") << b.name;
    }
}

// Every built-in figure in the paper theme, as a PDF and as the paper's own panel files:
// no text below 8 pt, no superscript or subscript below 6 pt, read from the PDFs' operators.
TEST(JournalText, EveryPaperPdfKeepsToEightPoints) {
    const fs::path dir = temp_dir("journal-sizes");
    fs::create_directories(dir / "all");
    fs::create_directories(dir / "paper");
    const run_result all = run_cli("render --all -f pdf --theme paper -o '" + (dir / "all").string() + "'");
    ASSERT_EQ(all.status, 0) << all.err;
    const run_result paper =
        run_cli("render --all --paper-files -f pdf --theme paper -o '" + (dir / "paper").string() + "'");
    ASSERT_EQ(paper.status, 0) << paper.err;
    int files = 0;
    for (const char* sub : {"all", "paper"}) {
        for (const auto& name : files_in(dir / sub)) {
            if (!name.ends_with(".pdf")) continue;
            ++files;
            EXPECT_EQ(small_text(dir / sub / name), "");
        }
    }
    EXPECT_GE(files, 13);
    fs::remove_all(dir);
}

// The reader sees what a theme below the minimum would set: with the minimum lifted, 7-pt
// ticks are read as 7 pt (and their scripts as 4.9).
TEST(JournalText, TheReaderSeesSmallText) {
    const fs::path dir = temp_dir("journal-reader");
    const run_result r = run_cli("render convergence -f pdf --set min_text_pt=0 --set min_script_pt=0 "
                                 "--set tick_font_pt=7 -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<double> sizes = text_sizes(dir / "convergence.pdf");
    ASSERT_FALSE(sizes.empty());
    EXPECT_NEAR(*std::min_element(sizes.begin(), sizes.end()), 4.9, 0.01);
    EXPECT_NE(small_text(dir / "convergence.pdf"), "");
    fs::remove_all(dir);
}

// min_text_pt: a size equal to it is accepted, one below it refused with a message naming the
// key, its value and the minimum; every text size key the same way; a title of 0 is none.
TEST(JournalText, MinTextBoundary) {
    for (const char* key : {"tick_font_pt", "label_font_pt", "legend_font_pt", "title_font_pt"}) {
        const std::string k = key;
        EXPECT_EQ(theme_problem({"min_script_pt=0", k + "=8"}), "") << key;
        const std::string refused = theme_problem({"min_script_pt=0", k + "=7.99"});
        EXPECT_NE(refused.find(k + " = 7.99 is below the theme's min_text_pt = 8"), std::string::npos) << refused;
        EXPECT_NE(refused.find("raise " + k + " to 8 or more, or lower min_text_pt"), std::string::npos) << refused;
    }
    EXPECT_EQ(theme_problem({"title_font_pt=0"}), "");
    EXPECT_EQ(theme_problem({"min_text_pt=0", "min_script_pt=0", "tick_font_pt=5"}), "");
}

// min_script_pt: scripts are 0.7 of their text, so 8.58 pt is accepted (scripts 6.006 pt)
// and 8.57 refused (5.999 pt).
TEST(JournalText, MinScriptBoundary) {
    EXPECT_EQ(theme_problem({"tick_font_pt=8.58"}), "");
    const std::string refused = theme_problem({"tick_font_pt=8.57"});
    EXPECT_NE(refused.find("tick_font_pt = 8.57 sets superscripts and subscripts at 5.999 pt, below the theme's "
                           "min_script_pt = 6: raise tick_font_pt to 8.58 or more (scripts are 0.7 of the text), "
                           "or lower min_script_pt"),
              std::string::npos)
        << refused;
}

// On the command line and in a style file: exit 2, one message, nothing written.
TEST(JournalText, SmallTextRefusedWithExit2) {
    const fs::path dir = temp_dir("journal-refused");
    const run_result set = run_cli("render fig1 -f pdf --set legend_font_pt=7 -o '" + dir.string() + "'");
    EXPECT_EQ(set.status, 2);
    EXPECT_NE(set.err.find("legend_font_pt = 7 is below the theme's min_text_pt = 8"), std::string::npos) << set.err;
    std::ofstream(dir / "small.toml") << "base = \"paper\"\ntick_font_pt = 7.5\n";
    const run_result file = run_cli("render fig1 -f pdf --theme small.toml -o .", dir);
    EXPECT_EQ(file.status, 2);
    EXPECT_NE(file.err.find("style file small.toml"), std::string::npos) << file.err;
    EXPECT_NE(file.err.find("tick_font_pt = 7.5 is below the theme's min_text_pt = 8"), std::string::npos) << file.err;
    EXPECT_EQ(files_in(dir), std::set<std::string>{"small.toml"});
    fs::remove_all(dir);
}

// The plot layer keeps to the rule too: a theme built in code below its minimum is refused.
TEST(JournalText, DrawFigureRefusesSmallText) {
    plot::theme th = figures::load_theme("paper");
    th.tick_font_pt = 7.5;
    EXPECT_NE(plot::text_size_problem(th).find("tick_font_pt = 7.5"), std::string::npos);
}


// Every built-in, whole and as the paper's panel files: the PDF (its texts as the overlay of
// the theme's own sizes records them, laid out exactly as the PDF) and the pdf_tex overlays
// of 10, 11 and 12 pt documents show the same texts: the same tick labels, legends and
// labels. Where a legend has no room, it goes from all of them, and stderr says so once.
TEST(JournalRoutes, PdfAndOverlaysAt10To12ShowTheSame) {
    const fs::path dir = temp_dir("journal-routes");
    const std::vector<std::pair<std::string, std::string>> routes = {{"pdf", "--tex-sizes absolute"},
                                                                     {"tex10", "--tex-font-size 10"},
                                                                     {"tex11", "--tex-font-size 11"},
                                                                     {"tex12", "--tex-font-size 12"}};
    std::map<std::string, std::string> errors;
    for (const char* set : {"", "--paper-files"}) {
        for (const auto& [name, options] : routes) {
            const fs::path out = dir / (std::string(set).empty() ? "all" : "paper") / name;
            fs::create_directories(out);
            const run_result r =
                run_cli("render --all -f pdf_tex " + std::string(set) + " " + options + " -o '" + out.string() + "'");
            ASSERT_EQ(r.status, 0) << name << " " << set << ": " << r.err;
            errors[out.string()] = r.err;
        }
    }
    int compared = 0;
    for (const char* set : {"all", "paper"}) {
        for (const auto& file : files_in(dir / set / "pdf")) {
            if (!file.ends_with(".pdf_tex")) continue;
            const auto pdf = overlay_texts(dir / set / "pdf" / file);
            for (const char* route : {"tex10", "tex11", "tex12"}) {
                ++compared;
                const std::string where = std::string(set) + "/" + route + "/" + file;
                const std::string difference = text_difference(pdf, overlay_texts(dir / set / route / file));
                EXPECT_EQ(difference, "") << where;
            }
        }
    }
    EXPECT_GE(compared, 3 * 13);
    // A warning is one line naming its file, and the same in every route.
    for (const auto& [out, err] : errors) {
        std::istringstream in(err);
        for (std::string line; std::getline(in, line);) {
            EXPECT_TRUE(line.starts_with("pendulum-figures: warning: ") && line.find(".pdf_tex: ") != std::string::npos)
                << out << ": " << line;
        }
    }
    fs::remove_all(dir);
}

// The reproduction: Fig. 2 as the paper's panel files at --tex-font-size 12 kept its legend
// in no file, silently. Now the PDF and the overlay agree on where it is.
TEST(JournalRoutes, Fig2PaperFilesKeepTheirLegendAt12) {
    const fs::path dir = temp_dir("journal-fig2");
    for (const char* options : {"--tex-sizes absolute", "--tex-font-size 12"}) {
        const fs::path out = dir / (std::string(options).find("12") != std::string::npos ? "tex12" : "pdf");
        fs::create_directories(out);
        const run_result r = run_cli("render fig2 --paper-files -f pdf_tex " + std::string(options) + " -o '" +
                                     out.string() + "'");
        ASSERT_EQ(r.status, 0) << r.err;
    }
    int with_legend_pdf = 0;
    int with_legend_tex = 0;
    for (const auto& file : files_in(dir / "pdf")) {
        if (!file.ends_with(".pdf_tex")) continue;
        with_legend_pdf += overlay_texts(dir / "pdf" / file).count("exact}}}%") > 0;
        with_legend_tex += overlay_texts(dir / "tex12" / file).count("exact}}}%") > 0;
    }
    EXPECT_EQ(with_legend_pdf, with_legend_tex);
    fs::remove_all(dir);
}

// regimes: the legend band above (a) moved (a) alone 6.4 mm (paper) and 11.6 mm (slides)
// below (b); every row's axes now stand level to 0.1 mm, in every theme.
TEST(JournalLayout, RegimesRowsLevel) {
    constexpr double mm = 72 / 25.4;
    const plot::figure fig = figures::build(figures::find("regimes"));
    for (const auto& b : figures::builtin_themes()) {
        const plot::theme th = figures::load_theme(b.name);
        const auto frames = plot::panel_frames(fig, th);
        ASSERT_EQ(frames.size(), 4u) << b.name;
        for (std::size_t row = 0; row < 2; ++row) {
            const auto& left = frames[2 * row];
            const auto& right = frames[2 * row + 1];
            EXPECT_NEAR(left.y, right.y, 0.1 * mm) << b.name << " row " << row;
            EXPECT_NEAR(left.y + left.h, right.y + right.h, 0.1 * mm) << b.name << " row " << row;
        }
    }
}

// phase-portrait: the separatrix is drawn over the orbits (after them), thinner than any of
// them and in a grey, so that the 0.99 pi orbit beside it cannot hide it.
TEST(JournalLayout, SeparatrixOverTheOrbits) {
    const plot::figure fig = figures::build(figures::find("phase-portrait"));
    ASSERT_FALSE(fig.panels.empty());
    const auto& data = fig.panels.front().data;
    std::size_t first_separatrix = data.size();
    for (std::size_t i = 0; i < data.size(); ++i) {
        if (data[i].label.markup == "separatrix") first_separatrix = std::min(first_separatrix, i);
    }
    ASSERT_LT(first_separatrix, data.size());
    int orbits = 0;
    for (std::size_t i = 0; i < data.size(); ++i) {
        const bool separatrix = i >= first_separatrix && data[i].rgb_color && data[first_separatrix].rgb_color &&
                                data[i].rgb_color->r == data[first_separatrix].rgb_color->r;
        if (separatrix || !data[i].curve) continue;
        ++orbits;
        EXPECT_LT(i, first_separatrix) << "orbit " << i << " drawn over the separatrix";
        EXPECT_GT(data[i].width_scale, data[first_separatrix].width_scale) << "orbit " << i;
    }
    EXPECT_GE(orbits, 5);
    EXPECT_EQ(data.size() - first_separatrix, 2u);  // its two halves, last
}

// Markers spaced by distance on the page: every built-in (still) figure in every theme, at a
// small (4.2 cm, the paper's narrowest) and a large panel width: no two of a method's
// markers in a panel closer than 1.5 diameters, their centres where draw_figure puts them.
TEST(JournalMarkers, NoTwoMarkersCloserThanOneAndAHalfDiameters) {
    int series_checked = 0;
    const sweep_counts counts = for_each_still_builtin({"panel_width_cm=4.2", "panel_width_cm=12"}, [&](const still_case& c) {
        const auto panels = plot::marker_centres(c.figure, c.theme);  // too small for its text: refused
        for (std::size_t i = 0; i < panels.size(); ++i) {
            for (std::size_t k = 0; k < panels[i].size(); ++k) {
                const auto& m = panels[i][k];
                if (!m.spaced || m.centres.size() < 2) continue;
                ++series_checked;
                double closest = std::numeric_limits<double>::infinity();
                for (std::size_t a = 0; a < m.centres.size(); ++a) {
                    for (std::size_t b = a + 1; b < m.centres.size(); ++b) {
                        closest = std::min(closest, std::hypot(m.centres[a].first - m.centres[b].first,
                                                               m.centres[a].second - m.centres[b].second));
                    }
                }
                EXPECT_GE(closest, 3 * m.radius - 1e-9) << c.where() << " panel " << i << " series " << k;
            }
        }
    });
    EXPECT_GE(series_checked, 30);
    EXPECT_LE(counts.refused, 10) << "most figures are drawn at the small size";  // of 78
}

// The reproductions: Fig. 5 had 23 circles 1.26 mm apart and 1.34 mm across on c5'' (a
// chain), regimes (c) 30 circles piled on the theta = pi plateau; now spaced, and fewer.
TEST(JournalMarkers, ChainsAndPilesThinned) {
    const plot::theme th = figures::load_theme("paper");
    for (const char* id : {"coefficients-second", "regimes"}) {
        const plot::figure fig = figures::build(figures::find(id), figures::sized_by({}, th));
        const auto panels = plot::marker_centres(fig, th);
        std::size_t drawn = 0;
        std::size_t points = 0;
        for (std::size_t i = 0; i < panels.size(); ++i) {
            for (std::size_t k = 0; k < panels[i].size(); ++k) {
                if (!panels[i][k].spaced) continue;
                drawn += panels[i][k].centres.size();
                points += fig.panels[i].data[k].x.size();
            }
        }
        EXPECT_LT(drawn, points) << id << ": no marker was left out";
        EXPECT_GT(drawn, 0u) << id;
    }
}
