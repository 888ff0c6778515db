// SPDX-License-Identifier: GPL-3.0-or-later
// SVG for the web, and words in the files: <title> and <desc> from describe (and the PDF's
// Title and Subject), text as <text> elements, and the SVG's size in points, pixels or none.
#include "figures/catalog.hpp"
#include "figures/describe.hpp"
#include "figures/themes.hpp"
#include "plot/figure.hpp"
#include "plot/output.hpp"
#include "plot/theme.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <regex>
#include <string>
#include <vector>

namespace {

using test_support::run_command;
using test_support::temp_dir;

/// The root element's start tag.
std::string root_of(const std::string& svg) {
    const auto a = svg.find("<svg");
    return a == std::string::npos ? "" : svg.substr(a, svg.find('>', a) - a + 1);
}

/// Text matched as it is by a regular expression.
std::string quoted(const std::string& text) {
    static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
    return std::regex_replace(text, special, R"(\$&)");
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t pos = 0; (pos = text.find(what, pos)) != std::string::npos; pos += what.size()) ++n;
    return n;
}

TEST(SvgWords, EveryBuiltinFigureHasTitleAndDescAndThePdfItsSubject) {
    const plot::theme th = figures::load_theme("paper", {});
    const auto dir = temp_dir("words");
    for (const auto& e : figures::catalog()) {
        const plot::figure built = figures::build(e);
        const auto words = figures::describe(e, built);
        ASSERT_FALSE(words.text.empty()) << e.id;
        const std::string svg = plot::render(built, th, "svg", {});
        // First in the root element, escaped as XML.
        const std::string root = root_of(svg);
        const std::string first = "\n<title>" + plot::escape_markup(words.alt) + "</title>\n<desc>" +
                                  plot::escape_markup(words.text) + "</desc>";
        EXPECT_EQ(svg.find(first), svg.find(root) + root.size()) << e.id << ":\n" << svg.substr(0, 2000);
        EXPECT_EQ(count(svg, "<title>"), 1u) << e.id;
        EXPECT_EQ(count(svg, "<desc>"), 1u) << e.id;
        // The same bytes every time.
        EXPECT_EQ(plot::render(built, th, "svg", {}), svg) << e.id;
        const auto pdf = dir / (e.id + ".pdf");
        plot::save(built, th, pdf, {});
        const auto info = run_command("pdfinfo '" + pdf.string() + "'");
        ASSERT_EQ(info.status, 0) << info.err;
        const std::string paragraph = words.text.substr(0, words.text.find('\n'));
        EXPECT_TRUE(std::regex_search(info.out, std::regex("Title: +" + quoted(words.alt) + "\n"))) << e.id << ":\n" << info.out;
        EXPECT_TRUE(std::regex_search(info.out, std::regex("Subject: +" + quoted(paragraph)))) << e.id << ":\n" << info.out;
    }
    std::filesystem::remove_all(dir);
}

TEST(SvgWords, PaperFilesCarryTheirFiguresWords) {
    const auto dir = temp_dir("paper-words");
    std::filesystem::create_directories(dir / "out");
    const auto r = test_support::run_cli("render period --paper-files -f svg -o out", dir);
    ASSERT_EQ(r.status, 0) << r.err;
    std::size_t files = 0;
    for (const auto& f : std::filesystem::directory_iterator(dir / "out")) {
        const std::string svg = test_support::slurp(f.path());
        EXPECT_EQ(count(svg, "<title>"), 1u) << f.path();
        EXPECT_EQ(count(svg, "<desc>Panel "), 1u) << f.path();
        ++files;
    }
    EXPECT_GE(files, 2u);
    std::filesystem::remove_all(dir);
}

TEST(SvgText, LabelsAreTextElementsWithTheirScripts) {
    const plot::theme paths = figures::load_theme("paper", {});
    const plot::theme texts = figures::load_theme("paper", {"svg_text=text"});
    const auto& e = figures::find("period");
    const plot::figure built = figures::build(e);
    const std::string drawn = plot::render(built, paths, "svg", {});
    const std::string svg = plot::render(built, texts, "svg", {});
    // Glyphs as outlines in one, none in the other; the frame and curves alike.
    EXPECT_GT(count(drawn, "<symbol"), 0u);
    EXPECT_EQ(count(drawn, "<text"), 0u);
    EXPECT_EQ(count(svg, "<symbol"), 0u);
    EXPECT_GT(count(svg, "<text"), 10u);
    EXPECT_LT(svg.size(), drawn.size());
    EXPECT_NE(svg.find("font-family=\"'CMU Serif', 'DejaVu Math TeX Gyre'\""), std::string::npos);
    // T/T0: italics, and the subscript smaller and lower (dy down), then back on the baseline.
    const std::regex t_over_t0(
        "<tspan font-style=\"italic\">T</tspan>/<tspan font-style=\"italic\">T</tspan>"
        "<tspan dy=\"([0-9.]+)\" font-size=\"([0-9.]+)\">0</tspan></text>");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(svg, m, t_over_t0)) << svg;
    EXPECT_EQ(paths.label_font_pt, 9);  // the paper theme's labels
    EXPECT_NEAR(std::stod(m[1]), 0.15 * 9, 0.01);
    EXPECT_NEAR(std::stod(m[2]), 0.7 * 9, 0.01);
    // The y axis label reads upwards about its anchor.
    EXPECT_NE(svg.find("transform=\"rotate(-90 "), std::string::npos);
    // Tick labels centred under their ticks.
    EXPECT_GT(count(svg, "text-anchor=\"middle\""), 3u);
    EXPECT_EQ(plot::render(built, texts, "svg", {}), svg);
}

TEST(SvgSize, PointsPixelsOrTheViewBoxAlone) {
    const auto& e = figures::find("c1-lowest");
    const plot::figure built = figures::build(e);
    const auto root = [&](const char* unit) {
        const plot::theme th = figures::load_theme("paper", {std::string("svg_size=") + unit});
        return root_of(plot::render(built, th, "svg", {}));
    };
    // The same numbers in points and in the viewBox, 4/3 of them in CSS pixels.
    const auto attribute = [](const std::string& root, const std::string& name) {
        std::smatch m;
        if (!std::regex_search(root, m, std::regex(" " + name + "=\"([^\"]*)\""))) return std::string("none");
        return std::string(m[1]);
    };
    const std::string in_points = root("pt");
    const std::string view_box = attribute(in_points, "viewBox");
    const double w = std::stod(view_box.substr(4));
    const double h = std::stod(view_box.substr(view_box.find(' ', 4)));
    ASSERT_EQ(attribute(in_points, "width").back(), 't') << in_points;
    EXPECT_NEAR(std::stod(attribute(in_points, "width")), w, 0.001);
    EXPECT_NEAR(std::stod(attribute(in_points, "height")), h, 0.001);
    const std::string in_pixels = root("px");
    EXPECT_EQ(attribute(in_pixels, "width").find_first_not_of("0123456789."), std::string::npos) << in_pixels;
    EXPECT_NEAR(std::stod(attribute(in_pixels, "width")), w * 4 / 3, 0.001);
    EXPECT_NEAR(std::stod(attribute(in_pixels, "height")), h * 4 / 3, 0.001);
    EXPECT_EQ(attribute(in_pixels, "viewBox"), view_box);
    const std::string responsive = root("viewbox");
    EXPECT_EQ(attribute(responsive, "width"), "none") << responsive;
    EXPECT_EQ(attribute(responsive, "height"), "none") << responsive;
    EXPECT_EQ(attribute(responsive, "viewBox"), view_box);
    // The default is points, as before.
    EXPECT_EQ(root_of(plot::render(built, figures::load_theme("paper", {}), "svg", {})), in_points);
    // A value not in the list is refused, naming the list.
    try {
        figures::load_theme("paper", {"svg_size=em"});
        ADD_FAILURE() << "svg_size=em accepted";
    } catch (const std::exception& x) {
        EXPECT_NE(std::string(x.what()).find("pt"), std::string::npos) << x.what();
    }
}

}  // namespace
