// SPDX-License-Identifier: GPL-3.0-or-later
// The preflight: render --check JOURNAL measures a figure as drawn (every text's size, every
// stroke's width, the figure's width, series that merge in greyscale) against the journal's
// rules; the journal style files keep to them; each rule at its boundary.
#include "figures/catalog.hpp"
#include "figures/themes.hpp"
#include "plot/preflight.hpp"
#include "plot/render.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace test_support;
namespace fs = std::filesystem;

namespace {

/// The journal style files, committed beside the built-in themes.
const fs::path journal_dir = fs::path(PENDULUM_TEST_DATA) / ".." / ".." / "src" / "figures" / "journals";

/// The reader of a PDF's text sizes, committed beside the tests.
const std::string size_reader = std::string(PENDULUM_TEST_DATA) + "/../pdf_text_sizes.py";

/// Writes text to a file.
void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

/// How many times `part` occurs in `text`.
std::size_t count(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

/// The paper theme with `sets` on top, minimums lifted so that any size can be measured.
plot::theme paper_with(std::vector<std::string> sets) {
    sets.insert(sets.begin(), {"min_text_pt=0", "min_script_pt=0", "min_line_pt=0"});
    return figures::load_theme("paper", sets);
}

/// A one-panel figure of two lines, labelled without scripts: its texts are the theme's
/// sizes and its strokes the frame's and the lines' widths.
plot::figure two_lines() {
    plot::figure fig;
    plot::panel p;
    p.x.label = "time";
    p.y.label = "angle";
    p.data.push_back(plot::series{.label = "one", .x = {0, 1, 2, 3}, .y = {0, 1, 0, 1}});
    p.data.push_back(plot::series{.label = "two", .x = {0, 1, 2, 3}, .y = {1, 0, 1, 0}, .line = plot::line_style::dashed});
    fig.panels.push_back(std::move(p));
    return fig;
}

/// The problems of a figure under a journal check such as "aps" or "aps:1".
std::vector<std::string> problems(const plot::figure& fig, const plot::theme& th, const std::string& journal) {
    return plot::preflight_problems(plot::measure_figure(fig, th), plot::find_journal(journal));
}

/// All problems in one string, for messages and searches.
std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

}  // namespace

// Every built-in still figure in the paper theme keeps to APS's rules, measured; nothing is written.
TEST(CheckAps, EveryBuiltinInPaperPasses) {
    const fs::path dir = temp_dir("preflight-all");
    const run_result r = run_cli("render --all --check aps --theme paper", dir);
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_GE(count(r.out, ": keeps to aps's rules ("), 13u) << r.out;
    EXPECT_EQ(r.err, "");
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

// In every theme, no two series of a built-in figure merge in greyscale print (slides figures
// are wider than a journal's column, which is the only other thing --check may say of them).
TEST(CheckAps, NoBuiltinMergesInGreyscaleInAnyTheme) {
    for (const char* theme : {"paper", "slides", "slides-dark"}) {
        const fs::path dir = temp_dir("preflight-grey");
        const run_result r = run_cli(std::string("render --all --check aps --theme ") + theme, dir);
        EXPECT_EQ(r.out.find("greyscale"), std::string::npos) << theme << ":\n" << r.out;
        EXPECT_TRUE(files_in(dir).empty());
        fs::remove_all(dir);
    }
}

// A deliberately bad spec: 7-pt ticks, 0.3-pt lines and a 10-cm width, each its own message
// naming the measured value, the rule and the key to change; exit status 1; nothing written.
TEST(CheckAps, BadSpecEachItsOwnMessage) {
    const fs::path dir = temp_dir("preflight-bad");
    write(dir / "bad.toml",
          "min_text_pt = 0\nmin_script_pt = 0\nmin_line_pt = 0\ntick_font_pt = 7\nline_width_pt = 0.3\n"
          "figure_width_cm = 10\n");
    write(dir / "bad-figure.toml", "[figure]\nstyle = \"bad.toml\"\n\n[[panel]]\nplot = \"coefficient\"\n"
                                   "harmonic = 1\nmethods = [\"exact\", \"lowest\"]\n");
    const run_result r = run_cli("render bad-figure.toml --check aps:1", dir);
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("bad-figure: the figure is 10 cm wide, wider than aps's one column (8.6 cm): set "
                         "figure_width_cm = 8.6"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("set at 7 pt, below aps's smallest lettering (8 pt): raise tick_font_pt to 8 pt or more"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find(" pt wide, thinner than aps's thinnest line (0.5 pt): set min_line_pt = 0.5"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("lines 0.3 pt wide"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("1 of 1 figure breaks aps's rules for figures"), std::string::npos) << r.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"bad.toml", "bad-figure.toml"}));
    // Without :1 a 10-cm figure is a two-column figure: the width is not a problem, the rest are.
    const run_result either = run_cli("render bad-figure.toml --check aps", dir);
    EXPECT_EQ(either.status, 1);
    EXPECT_EQ(either.out.find("cm wide"), std::string::npos) << either.out;
    EXPECT_NE(either.out.find("set at 7 pt"), std::string::npos) << either.out;
    fs::remove_all(dir);
}

// Lettering: 8 pt accepted, 7.99 refused, for each text size key.
TEST(CheckBoundary, EightPointLettering) {
    for (const char* key : {"tick_font_pt", "label_font_pt", "legend_font_pt"}) {
        const std::string k = key;
        EXPECT_EQ(joined(problems(two_lines(), paper_with({"tick_font_pt=9", "label_font_pt=9", "legend_font_pt=9",
                                                          k + "=8"}),
                                  "aps")),
                  "")
            << key;
        const std::string refused = joined(problems(
            two_lines(), paper_with({"tick_font_pt=9", "label_font_pt=9", "legend_font_pt=9", k + "=7.99"}), "aps"));
        EXPECT_NE(refused.find("set at 7.99 pt, below aps's smallest lettering (8 pt): raise " + k), std::string::npos)
            << key << ": " << refused;
        EXPECT_EQ(count(refused, "\n"), 1u) << refused;  // one message for every text of that size
    }
}

// Scripts: a subscript of a 8.58-pt label is 6.006 pt, accepted; of a 8.57-pt label 5.999, refused.
TEST(CheckBoundary, SixPointScripts) {
    plot::figure fig = two_lines();
    fig.panels[0].y.label = "<i>T</i><sub>0</sub>";
    EXPECT_EQ(joined(problems(fig, paper_with({"label_font_pt=8.58"}), "aps")), "");
    const std::string refused = joined(problems(fig, paper_with({"label_font_pt=8.57"}), "aps"));
    EXPECT_NE(refused.find("script \"0\" (in \"T0\") set at 5.999 pt, below aps's smallest superscripts and "
                           "subscripts (6 pt): raise label_font_pt"),
              std::string::npos)
        << refused;
}

// Lines: 0.5 pt accepted, 0.49 refused, as the series' lines and as the frame.
TEST(CheckBoundary, HalfPointLines) {
    EXPECT_EQ(joined(problems(two_lines(), paper_with({"line_width_pt=0.5"}), "aps")), "");
    const std::string lines = joined(problems(two_lines(), paper_with({"line_width_pt=0.49"}), "aps"));
    EXPECT_NE(lines.find("lines 0.49 pt wide, thinner than aps's thinnest line (0.5 pt)"), std::string::npos) << lines;
    const std::string frame = joined(problems(two_lines(), paper_with({"frame_width_pt=0.49"}), "aps"));
    EXPECT_NE(frame.find("0.49 pt wide, thinner than aps's thinnest line (0.5 pt)"), std::string::npos) << frame;
    // Open markers' outlines are 0.75 of the line: measured as drawn, not as set.
    plot::figure marked = two_lines();
    marked.panels[0].data[0].marker = plot::marker_style::open_circle;
    const std::string outlines = joined(problems(marked, paper_with({"line_width_pt=0.6"}), "aps"));
    EXPECT_NE(outlines.find("0.45 pt wide, thinner"), std::string::npos) << outlines;
    // With the paper theme's min_line_pt = 0.5, every stroke is drawn at least that wide: the
    // outlines, a 0.3-pt frame, thin lines.
    const plot::theme floored = figures::load_theme("paper", {"line_width_pt=0.6", "frame_width_pt=0.3"});
    EXPECT_EQ(floored.min_line_pt, 0.5);
    EXPECT_EQ(joined(problems(marked, floored, "aps")), "");
    const plot::figure_measure m = plot::measure_figure(marked, floored);
    EXPECT_TRUE(std::all_of(m.strokes.begin(), m.strokes.end(), [](const auto& s) { return s.width_pt >= 0.5; }));
    EXPECT_TRUE(std::any_of(m.strokes.begin(), m.strokes.end(), [](const auto& s) { return s.width_pt == 0.6; }));
}

// Width: 8.6 cm accepted and 8.61 refused for one column; 17.8 accepted and 17.81 refused for
// two; without :1 or :2 a figure is one column if it fits, else two.
TEST(CheckBoundary, ColumnWidths) {
    const auto width = [](const char* cm, const char* journal) {
        return joined(problems(two_lines(), paper_with({std::string("figure_width_cm=") + cm}), journal));
    };
    EXPECT_EQ(width("8.6", "aps:1"), "");
    EXPECT_NE(width("8.61", "aps:1").find("the figure is 8.61 cm wide, wider than aps's one column (8.6 cm)"),
              std::string::npos);
    EXPECT_EQ(width("8.61", "aps"), "");
    EXPECT_EQ(width("17.8", "aps:2"), "");
    EXPECT_EQ(width("17.8", "aps"), "");
    EXPECT_NE(width("17.81", "aps").find("the figure is 17.81 cm wide, wider than aps's two columns (17.8 cm)"),
              std::string::npos);
    EXPECT_NE(width("17.81", "aps:2").find("wider than aps's two columns"), std::string::npos);
    // AIP's one column is 8.5 cm, two 17 cm.
    EXPECT_EQ(width("8.5", "aip:1"), "");
    EXPECT_NE(width("8.51", "aip:1").find("wider than aip's one column (8.5 cm)"), std::string::npos);
    EXPECT_NE(width("17.01", "aip").find("wider than aip's two columns (17 cm)"), std::string::npos);
}

// Greyscale: two labelled series of one panel with the same dash and marker merge when their
// greys differ by less than 0.15; by 0.15 they do not, nor with another dash.
TEST(CheckBoundary, GreysThatMerge) {
    const auto with_greys = [](double a, double b, plot::line_style second) {
        plot::figure fig = two_lines();
        fig.panels[0].data[0].rgb_color = plot::rgb{a, a, a};
        fig.panels[0].data[1].rgb_color = plot::rgb{b, b, b};
        fig.panels[0].data[1].line = second;
        return joined(problems(fig, paper_with({}), "aps"));
    };
    EXPECT_EQ(with_greys(0.2, 0.35, plot::line_style::solid), "");
    const std::string merged = with_greys(0.2, 0.349, plot::line_style::solid);
    EXPECT_NE(merged.find("\"one\" and \"two\" have the same dash and marker and greys 0.149 apart (less than 0.15"),
              std::string::npos)
        << merged;
    EXPECT_EQ(with_greys(0.2, 0.2, plot::line_style::dashed), "");
    // One colour: not told apart by colour, so greyscale changes nothing.
    EXPECT_EQ(with_greys(0.2, 0.2, plot::line_style::solid), "");
    // Colours that differ in hue and not in grey: red and a green of the same luma.
    plot::figure fig = two_lines();
    fig.panels[0].data[1].line = plot::line_style::solid;
    fig.panels[0].data[0].rgb_color = plot::rgb{1, 0, 0};
    fig.panels[0].data[1].rgb_color = plot::rgb{0, 0.299 / 0.587, 0};
    EXPECT_NE(joined(problems(fig, paper_with({}), "aps")).find("merge in greyscale"), std::string::npos);
    EXPECT_NEAR(plot::grey_of({1, 1, 1}), 1.0, 1e-12);
}

// The panel a problem is in is named by its label.
TEST(CheckBoundary, ProblemsNameThePanel) {
    plot::figure fig = two_lines();
    fig.cols = 2;
    fig.panels.push_back(fig.panels[0]);
    fig.panels[0].label = "(a)";
    fig.panels[1].label = "(b)";
    fig.panels[1].data[1].line = plot::line_style::solid;
    fig.panels[1].data[0].rgb_color = plot::rgb{0.3, 0.3, 0.3};
    fig.panels[1].data[1].rgb_color = plot::rgb{0.35, 0.35, 0.35};
    const std::string out = joined(problems(fig, paper_with({}), "aps"));
    EXPECT_NE(out.find("(b): \"one\" and \"two\" have the same dash and marker"), std::string::npos) << out;
    EXPECT_EQ(out.find("(a):"), std::string::npos) << out;
}

// An unknown journal, or a column other than 1 or 2, is exit 2 with the known journals named
// from the one table; a hostile value is not echoed raw to the terminal.
TEST(CheckOption, UnknownJournal) {
    const run_result r = run_cli("render c1-lowest --check nature");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--check 'nature': unknown journal; journals: aps, aip, ajp"), std::string::npos) << r.err;
    const run_result column = run_cli("render c1-lowest --check aps:3");
    EXPECT_EQ(column.status, 2);
    EXPECT_NE(column.err.find(":1 (one column) or :2 (two columns)"), std::string::npos) << column.err;
    const run_result hostile = run_cli("render c1-lowest --check \"$(printf 'aps\\033[31m')\"");
    EXPECT_EQ(hostile.status, 2);
    EXPECT_EQ(hostile.err.find('\033'), std::string::npos) << hostile.err;
    EXPECT_EQ(plot::journal_names(), "aps, aip, ajp");
}

// --check writes nothing: it refuses the options that name files, and animations.
TEST(CheckOption, RefusesWhatWritesFiles) {
    const fs::path dir = temp_dir("preflight-options");
    for (const char* extra : {"-o -", "--depfile d.mk", "--paper-files"}) {
        const run_result r = run_cli(std::string("render c1-lowest --check aps ") + extra, dir);
        EXPECT_EQ(r.status, 2) << extra;
        EXPECT_NE(r.err.find("--check measures the figures and writes no file"), std::string::npos) << r.err;
    }
    const run_result moving = run_cli("render swing --check aps", dir);
    EXPECT_EQ(moving.status, 2);
    EXPECT_NE(moving.err.find("'swing' is an animation"), std::string::npos) << moving.err;
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

// The journal style files: each loads, sets the journal's one-column width and minimums as the
// table has them, and a one-panel figure drawn with it keeps to the journal's one-column rules.
TEST(JournalStyles, EachKeepsToItsJournal) {
    for (const auto& j : plot::journal_table()) {
        const fs::path file = journal_dir / (std::string(j.name) + ".toml");
        ASSERT_TRUE(fs::exists(file)) << file;
        const plot::theme th = figures::load_theme(file.string());
        EXPECT_DOUBLE_EQ(th.fixed_width_cm, j.column_cm) << j.name;
        EXPECT_EQ(th.min_text_pt, j.min_text_pt) << j.name;
        EXPECT_EQ(th.min_script_pt, j.min_script_pt) << j.name;
        for (const char* id : {"c1-lowest", "convergence", "phase-portrait", "spectrum"}) {
            const plot::figure fig = figures::build(figures::find(id), figures::sized_by({}, th));
            EXPECT_EQ(joined(problems(fig, th, std::string(j.name) + ":1")), "") << j.name << " " << id;
        }
    }
}

// The sizes measured are the PDF's own: every size pdf_text_sizes.py reads from the PDF's
// operators is one the preflight measured, and the other way round, for a figure with scripts.
TEST(CheckMeasure, TextSizesAsThePdfHasThem) {
    const fs::path dir = temp_dir("preflight-pdf");
    const run_result r = run_cli("render convergence -f pdf --theme paper -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const run_result read = run_command("/usr/bin/python3 '" + size_reader + "' '" + (dir / "convergence.pdf").string() + "'");
    ASSERT_EQ(read.status, 0) << read.err;
    std::set<long> pdf;
    std::istringstream in(read.out);
    double size = 0;
    std::string hex;
    while (in >> size >> hex) pdf.insert(std::lround(size * 100));
    const plot::theme th = figures::load_theme("paper");
    const plot::figure_measure m = plot::measure_figure(figures::build(figures::find("convergence"), figures::sized_by({}, th)), th);
    std::set<long> measured;
    bool scripts = false;
    for (const auto& t : m.texts) {
        measured.insert(std::lround(t.size_pt * 100));
        scripts = scripts || t.script;
    }
    EXPECT_TRUE(scripts);
    EXPECT_EQ(measured, pdf);
    fs::remove_all(dir);
}

// The stroke widths measured are the PDF's own: the widths of the PDF's stroking operators, read
// by pdf_line_widths.py, are those the preflight measured, for a figure with markers and lines.
TEST(CheckMeasure, LineWidthsAsThePdfHasThem) {
    const fs::path dir = temp_dir("preflight-pdf-lines");
    const run_result r = run_cli("render period-error -f pdf --theme paper -o '" + dir.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string reader = std::string(PENDULUM_TEST_DATA) + "/../pdf_line_widths.py";
    const run_result read = run_command("/usr/bin/python3 '" + reader + "' '" + (dir / "period-error.pdf").string() + "'");
    ASSERT_EQ(read.status, 0) << read.err;
    std::set<long> pdf;
    std::istringstream in(read.out);
    double width = 0;
    while (in >> width) pdf.insert(std::lround(width * 1000));
    const plot::theme th = figures::load_theme("paper");
    const plot::figure_measure m =
        plot::measure_figure(figures::build(figures::find("period-error"), figures::sized_by({}, th)), th);
    std::set<long> measured;
    for (const auto& s : m.strokes) measured.insert(std::lround(s.width_pt * 1000));
    EXPECT_GE(measured.size(), 2u);
    EXPECT_EQ(measured, pdf);
    fs::remove_all(dir);
}

// A figure between one column and two passes --check NAME as a two-column figure, with a note:
// included at its natural size it keeps to the rules; scaled to the column its text would not.
// At the column's width, and with :2 (the author said two columns), there is no note.
TEST(CheckAps, AFigureBetweenTheWidthsSaysWhatScalingToTheColumnWouldDo) {
    const fs::path dir = temp_dir("preflight-scaling");
    const run_result wide = run_cli("render fig1 --check aps --set figure_width_cm=12", dir);
    EXPECT_EQ(wide.status, 0) << wide.out << wide.err;
    // The smallest text, 8.6 pt (the paper theme's ticks), times 8.6/12: 6.16, shown rounded down.
    EXPECT_NE(wide.out.find("c1-lowest: note: include it at its natural size (width 12 cm): scaled to the 8.6-cm "
                            "column, its smallest text would be 6.1 pt, below 8\n"),
              std::string::npos)
        << wide.out;
    for (const char* quiet : {"render fig1 --check aps --set figure_width_cm=8.6",
                              "render fig1 --check aps:2 --set figure_width_cm=12"}) {
        const run_result r = run_cli(quiet, dir);
        EXPECT_EQ(r.status, 0) << quiet << ": " << r.out << r.err;
        EXPECT_EQ(r.out.find("note:"), std::string::npos) << quiet << ": " << r.out;
        EXPECT_NE(r.out.find("keeps to aps's rules"), std::string::npos) << quiet << ": " << r.out;
    }
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}
