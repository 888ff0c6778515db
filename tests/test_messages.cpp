// SPDX-License-Identifier: GPL-3.0-or-later
// Messages that name what is wrong: bad input is exit 2 before anything is written, and
// the message names the key or option, its value, and what is allowed.
#include "cli/table.hpp"
#include "plot/errors.hpp"
#include "plot/latex_overlay.hpp"
#include "plot/output.hpp"
#include "plot/ticks.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::temp_dir;

/// True if text holds part.
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Messages, UnknownFontFamilyIsBadInputBeforeAnyWork) {
    const auto dir = temp_dir("font");
    auto r = run_cli("render fig1 -f pdf,png --set font_family=Nonesuch -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(has(r.err, "font_family")) << r.err;
    EXPECT_TRUE(has(r.err, "'Nonesuch'")) << r.err;
    EXPECT_TRUE(has(r.err, "fc-list : family")) << r.err;
    EXPECT_FALSE(has(r.err, "fonts-cmu")) << r.err;  // not a CMU family
    EXPECT_TRUE(files_in(dir).empty());

    // In a style file, the first family is the one that must be there.
    std::ofstream(dir / "style.toml") << "font_family = \"Nonesuch, DejaVu Sans\"\n";
    r = run_cli("render fig1 -f pdf --theme style.toml -o out", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(has(r.err, "style.toml")) << r.err;
    EXPECT_TRUE(has(r.err, "'Nonesuch'")) << r.err;

    // The CMU families come from fonts-cmu.
    r = run_cli("render fig1 -f pdf --set 'font_family=CMU Nonesuch' -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(has(r.err, "fonts-cmu")) << r.err;
    EXPECT_EQ(files_in(dir), std::set<std::string>{"style.toml"});

    // Any family fontconfig finds is used.
    r = run_cli("render fig1 -f pdf --set 'font_family=DejaVu Sans' -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    fs::remove_all(dir);
}

TEST(Messages, TinyFiguresAreTooSmallNotTooLarge) {
    const auto dir = temp_dir("tiny");
    for (const std::string set : {"figure_width_cm=0.001", "figure_height_cm=0.01", "panel_width_cm=0.001"}) {
        const auto r = run_cli("render fig1 -f png,pdf --theme slides --set " + set + " -o '" + dir.string() + "'");
        EXPECT_EQ(r.status, 2) << set << ": " << r.err;
        EXPECT_TRUE(has(r.err, set.substr(0, set.find('=')))) << r.err;
        EXPECT_FALSE(has(r.err, "too large")) << r.err;
        EXPECT_FALSE(has(r.err, "--dpi")) << r.err;
    }
    const auto r = run_cli("render fig1 -f png --theme slides --set figure_width_cm=0.5 -o '" + dir.string() + "'");
    EXPECT_TRUE(has(r.err, "too small; the smallest allowed is 1")) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

/// check_raster_size's message for a fixed figure size in cm at dpi.
std::string raster_problem(double width_cm, double height_cm, double dpi) {
    plot::theme th;
    th.fixed_width_cm = width_cm;
    th.fixed_height_cm = height_cm;
    try {
        plot::check_raster_size(plot::figure{}, th, dpi);
    } catch (const plot::bad_input& e) {
        return e.what();
    }
    return "accepted";
}

TEST(Messages, RasterSizesSuggestOnlyDpisInRange) {
    // Too small: the least dpi that gives a pixel, within 10 to 2400.
    std::string m = raster_problem(0.01, 5, 100);
    EXPECT_TRUE(has(m, "too small")) << m;
    EXPECT_TRUE(has(m, "--dpi 127 is the least")) << m;
    m = raster_problem(0.0001, 5, 300);
    EXPECT_TRUE(has(m, "too small at any resolution")) << m;
    EXPECT_FALSE(has(m, "too large")) << m;
    // Too large: the most dpi that fits, never above 2400 nor below 10.
    m = raster_problem(100, 100, 2400);
    EXPECT_TRUE(has(m, "too large")) << m;
    EXPECT_TRUE(has(m, "--dpi 254 is the most")) << m;
    m = raster_problem(10000, 10000, 10);
    EXPECT_TRUE(has(m, "too large at any resolution")) << m;
    EXPECT_FALSE(has(m, "--dpi 2 ")) << m;
    EXPECT_EQ(raster_problem(25.4, 14.2875, 128), "accepted");
}

TEST(Messages, TimesThatOverflowAreRefused) {
    const auto dir = temp_dir("at");
    for (const char* at : {"1e308", "-1e308", "1e7"}) {
        const auto r = run_cli("render swing --at " + std::string(at) + " -f svg -o '" + dir.string() + "'");
        EXPECT_EQ(r.status, 2) << at << ": " << r.err;
        EXPECT_TRUE(has(r.err, "--at")) << r.err;
        EXPECT_TRUE(has(r.err, "at most 1e6")) << r.err;
        EXPECT_FALSE(has(r.err, "nan")) << r.err;
    }
    EXPECT_TRUE(files_in(dir).empty());
    // trajectory reduces any finite time modulo the period exactly: only what no double
    // holds is refused.
    for (const char* at : {"1e309", "0,-1e309", "inf"}) {
        const auto r = run_cli("trajectory --theta0 1 --method lowest --at '" + std::string(at) + "'");
        EXPECT_EQ(r.status, 2) << at << ": " << r.out << r.err;
        EXPECT_TRUE(has(r.err, "--at")) << r.err;
        EXPECT_FALSE(has(r.err, "nan")) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
    for (const char* at : {"1e308,-1e300,2e6", "1.7976931348623157e308"}) {
        const auto r = run_cli("trajectory --theta0 1 --method lowest --at '" + std::string(at) + "'");
        EXPECT_EQ(r.status, 0) << at << ": " << r.err;
        EXPECT_FALSE(has(r.out, "nan") || has(r.out, "inf")) << r.out;
    }
    const auto r = run_cli("plot trajectory --theta0 1 --methods exact --range 0,1e308 -f svg -o '" + dir.string() + "'");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(has(r.err, "range")) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
    fs::remove_all(dir);
}

TEST(Messages, NulInAFileLineIsShownEscaped) {
    const auto dir = temp_dir("nul");
    std::ofstream(dir / "amplitudes.txt", std::ios::binary) << std::string("1\0x\n", 4);
    const auto r = run_cli("eval --theta0 @amplitudes.txt", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(r.out.empty());
    EXPECT_EQ(r.err.find('\0'), std::string::npos);
    EXPECT_TRUE(has(r.err, "--theta0 '1\\x00x'")) << r.err;
    // The whole message, to its end, not cut at the NUL.
    EXPECT_TRUE(has(r.err, "has the control character U+0000 (text here is one line of printable characters)")) << r.err;
    fs::remove_all(dir);
}

/// A short animation at `fps` frames per second, as a spec file in dir.
fs::path animation_at(const fs::path& dir, const std::string& fps) {
    const auto path = dir / ("moving" + fps + ".toml");
    std::ofstream(path) << "[pendulum]\nlength_m = 1.0\n\n[animation]\nfps = " << fps
                        << "\nperiods = 0.1\n\n[[panel]]\nplot = \"pendulum\"\ntheta0 = \"170deg\"\n"
                           "methods = [\"exact\"]\n";
    return path;
}

TEST(Messages, GifFrameRatesItCannotPlayAreRefusedBeforeAnyFile) {
    const auto dir = temp_dir("fps");
    const auto out = dir / "out";
    fs::create_directories(out);
    for (const std::string fps : {"120", "60", "50.5"}) {
        const auto spec = animation_at(dir, fps);
        const auto r = run_cli("render '" + spec.string() + "' -f png,gif --dpi 20 -o '" + out.string() + "'");
        EXPECT_EQ(r.status, 2) << fps << ": " << r.err;
        EXPECT_TRUE(has(r.err, "fps = " + fps + ": a GIF plays 100/k frames per second")) << r.err;
        EXPECT_TRUE(has(r.err, "nearest: 50 or 33.33")) << r.err;
        EXPECT_TRUE(files_in(out).empty()) << fps;
    }
    // PNG frames play at any rate; a GIF at 50 fps, or at 30 with delays of 3, 3 and 4.
    auto r = run_cli("render '" + animation_at(dir, "120").string() + "' -f png --dpi 20 -o '" + out.string() + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    for (const std::string fps : {"50", "30"}) {
        r = run_cli("render '" + animation_at(dir, fps).string() + "' -f gif --dpi 20 -o '" + out.string() + "'");
        EXPECT_EQ(r.status, 0) << fps << ": " << r.err;
    }
    EXPECT_TRUE(fs::exists(out / "moving30.gif"));
    fs::remove_all(dir);
}

TEST(Messages, CsvTextThatLooksLikeAFormulaIsNeutralised) {
    const auto dir = temp_dir("csv");
    std::ofstream(dir / "labels.toml")
        << "[[panel]]\nplot = \"trajectory\"\ntheta0 = \"1\"\nmethods = ["
           "{ method = \"exact\", label = '=HYPERLINK(\"http://example.com\",\"x\")' }, "
           "{ method = \"lowest\", label = \"-1+2\" }, { method = \"harmonic\", label = \"@SUM(A1)\" }, "
           "{ method = \"first\", label = \"+x\" }]\n";
    const auto r = run_cli("data labels.toml", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(has(r.out, "\na,\"'=HYPERLINK(\"\"http://example.com\"\",\"\"x\"\")\",0,")) << r.out.substr(0, 300);
    EXPECT_TRUE(has(r.out, "\na,'-1+2,0,")) << r.out.substr(0, 300);
    EXPECT_TRUE(has(r.out, "\na,'@SUM(A1),0,"));
    EXPECT_TRUE(has(r.out, "\na,'+x,0,"));
    EXPECT_FALSE(has(r.out, ",=")) << r.out.substr(0, 300);
    // Numbers stay numbers, negative ones too.
    EXPECT_TRUE(has(r.out, ",-")) << r.out.substr(0, 300);
    fs::remove_all(dir);

    std::ostringstream out;
    pendulum::cli::table_writer w(out, {"name", "value"}, pendulum::cli::table_format::csv);
    w.record({std::string("=1+1"), -1.5});
    w.record({std::string("\tx"), 2.0});
    w.record({std::string("plain -"), 3.0});
    w.finish();
    EXPECT_EQ(out.str(), "name,value\n'=1+1,-1.5\n'\tx,2\nplain -,3\n");
}

TEST(Messages, YRangesTheTicksCannotLabelAreRefused) {
    const auto dir = temp_dir("yrange");
    const auto out = dir / "out";
    fs::create_directories(out);
    for (const std::string range : {"[-1.7e308, 1.7e308]", "[0, 5e-324]", "[0, 1e-301]", "[1, 1.0000000000001]",
                                    "[-2e300, 0]"}) {
        std::ofstream(dir / "y.toml") << "[[panel]]\nplot = \"trajectory\"\ntheta0 = \"1\"\nmethods = [\"exact\"]\n"
                                         "y_range = " << range << "\n";
        const auto r = run_cli("render y.toml -f svg -o out", dir);
        EXPECT_EQ(r.status, 2) << range << ": " << r.err;
        EXPECT_TRUE(has(r.err, "'y_range'")) << r.err;
        EXPECT_TRUE(has(r.err, "1e300")) << r.err;
        EXPECT_TRUE(files_in(out).empty()) << range;
    }
    fs::remove_all(dir);
}

TEST(Messages, EveryAcceptedYRangeHasTwoDistinctTickLabels) {
    // The limits of y_range: values within 1e300, a span of 1e-300 at least and of 1e-9 of
    // the largest magnitude.
    const std::pair<double, double> ranges[] = {
        {-1e300, 1e300}, {0, 1e-300}, {-1e-300, 0}, {1, 1 + 1e-9}, {-1 - 1e-9, -1}, {1e300 - 1e291, 1e300},
        {-1e300, -1e300 + 1e291}, {1e-290, 1e-290 + 1e-299}, {0.1, 0.1 + 1e-10}, {123456.789, 123456.789 + 1.3e-4}};
    for (const auto& [lo, hi] : ranges) {
        for (const bool expand : {true, false}) {
            for (const int n : {3, 6, 10}) {
                const plot::tick_set t = plot::linear_ticks(lo, hi, n, expand);
                const std::set<std::string> distinct(t.labels.begin(), t.labels.end());
                EXPECT_GE(distinct.size(), 2u) << lo << " " << hi << " " << expand << " " << n;
                EXPECT_EQ(distinct.size(), t.labels.size()) << lo << " " << hi;
            }
        }
    }
}

}  // namespace

namespace {

/// Every line of text starts with prefix.
bool every_line_starts_with(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(prefix, 0) != 0) return false;
    }
    return true;
}

TEST(Messages, ALineBreakInAStrangersFileNameStartsNoLineOfItsOwn) {
    const auto dir = temp_dir("forged-lines");
    // A spec whose name holds line breaks: the message names it, and every line of the
    // message is the program's, so no line begins with the forged CI command.
    const std::string name = "x\n::error file=a.c,line=1::forged\n.toml";
    std::ofstream(dir / name) << "[[panel]]\nplot = \"period\"\nmethods = [\"exact\"]\n";
    const auto r = run_cli("describe \"$(printf 'x\\n::error file=a.c,line=1::forged\\n.toml')\"", dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(has(r.err, "::error")) << r.err;
    EXPECT_TRUE(every_line_starts_with(r.err, "pendulum-figures: error: ")) << r.err;
    fs::remove_all(dir);
}

TEST(Messages, AnOverlaysDrawingNameLaTeXCannotTakeIsBadInput) {
    const auto dir = temp_dir("overlay-name");
    for (const std::string name : {"a%b", "a b", "a{b", "a#b", "a~b", "a\\\\b"}) {
        const auto r = run_cli("plot period --methods exact -f pdf_tex --name '" + name + "'", dir);
        EXPECT_EQ(r.status, 2) << name << ": " << r.err;
        // --name keeps to the rule of every figure's file name, which LaTeX can take as written.
        EXPECT_TRUE(has(r.err, "a file name here is letters, digits and . _ + -")) << r.err;
        EXPECT_TRUE(files_in(dir).empty()) << name;
    }
    const auto ok = run_cli("plot period --methods exact -f pdf_tex --name 'Fig.1_a+b-c'", dir);
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(files_in(dir), (std::set<std::string>{"Fig.1_a+b-c.pdf", "Fig.1_a+b-c.pdf_tex"}));
    fs::remove_all(dir);
}

TEST(Messages, EveryByteOfAnOverlaysDrawingNameIsRefusedOrPlain) {
    for (int b = 0; b < 256; ++b) {
        const std::string name = std::string("a") + static_cast<char>(b) + "b.pdf";
        const bool plain = (b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || b == '.' ||
                           b == '_' || b == '+' || b == '-';
        if (plain) {
            EXPECT_NO_THROW(plot::check_latex_file_name(name)) << "byte " << b;
        } else {
            EXPECT_THROW(plot::check_latex_file_name(name), plot::bad_input) << "byte " << b;
        }
    }
}

}  // namespace
