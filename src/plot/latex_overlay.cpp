// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/latex_overlay.hpp"

#include "plot/errors.hpp"
#include "plot/tex_markup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace plot {

namespace {

/// LaTeX's size commands, smallest first.
constexpr std::array<std::string_view, 9> commands = {"\\tiny",      "\\scriptsize", "\\footnotesize",
                                                      "\\small",     "\\normalsize", "\\large",
                                                      "\\Large",     "\\LARGE",      "\\huge"};
using size_list = std::array<double, commands.size()>;
/// Their sizes in points in the standard classes (size10.clo, size11.clo, size12.clo).
constexpr size_list size10 = {5, 7, 8, 9, 10, 12, 14.4, 17.28, 20.74};
constexpr size_list size11 = {6, 8, 9, 10, 10.95, 12, 14.4, 17.28, 20.74};
constexpr size_list size12 = {6, 8, 10, 10.95, 12, 14.4, 17.28, 20.74, 24.88};

/// The sizes in a document set at document_pt: the class files' at 10, 11 (or 10.95) and
/// 12 pt, and the 10 pt ones scaled at any other size.
size_list document_sizes(double document_pt) {
    if (std::fabs(document_pt - 10) < 0.01) return size10;
    if (std::fabs(document_pt - 11) < 0.06) return size11;
    if (std::fabs(document_pt - 12) < 0.01) return size12;
    size_list scaled = size10;
    for (double& pt : scaled) pt *= document_pt / 10;
    return scaled;
}

/// The index of the size in the list nearest to size_pt, nearest by ratio.
std::size_t nearest_size(double size_pt, const size_list& list) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < list.size(); ++i) {
        if (std::fabs(std::log(size_pt / list[i])) < std::fabs(std::log(size_pt / list[best]))) best = i;
    }
    return best;
}

/// A size in points as LaTeX reads it: at most two decimals, no trailing zeros.
std::string points(double pt) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", pt);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

std::string fixed(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.5f", v);
    std::string s = buf;
    if (s == "-0.00000") s = "0.00000";
    return s;
}

}  // namespace

namespace {

/// The theme's text sizes as a LaTeX document of document_pt sets them: the nearest size
/// command, or a larger one where the document sets that below the theme's least text size
/// (\scriptsize is 7 pt in a 10 pt document).
text_sizes in_document(const theme& th, double document_pt) {
    const size_list sizes = document_sizes(document_pt);
    const auto sized = [&](double pt) {
        std::size_t i = nearest_size(pt, size10);
        while (i + 1 < sizes.size() && sizes[i] < th.min_text_pt) ++i;
        return sizes[i];
    };
    return {sized(th.tick_font_pt), sized(th.label_font_pt), sized(th.legend_font_pt)};
}

text_sizes larger(const text_sizes& a, const text_sizes& b) {
    return {std::max(a.tick_pt, b.tick_pt), std::max(a.label_pt, b.label_pt), std::max(a.legend_pt, b.legend_pt)};
}

}  // namespace

text_sizes decided_sizes(const theme& th) {
    const text_sizes own{th.tick_font_pt, th.label_font_pt, th.legend_font_pt};
    if (th.decided_at) return larger(*th.decided_at, own);
    if (!(th.tex_agree_pt > 0)) return own;
    return larger(own, in_document(th, th.tex_agree_pt));
}

theme latex_sized_theme(const theme& th, const output_options& options) {
    theme sized = th;
    sized.decided_at = decided_sizes(th);
    if (options.tex_sizes == tex_sizing::absolute) return sized;
    const text_sizes at = in_document(th, options.tex_font_pt);
    sized.tick_font_pt = at.tick_pt;
    sized.label_font_pt = at.label_pt;
    sized.legend_font_pt = at.legend_pt;
    return sized;
}

std::string latex_size_command(double size_pt, const output_options& options) {
    if (options.tex_sizes == tex_sizing::absolute) {
        return "\\fontsize{" + points(size_pt) + "}{" + points(1.2 * size_pt) + "}\\selectfont";
    }
    return std::string(commands[nearest_size(size_pt, document_sizes(options.tex_font_pt))]);
}

namespace {

constexpr std::array<tex_sizing_row, 2> sizings = {{
    {"relative", tex_sizing::relative,
     "LaTeX's size commands (\\footnotesize, \\small): the text follows the document's size, "
     "given by --tex-font-size"},
    {"absolute", tex_sizing::absolute,
     "the theme's sizes in points (\\fontsize{7.5}{9}): the same in any document (--set tick_font_pt=... "
     "changes them)"},
}};

}  // namespace

std::span<const tex_sizing_row> tex_sizing_table() { return sizings; }

const tex_sizing_row& find_tex_sizing(std::string_view name) {
    for (const auto& row : sizings) {
        if (row.name == name) return row;
    }
    std::string list;
    for (const auto& row : sizings) list += (list.empty() ? "" : ", ") + std::string(row.name);
    throw bad_input("unknown text sizing '" + std::string(name) + "'; sizings: " + list);
}

bool plain_file_name_character(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
           c == '+' || c == '-';
}

void check_latex_file_name(std::string_view name) {
    for (const char c : name) {
        if (plain_file_name_character(c)) continue;
        const auto u = static_cast<unsigned char>(c);
        char shown[16];
        std::snprintf(shown, sizeof shown, u < 0x20 || u >= 0x7f ? "\\x%02x" : "'%c'", u);
        std::string safe;
        for (const char d : name) safe += (static_cast<unsigned char>(d) < 0x20 || static_cast<unsigned char>(d) >= 0x7f) ? '?' : d;
        throw bad_input("an overlay's drawing '" + safe + "' has the character " + shown +
                        ", which LaTeX cannot take in a file name as written; name the file with letters, "
                        "digits and . _ + -");
    }
}

std::string latex_picture(const std::vector<placed_text>& texts, page_size size, const theme& th,
                          const std::string& graphics_name, const output_options& options) {
    check_latex_file_name(graphics_name);
    const double w = size.width_pt;
    const double h = size.height_pt;
    const bool black = th.foreground.r == 0 && th.foreground.g == 0 && th.foreground.b == 0;
    std::string out;
    out += "%% LaTeX text of " + graphics_name + ", written by pendulum-figures.\n";
    out += "%% \\input{this file} with \\usepackage{graphicx}; \\def\\figurewidth{8.6cm} first scales the drawing,\n";
    if (options.tex_sizes == tex_sizing::absolute) {
        out += "%% not the text, which is set in the document's fonts at sizes in points (\\fontsize): with\n";
        out += "%% Computer Modern, \\RequirePackage{fix-cm} before \\documentclass makes every size exist.\n";
    } else {
        out += "%% not the text, which is set in the document's fonts at sizes relative to its own.\n";
    }
    out += "\\begingroup%\n";
    out += "\\makeatletter%\n";
    // Colour without the color package is no colour; amsmath's macros without amsmath, plain ones.
    out += "\\providecommand\\color[2][]{}%\n";
    out += "\\providecommand\\lvert{|}\\providecommand\\rvert{|}%\n";
    out += "\\providecommand\\text[1]{\\mbox{#1}}\\providecommand\\operatorname[1]{\\mathrm{#1}}%\n";
    out += "\\ifx\\figurewidth\\undefined%\n";
    out += "  \\setlength{\\unitlength}{" + fixed(w) + "bp}%\n";
    out += "\\else%\n";
    out += "  \\setlength{\\unitlength}{\\figurewidth}%\n";
    out += "\\fi%\n";
    out += "\\global\\let\\figurewidth\\undefined%\n";
    if (options.tex_sizes == tex_sizing::relative) {
        // The layout made room for the size commands as they are in a document of
        // tex_font_pt. In a document of another size they would be larger or smaller than
        // that room (text over text): there they keep the sizes the layout had, and say so.
        const size_list sizes = document_sizes(options.tex_font_pt);
        const std::string normal = points(sizes[4]);
        out += "\\normalsize\\edef\\PFnormal{\\f@size}\\def\\PFother{0}%\n";
        out += "\\ifdim\\PFnormal pt<" + points(sizes[4] - 0.1) + "pt \\def\\PFother{1}\\fi%\n";
        out += "\\ifdim\\PFnormal pt>" + points(sizes[4] + 0.1) + "pt \\def\\PFother{1}\\fi%\n";
        out += "\\if1\\PFother%\n";
        out += "  \\typeout{pendulum-figures: " + graphics_name + " was laid out for a " + normal +
               " pt document, not \\PFnormal\\space pt; its text keeps those sizes (render with "
               "--tex-font-size \\PFnormal)}%\n";
        for (std::size_t i = 0; i < commands.size(); ++i) {
            out += "  \\def" + std::string(commands[i]) + "{\\fontsize{" + points(sizes[i]) + "}{" +
                   points(1.2 * sizes[i]) + "}\\selectfont}%\n";
        }
        out += "\\fi%\n";
    }
    out += "\\makeatother%\n";
    out += "\\begin{picture}(1," + fixed(h / w) + ")%\n";
    out += "  \\put(0,0){\\includegraphics[width=\\unitlength]{" + graphics_name + "}}%\n";
    if (!black) {
        char rgb[96];
        std::snprintf(rgb, sizeof rgb, "\\color[rgb]{%.4f,%.4f,%.4f}%%\n", th.foreground.r, th.foreground.g,
                      th.foreground.b);
        out += std::string("  ") + rgb;
    }
    for (const auto& t : texts) {
        const char* align = t.align < 0.25 ? "l" : t.align > 0.75 ? "r" : "c";
        std::string box = std::string("\\makebox(0,0)[") + align + "]{\\smash{" +
                          latex_size_command(t.size_pt, options) + " " + label_latex(t.text) + "}}";
        if (t.rotate) box = "\\rotatebox{90}{" + box + "}";
        out += "  \\put(" + fixed(t.x / w) + "," + fixed((h - t.y) / w) + "){" + box + "}%\n";
    }
    out += "\\end{picture}%\n";
    out += "\\endgroup%\n";
    return out;
}

}  // namespace plot
