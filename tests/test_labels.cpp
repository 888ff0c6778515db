// SPDX-License-Identifier: GPL-3.0-or-later
// Labels from specs are untrusted text: what reaches a LaTeX overlay is written from the
// label's parse (text escaped, math limited to what the engine draws), and a label's LaTeX
// travels with it, so that no file depends on what else the process drew.
#include "plot/tex_markup.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using test_support::files_in;
using test_support::run_cli;
using test_support::temp_dir;

namespace {

/// The control sequences an overlay may hold: the engine's symbols and accents, its spaces,
/// and the escapes of characters. Anything else (\input, \write, \openout, \csname,
/// \catcode, \def, ...) would be a label reaching into the document.
const std::set<std::string>& allowed_macros() {
    static const std::set<std::string> names = {
        // Greek and symbols of the engine's table
        "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta", "iota",
        "kappa", "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "varphi", "chi", "psi",
        "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega", "cdot", "times",
        "pm", "mp", "le", "leq", "ge", "geq", "approx", "sim", "infty", "circ", "prime", "ldots", "dots", "to",
        "propto", "partial", "ln", "log", "exp", "sin", "cos", "tan", "lvert", "rvert",
        "varpi", "varrho", "varsigma", "Upsilon", "nabla", "ell", "hbar", "cdots", "ne", "neq", "simeq", "equiv",
        "rightarrow", "cot", "sinh", "cosh", "tanh", "arcsin", "arccos", "arctan", "max", "min",
        // roots, fractions and delimiters, passed to LaTeX as written
        "sqrt", "frac", "tfrac", "dfrac", "left", "right",
        // accents, spaces, upright and italic text
        "dot", "ddot", "hat", "bar", "tilde", "vec", "overline", "quad", "qquad", "mathrm", "mathit", "mathbf", "text",
        "textrm", "operatorname",
        // escapes of characters
        "textbackslash", "textbar", "textless", "textgreater", "backslash", "hat",
        ",", ":", ">", ";", "!", " ", "{", "}", "%", "$", "&", "#", "_", "|", "^", "~"};
    return names;
}

/// Every control sequence of `latex` that is not allowed.
std::vector<std::string> foreign_macros(const std::string& latex) {
    std::vector<std::string> found;
    static const std::regex macro(R"(\\([A-Za-z]+|[^A-Za-z]))");
    for (auto it = std::sregex_iterator(latex.begin(), latex.end(), macro); it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[1].str();
        if (!allowed_macros().count(name)) found.push_back(name);
    }
    return found;
}

/// Labels that try to reach into the document that \inputs the overlay.
const std::vector<std::string> hostile = {
    "host: \\input /etc/hostname \\immediate\\openout15=victim.tex",
    "\\immediate\\write18[touch pwned.txt]",
    "\\\\input{x} \\\\$\\\\ \\catcode`\\^^M=13 \\def\\x{}",
    "$\\mathrm{\\input /etc/passwd}$ $\\text{\\write18{ls}$",
    "$\\text{\\immediate\\write18 ls}$ and $\\operatorname{\\openout1=a}$",
    "$x^{\\dot{\\mathit{\\csname input\\endcsname}}}$",
    "50% & #1 a_b {c} ^ ~ | < > \\",
    "$a \\% b \\& c \\# d \\{ e \\} f \\_ g \\$ h \\, i \\; j \\! k \\| l$",
    "$\\left( x \\right) \\big| \\Big\\{$",
};

}  // namespace

TEST(Labels, OverlayHoldsOnlyWhatTheEngineDraws) {
    for (const auto& tex : hostile) {
        std::string latex;
        try {
            latex = plot::tex_to_latex(tex);
        } catch (const std::invalid_argument&) {
            continue;  // refused: nothing to write
        }
        EXPECT_EQ(foreign_macros(latex), std::vector<std::string>{}) << tex << "\n  -> " << latex;
    }
    // The text of a hostile label is still shown, as text.
    EXPECT_EQ(plot::tex_to_latex("\\input /etc/hostname"), "\\textbackslash{}input /etc/hostname");
    EXPECT_EQ(plot::tex_to_latex("$\\mathrm{\\input x}$"), "$\\mathrm{\\backslash input\\ x}$");
    EXPECT_EQ(plot::tex_to_latex("$\\text{\\write18 ls}$"), "$\\text{\\textbackslash{}write18 ls}$");
    // Macros the engine does not know are refused, in math as outside it.
    EXPECT_THROW(plot::tex_to_latex("$\\input{/etc/passwd}$"), std::invalid_argument);
    EXPECT_THROW(plot::tex_to_latex("$\\csname x\\endcsname$"), std::invalid_argument);
    EXPECT_THROW(plot::tex_to_latex("$\\@$"), std::invalid_argument);
}

TEST(Labels, ScriptsAndPrimesAreValidLatex) {
    // A prime is a superscript in TeX: with another superscript they share one.
    EXPECT_EQ(plot::tex_to_latex("$c''_1$"), "$c''_1$");
    EXPECT_EQ(plot::tex_to_latex("$x'^2$"), "$x^{\\prime 2}$");
    EXPECT_EQ(plot::tex_to_latex("$x^{2}'$"), "$x^2{}^{\\prime}$");
    EXPECT_EQ(plot::tex_to_latex("$T_{1}$"), "$T_1$");
    EXPECT_EQ(plot::tex_to_latex("$T_1$"), "$T_1$");
    EXPECT_EQ(plot::tex_to_latex("$T_{12}$"), "$T_{12}$");
    EXPECT_EQ(plot::tex_to_latex("$\\dot\\vartheta$"), "$\\dot{\\vartheta }$");
}

TEST(Labels, ControlCharactersLengthAndNestingAreRefused) {
    for (const std::string& bad : {std::string("a\rb"), std::string("a\x1b[2Jb"), std::string("a\0b", 3),
                                  std::string("$x\ny$"), std::string("tab\there")}) {
        EXPECT_THROW(plot::tex_to_markup(bad), std::invalid_argument) << bad;
        EXPECT_THROW(plot::tex_to_latex(bad), std::invalid_argument) << bad;
    }
    EXPECT_NO_THROW(plot::tex_to_markup(std::string(plot::max_label_bytes, 'a')));
    EXPECT_THROW(plot::tex_to_markup(std::string(plot::max_label_bytes + 1, 'a')), std::invalid_argument);
    // Deep nesting is an error, not a stack overflow, in every construct that nests.
    const auto nested = [](const std::string& open, const std::string& close, int n) {
        std::string s = "$";
        for (int i = 0; i < n; ++i) s += open;
        s += "x";
        for (int i = 0; i < n; ++i) s += close;
        return s + "$";
    };
    EXPECT_NO_THROW(plot::tex_to_markup(nested("{", "}", 40)));
    for (const int n : {60, 300}) {  // 300 levels: within the length limit, far past the depth one
        EXPECT_THROW(plot::tex_to_markup(nested("{", "}", n)), std::invalid_argument) << n;
        EXPECT_THROW(plot::tex_to_markup(nested("x^{", "}", n)), std::invalid_argument) << n;
        EXPECT_THROW(plot::tex_to_markup(nested("\\dot", "", n)), std::invalid_argument) << n;
        EXPECT_THROW(plot::tex_to_markup(nested("\\left", "", n)), std::invalid_argument) << n;
        EXPECT_THROW(plot::tex_to_latex(nested("x_{", "}", n)), std::invalid_argument) << n;
    }
}

TEST(Labels, ALabelCarriesItsLatex) {
    // The same markup from two different TeX sources keeps each its own LaTeX.
    const plot::label a = plot::tex_label("$T_{1} \\le 1$");
    const plot::label b = plot::tex_label("$T_1 \\leq 1$");
    EXPECT_EQ(a.markup, b.markup);
    EXPECT_EQ(plot::label_latex(a), "$T_1\\le 1$");
    EXPECT_EQ(plot::label_latex(b), "$T_1\\leq 1$");
    // A label the program made is written from its markup.
    EXPECT_EQ(plot::label_latex(plot::label("<i>T</i> (s)")), "$T$ (s)");
    // Joined labels keep both forms.
    const plot::label j = plot::join(plot::label("(a) "), a);
    EXPECT_EQ(j.markup, "(a) " + a.markup);
    EXPECT_EQ(plot::label_latex(j), "(a) $T_1\\le 1$");
}

TEST(Labels, SameBytesAloneOrInABatchInEveryFormat) {
    // Two specs whose labels differ only in TeX that draws the same (T_{1} and T_1): each
    // file is the same whether it was rendered alone or after the other, in either order.
    const auto specs = temp_dir("labels-specs");
    for (const auto& [name, label] : {std::pair{"a", "$T_{1} \\le 1$"}, std::pair{"b", "$T_1 \\leq 1$"}}) {
        std::ofstream(specs / (std::string(name) + ".toml"))
            << "[[panel]]\nplot = \"period\"\nmethods = [\"exact\", \"lowest\"]\nx_label = '" << label << "'\n"
            << "title = '" << label << "'\n";
    }
    const std::string a = (specs / "a.toml").string();
    const std::string b = (specs / "b.toml").string();
    for (const char* formats : {"png,pdf,svg,eps", "pdf_tex", "eps_tex"}) {
        const auto ab = temp_dir("labels-ab");
        const auto ba = temp_dir("labels-ba");
        const auto alone = temp_dir("labels-alone");
        const std::string f = std::string(" -f ") + formats + " --dpi 40 ";
        ASSERT_EQ(run_cli("render fig1 '" + a + "' '" + b + "'" + f + "-o '" + ab.string() + "'").status, 0) << formats;
        ASSERT_EQ(run_cli("render '" + b + "' '" + a + "' fig1" + f + "-o '" + ba.string() + "'").status, 0) << formats;
        for (const std::string& one : {a, b, std::string("fig1")}) {
            ASSERT_EQ(run_cli("render '" + one + "'" + f + "-o '" + alone.string() + "'").status, 0) << formats;
        }
        const auto names = files_in(alone);
        EXPECT_GE(names.size(), 3u) << formats;
        for (const auto& name : names) {
            EXPECT_EQ(test_support::slurp(ab / name), test_support::slurp(alone / name)) << formats << " " << name;
            EXPECT_EQ(test_support::slurp(ba / name), test_support::slurp(alone / name)) << formats << " " << name;
        }
        if (std::string(formats) == "pdf_tex") {
            EXPECT_NE(test_support::slurp(alone / "a.pdf_tex").find("$T_1\\le 1$"), std::string::npos);
            EXPECT_NE(test_support::slurp(alone / "b.pdf_tex").find("$T_1\\leq 1$"), std::string::npos);
        }
        fs::remove_all(ab);
        fs::remove_all(ba);
        fs::remove_all(alone);
    }
    fs::remove_all(specs);
}

TEST(Labels, InvalidUtf8IsRefused) {
    // A lone lead byte, a stray continuation byte, an overlong form, a surrogate, a truncated end.
    for (const std::string& bad : {std::string("$c'\xc8'_1$"), std::string("a\x80"), std::string("\xc0\xaf"),
                                  std::string("\xed\xa0\x80"), std::string("ab\xe2\x82")}) {
        EXPECT_THROW(plot::tex_to_markup(bad), std::invalid_argument);
        EXPECT_THROW(plot::tex_to_latex(bad), std::invalid_argument);
    }
    EXPECT_NO_THROW(plot::tex_to_markup("\xcf\x91 \xe2\x80\x93 \xf0\x9f\x98\x80"));  // ϑ, en dash, an emoji
}
