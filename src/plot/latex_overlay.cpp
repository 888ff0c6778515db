// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/latex_overlay.hpp"

#include "plot/tex_markup.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <utility>

namespace plot {

namespace {

/// LaTeX's sizes in a 10 pt document (size10.clo), as multiples of \normalsize.
constexpr std::array<std::pair<double, std::string_view>, 9> sizes = {{{0.5, "\\tiny"},
                                                                      {0.7, "\\scriptsize"},
                                                                      {0.8, "\\footnotesize"},
                                                                      {0.9, "\\small"},
                                                                      {1.0, "\\normalsize"},
                                                                      {1.2, "\\large"},
                                                                      {1.44, "\\Large"},
                                                                      {1.728, "\\LARGE"},
                                                                      {2.074, "\\huge"}}};

/// The index of the size nearest to size_pt (in a 10 pt scale), nearest by ratio.
std::size_t nearest_size(double size_pt) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < sizes.size(); ++i) {
        if (std::fabs(std::log(size_pt / 10 / sizes[i].first)) < std::fabs(std::log(size_pt / 10 / sizes[best].first))) {
            best = i;
        }
    }
    return best;
}

std::string fixed(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.5f", v);
    std::string s = buf;
    if (s == "-0.00000") s = "0.00000";
    return s;
}

}  // namespace

theme latex_sized_theme(const theme& th, double document_pt) {
    theme sized = th;
    for (double* pt : {&sized.tick_font_pt, &sized.label_font_pt, &sized.legend_font_pt}) {
        *pt = sizes[nearest_size(*pt)].first * document_pt;
    }
    return sized;
}

std::string latex_size_command(double size_pt, double document_pt) {
    return std::string(sizes[nearest_size(size_pt * 10 / document_pt)].second);
}

std::string latex_picture(const std::vector<placed_text>& texts, page_size size, const theme& th,
                          const std::string& graphics_name, double document_pt) {
    const double w = size.width_pt;
    const double h = size.height_pt;
    const bool black = th.foreground.r == 0 && th.foreground.g == 0 && th.foreground.b == 0;
    std::string out;
    out += "%% LaTeX text of " + graphics_name + ", written by pendulum-figures.\n";
    out += "%% \\input{this file} with \\usepackage{graphicx}; \\def\\figurewidth{8.6cm} first scales the drawing,\n";
    out += "%% not the text, which is set in the document's fonts at sizes relative to its own.\n";
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
                          latex_size_command(t.size_pt, document_pt) + " " + markup_to_latex(t.markup) + "}}";
        if (t.rotate) box = "\\rotatebox{90}{" + box + "}";
        out += "  \\put(" + fixed(t.x / w) + "," + fixed((h - t.y) / w) + "){" + box + "}%\n";
    }
    out += "\\end{picture}%\n";
    out += "\\endgroup%\n";
    return out;
}

}  // namespace plot
