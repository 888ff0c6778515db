// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/tex_markup.hpp"

#include "common/suggest.hpp"
#include "plot/errors.hpp"
#include "plot/figure.hpp"
#include "plot/math_layout.hpp"

#include <glib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

namespace plot {

namespace {

using enum macro_kind;
constexpr auto bin = math_class::binary;
constexpr auto rel = math_class::relation;

// Lowercase Greek is italic in TeX's math, uppercase upright. TeX has no \omicron, \Alpha,
// \Beta, ...: those are Latin letters (o, A, B), and LaTeX would refuse the names.
constexpr tex_macro macro_table[] = {
    {"alpha", "\u03b1", "\\alpha ", symbol, true},       {"beta", "\u03b2", "\\beta ", symbol, true},
    {"gamma", "\u03b3", "\\gamma ", symbol, true},       {"delta", "\u03b4", "\\delta ", symbol, true},
    {"epsilon", "\u03f5", "\\epsilon ", symbol, true},   {"varepsilon", "\u03b5", "\\varepsilon ", symbol, true},
    {"zeta", "\u03b6", "\\zeta ", symbol, true},         {"eta", "\u03b7", "\\eta ", symbol, true},
    {"theta", "\u03b8", "\\theta ", symbol, true},       {"vartheta", "\u03d1", "\\vartheta ", symbol, true},
    {"iota", "\u03b9", "\\iota ", symbol, true},         {"kappa", "\u03ba", "\\kappa ", symbol, true},
    {"lambda", "\u03bb", "\\lambda ", symbol, true},     {"mu", "\u03bc", "\\mu ", symbol, true},
    {"nu", "\u03bd", "\\nu ", symbol, true},             {"xi", "\u03be", "\\xi ", symbol, true},
    {"pi", "\u03c0", "\\pi ", symbol, true},             {"varpi", "\u03d6", "\\varpi ", symbol, true},
    {"rho", "\u03c1", "\\rho ", symbol, true},           {"varrho", "\u03f1", "\\varrho ", symbol, true},
    {"sigma", "\u03c3", "\\sigma ", symbol, true},       {"varsigma", "\u03c2", "\\varsigma ", symbol, true},
    {"tau", "\u03c4", "\\tau ", symbol, true},           {"upsilon", "\u03c5", "\\upsilon ", symbol, true},
    {"phi", "\u03d5", "\\phi ", symbol, true},           {"varphi", "\u03c6", "\\varphi ", symbol, true},
    {"chi", "\u03c7", "\\chi ", symbol, true},           {"psi", "\u03c8", "\\psi ", symbol, true},
    {"omega", "\u03c9", "\\omega ", symbol, true},       {"Gamma", "\u0393", "\\Gamma ", symbol},
    {"Delta", "\u0394", "\\Delta ", symbol},             {"Theta", "\u0398", "\\Theta ", symbol},
    {"Lambda", "\u039b", "\\Lambda ", symbol},           {"Xi", "\u039e", "\\Xi ", symbol},
    {"Pi", "\u03a0", "\\Pi ", symbol},                   {"Sigma", "\u03a3", "\\Sigma ", symbol},
    {"Upsilon", "\u03a5", "\\Upsilon ", symbol},         {"Phi", "\u03a6", "\\Phi ", symbol},
    {"Psi", "\u03a8", "\\Psi ", symbol},                 {"Omega", "\u03a9", "\\Omega ", symbol},
    // Letter-like symbols
    {"partial", "\u2202", "\\partial ", symbol, true},   {"nabla", "\u2207", "\\nabla ", symbol},
    {"ell", "\u2113", "\\ell ", symbol},                 {"hbar", "\u210f", "\\hbar ", symbol},
    {"infty", "\u221e", "\\infty ", symbol},             {"prime", "\u2032", "\\prime ", symbol},
    {"ldots", "\u2026", "\\ldots ", symbol},             {"dots", "\u2026", "\\dots ", symbol},
    {"cdots", "\u22ef", "\\cdots ", symbol},             {"lvert", "|", "\\lvert ", symbol},
    {"rvert", "|", "\\rvert ", symbol},
    // Binary operators and relations
    {"cdot", "\u22c5", "\\cdot ", symbol, false, bin},   {"times", "\u00d7", "\\times ", symbol, false, bin},
    {"pm", "\u00b1", "\\pm ", symbol, false, bin},       {"mp", "\u2213", "\\mp ", symbol, false, bin},
    {"circ", "\u2218", "\\circ ", symbol, false, bin},   {"le", "\u2264", "\\le ", symbol, false, rel},
    {"leq", "\u2264", "\\leq ", symbol, false, rel},     {"ge", "\u2265", "\\ge ", symbol, false, rel},
    {"geq", "\u2265", "\\geq ", symbol, false, rel},     {"ne", "\u2260", "\\ne ", symbol, false, rel},
    {"neq", "\u2260", "\\neq ", symbol, false, rel},     {"approx", "\u2248", "\\approx ", symbol, false, rel},
    {"sim", "\u223c", "\\sim ", symbol, false, rel},     {"simeq", "\u2243", "\\simeq ", symbol, false, rel},
    {"equiv", "\u2261", "\\equiv ", symbol, false, rel}, {"propto", "\u221d", "\\propto ", symbol, false, rel},
    {"to", "\u2192", "\\to ", symbol, false, rel},       {"rightarrow", "\u2192", "\\rightarrow ", symbol, false, rel},
    // Functions' names, upright
    {"sin", "sin", "\\sin ", symbol},     {"cos", "cos", "\\cos ", symbol},     {"tan", "tan", "\\tan ", symbol},
    {"cot", "cot", "\\cot ", symbol},     {"sinh", "sinh", "\\sinh ", symbol},  {"cosh", "cosh", "\\cosh ", symbol},
    {"tanh", "tanh", "\\tanh ", symbol},  {"arcsin", "arcsin", "\\arcsin ", symbol},
    {"arccos", "arccos", "\\arccos ", symbol},  {"arctan", "arctan", "\\arctan ", symbol},
    {"ln", "ln", "\\ln ", symbol},        {"log", "log", "\\log ", symbol},     {"exp", "exp", "\\exp ", symbol},
    {"max", "max", "\\max ", symbol},     {"min", "min", "\\min ", symbol},
    // Spaces
    {",", "\u2009", "\\,", symbol},  {":", "\u2005", "\\:", symbol},  {">", "\u2005", "\\>", symbol},
    {";", "\u2005", "\\;", symbol},  {"!", "", "\\!", symbol},         {" ", " ", "\\ ", symbol},
    {"quad", "\u2003", "\\quad ", symbol},  {"qquad", "\u2003\u2003", "\\qquad ", symbol},
    // Characters TeX reads as markup, escaped
    {"{", "{", "\\{", symbol},  {"}", "}", "\\}", symbol},  {"%", "%", "\\%", symbol},  {"$", "$", "\\$", symbol},
    {"&", "&", "\\&", symbol},  {"#", "#", "\\#", symbol},  {"_", "_", "\\_", symbol},  {"|", "\u2016", "\\|", symbol},
    // Layout: the markup column says what the drawing shows
    {"sqrt", "\u221a and a line over x; [n]: n raised before", "\\sqrt", function},
    {"frac", "a over a rule over b", "\\frac", function},
    {"tfrac", "as \\frac", "\\tfrac", function},
    {"dfrac", "as \\frac, parts at text size", "\\dfrac", function},
    {"left", "a delimiter: ( ) [ ] \\{ \\} | \\| . (none)", "\\left", function},
    {"right", "the delimiter closing \\left", "\\right", function},
    {"big", "its delimiter, at the text's size", "", function},
    {"Big", "its delimiter, at the text's size", "", function},
    // Accents: a combining mark after the argument, or an overline
    {"dot", "\u0307", "\\dot", accent},    {"ddot", "\u0308", "\\ddot", accent},  {"hat", "\u0302", "\\hat", accent},
    {"bar", "\u0304", "\\bar", accent},    {"tilde", "\u0303", "\\tilde", accent},
    {"vec", "\u20d7", "\\vec", accent},    {"overline", "", "\\overline", accent},
    // Faces: the argument as it is, in the face of the Pango tag (empty: upright)
    {"mathrm", "", "\\mathrm", font},      {"mathit", "i", "\\mathit", font},      {"mathbf", "b", "\\mathbf", font},
    {"text", "", "\\text", font},          {"textrm", "", "\\textrm", font},       {"operatorname", "", "\\operatorname", font},
};

/// The row of a macro's name, or null.
const tex_macro* find_macro(std::string_view name) {
    for (const auto& m : macro_table) {
        if (m.name == name) return &m;
    }
    return nullptr;
}

/// "unknown macro \\name", and the table's nearest name if one is close.
std::string unknown_macro(std::string_view name) {
    std::string out = "unknown macro \\" + std::string(name);
    const tex_macro* best = nullptr;
    // One edit for a short name, two for a longer one: farther is a guess, not a typo.
    std::size_t best_distance = name.size() <= 4 ? 2 : 3;
    for (const auto& m : macro_table) {
        if (m.name.size() < 2) continue;
        const std::size_t d = common::edit_distance(name, m.name);
        if (d < best_distance) best = &m, best_distance = d;
    }
    if (best) out += " (did you mean \\" + std::string(best->name) + "?)";
    return out;
}

/// The code point of the UTF-8 sequence at text[i] and its length, or a length of 0 where
/// the bytes are not valid UTF-8 (the shortest form, no surrogate, at most U+10FFFF).
std::pair<char32_t, std::size_t> utf8_at(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b = byte(i);
    if (b < 0x80) return {b, 1};
    std::size_t length = 0;
    unsigned char lo = 0x80;
    unsigned char hi = 0xbf;
    char32_t cp = 0;
    if (b >= 0xc2 && b <= 0xdf) {
        length = 2, cp = b & 0x1f;
    } else if (b >= 0xe0 && b <= 0xef) {
        length = 3, cp = b & 0x0f, lo = b == 0xe0 ? 0xa0 : 0x80, hi = b == 0xed ? 0x9f : 0xbf;
    } else if (b >= 0xf0 && b <= 0xf4) {
        length = 4, cp = b & 0x07, lo = b == 0xf0 ? 0x90 : 0x80, hi = b == 0xf4 ? 0x8f : 0xbf;
    } else {
        return {0, 0};
    }
    if (i + length > text.size()) return {0, 0};
    for (std::size_t k = 1; k < length; ++k) {
        const unsigned char c = byte(i + k);
        if (c < (k == 1 ? lo : 0x80) || c > (k == 1 ? hi : 0xbf)) return {0, 0};
        cp = (cp << 6) | (c & 0x3f);
    }
    return {cp, length};
}

std::string code_point(char32_t cp) {
    char out[16];
    std::snprintf(out, sizeof out, "U+%04X", static_cast<unsigned>(cp));
    return out;
}

std::string math_character(const std::string& c, const std::string& whole);
std::string text_character(const std::string& c);
std::string_view text_escape(char c);

/// What a label's TeX is turned into.
enum class target {
    markup,  ///< Pango markup, to draw
    plain,   ///< text without markup, for CSV headers and metadata
    latex,   ///< LaTeX for overlays: only what the engine draws, every other character escaped
};

/// Reads a label's TeX (text with math in $...$) and writes it in the target's form. The
/// LaTeX target is written from the parse, never copied: text is escaped, and math holds
/// only the characters and the macros of this file's tables, so that no label can make a
/// document read, write or run anything.
class converter {
public:
    converter(std::string_view tex, target to) : tex_(tex), markup_(to == target::markup), latex_(to == target::latex) {}

    std::string run() {
        if (tex_.size() > max_label_bytes) {
            throw bad_input("label of " + std::to_string(tex_.size()) + " bytes: at most " +
                                        std::to_string(max_label_bytes));
        }
        if (const std::string why = text_problem(tex_, max_label_bytes); !why.empty()) fail(why);
        std::string out;
        while (pos_ < tex_.size()) {
            const char c = tex_[pos_];
            if (c == '$') {
                ++pos_;
                const std::string inner = math('$');
                out += latex_ ? "$" + inner + "$" : inner;
                if (pos_ >= tex_.size() || tex_[pos_] != '$') fail("unbalanced $");
                ++pos_;
            } else if (c == '\\' && pos_ + 1 < tex_.size() && (tex_[pos_ + 1] == '$' || tex_[pos_ + 1] == '\\')) {
                out += text(std::string(1, tex_[pos_ + 1]));
                pos_ += 2;
            } else if (static_cast<unsigned char>(c) >= 0x80) {
                const std::string ch = utf8_character();
                out += latex_ ? text_latex(ch) : ch;
            } else if (markup_ && (c == '\'' || c == '`')) {
                out += quote(c);
            } else {
                out += text(std::string(1, c));
                ++pos_;
            }
        }
        return out;
    }

    /// TeX's quotes in text as it sets them: ' and ` as ’ and ‘, '' and `` as
    /// ” and “ (LaTeX is given them as written, and sets the same).
    std::string quote(char c) {
        const bool doubled = pos_ + 1 < tex_.size() && tex_[pos_ + 1] == c;
        pos_ += doubled ? 2 : 1;
        if (c == '\'') return doubled ? "\u201d" : "\u2019";
        return doubled ? "\u201c" : "\u2018";
    }

private:
    [[noreturn]] void fail(const std::string& why) const {
        const std::string shown = tex_.size() <= 80 ? std::string(tex_)
                                                     : std::string(tex_.substr(0, 40)) + "..." +
                                                           std::string(tex_.substr(tex_.size() - 20));
        throw bad_input("label '" + shown + "': " + why);
    }

    /// One character outside math, as the target writes it.
    std::string text(const std::string& s) const {
        if (latex_) {
            const std::string_view e = text_escape(s[0]);
            return e.empty() ? s : std::string(e);
        }
        return markup_ ? escape_markup(s) : s;
    }

    /// A UTF-8 character outside math as LaTeX: its text-mode form, or math.
    std::string text_latex(const std::string& ch) const {
        const std::string t = text_character(ch);
        return t.empty() ? "$" + math_character(ch, std::string(tex_)) + "$" : t;
    }

    /// The UTF-8 character at pos_, whole; pos_ moves past it.
    std::string utf8_character() {
        std::size_t end = pos_ + 1;
        while (end < tex_.size() && (static_cast<unsigned char>(tex_[end]) & 0xc0) == 0x80) ++end;
        std::string ch(tex_.substr(pos_, end - pos_));
        pos_ = end;
        return ch;
    }

    /// One ASCII character in math, as the target writes it.
    std::string escape(const std::string& s) const {
        if (latex_) return math_character(s, std::string(tex_));
        return markup_ ? escape_markup(s) : s;
    }
    std::string italic(const std::string& s) const { return markup_ ? "<i>" + s + "</i>" : s; }
    std::string wrap(const char* tag, const std::string& s) const {
        if (!markup_) return s;
        return std::string("<") + tag + ">" + s + "</" + tag + ">";
    }

    /// Braces, scripts and accents nest; deeper than this is no label anyone writes, and it
    /// would exhaust the stack.
    static constexpr int max_depth = 50;

    /// Counts one level of nesting for the rest of the enclosing call.
    struct nesting {
        explicit nesting(converter& c) : c_(c) {
            if (++c_.depth_ > max_depth) {
                c_.fail("nested too deeply (at most " + std::to_string(max_depth) + " levels of braces, scripts and accents)");
            }
        }
        ~nesting() { --c_.depth_; }
        nesting(const nesting&) = delete;
        nesting& operator=(const nesting&) = delete;
        converter& c_;
    };

    /// What an atom was, for the layout around it.
    struct atom_facts {
        math_class spacing = math_class::ordinary;  ///< a symbol's class
        bool group = false;                         ///< a braced group
        bool sum = false;                           ///< a group with a binary operator, relation, / or * at its top
        bool prime = false;                         ///< a lone ' (LaTeX: a prime on an empty base)
        bool operator_name = false;                 ///< \sin, \log, ...: a thin space before an operand after it
        bool fraction = false;                      ///< \frac, \tfrac, \dfrac: a quotient, in line a/b
    };

    /// True at "\right" (a whole macro name).
    bool at_right() const {
        return tex_.compare(pos_, 6, "\\right") == 0 &&
               (pos_ + 6 >= tex_.size() || !std::isalpha(static_cast<unsigned char>(tex_[pos_ + 6])));
    }

    /// What math() is given to read up to \right: a character no label holds.
    static constexpr char right_ = '\0';

    /// Math up to `closing` ('$', '}' or ']'), which is left for the caller; with closing
    /// right_, math up to \right (or the end of the enclosing group, which \left reports).
    /// Spaces in the source are ignored, as TeX does; binary operators and relations get a
    /// space each side, a sign (unary + or -) none, and nothing in scripts. `sum` is set if
    /// a binary operator or relation stands at this level.
    std::string math(char closing, bool* sum = nullptr) {
        std::string out;
        math_state state;
        for (;;) {
            skip_space();
            if (pos_ >= tex_.size()) return out;
            const char c = tex_[pos_];
            if (c == closing || (closing == right_ && (c == '$' || c == '}' || at_right()))) return out;
            if (c == '$' || c == '}') fail(c == '$' ? "unbalanced $" : "unbalanced }");
            const bool opens = c == '(' || c == '[' || at_left(c);  // before atom_with_scripts moves pos_
            const std::string item = atom_with_scripts();
            append_item(out, item, c, opens, state, sum);
        }
    }

    /// What math() has read of its group, for the spacing of what follows.
    struct math_state {
        bool after_operand = false;  ///< a binary operator after it is one, not a sign
        bool after_name = false;     ///< an operator name (\sin): a thin space before its operand
        int parens = 0;              ///< ( ... ) written in this group: what is inside them is not at its top
    };

    /// The class of the item that began with character c: its symbol's, a relation for
    /// = < >, a binary operator for + and - (a sign where no operand precedes it).
    math_class item_spacing(char c, bool after_operand) const {
        math_class spacing = last_.spacing;
        if (c == '=' || c == '<' || c == '>') spacing = math_class::relation;
        if (c == '+' || c == '-') spacing = math_class::binary;
        if (spacing == math_class::binary && !after_operand) spacing = math_class::ordinary;  // a sign
        return spacing;
    }

    /// Appends an item that began with character c, spaced as TeX spaces it: binary
    /// operators and relations a space each side (none in scripts), a thin space between an
    /// operator name and its operand and after a comma. `sum` is set if a binary operator,
    /// relation, / or * stands at the group's top.
    void append_item(std::string& out, const std::string& item, char c, bool opens, math_state& state, bool* sum) const {
        const math_class spacing = item_spacing(c, state.after_operand);
        // TeX's thin space between an operator name and its operand: sin x, not sinx.
        const bool operand = spacing == math_class::ordinary && !opens;
        if (state.after_name && operand && !latex_) out += "\u2009";
        state.after_name = last_.operator_name;
        if (c == '(') ++state.parens;
        if (c == ')' && state.parens > 0) --state.parens;
        if (spacing != math_class::ordinary) {
            if (sum && state.parens == 0) *sum = true;
            out += script_depth_ == 0 && !latex_ ? " " + item + " " : item;
            state.after_operand = false;
            return;
        }
        out += item;
        // TeX's thin space after punctuation in math: f(a, b); none in scripts.
        if (c == ',' && script_depth_ == 0 && !latex_) out += "\u2009";
        state.after_operand = !(c == '(' || c == '/' || c == '*' || c == ',' || c == '+' || c == '-');
        // a/b/c reads as (a/b)/c: a quotient or product in a fraction's part is one too
        if (sum && state.parens == 0 && (c == '/' || c == '*' || last_.fraction)) *sum = true;
    }

    /// One atom and the primes and scripts that follow it; last_ keeps the atom's facts.
    std::string atom_with_scripts() {
        std::string base = atom();
        const atom_facts facts = last_;
        // A lone ' is a prime on an empty base: it shares the superscript of the primes and
        // script after it, which LaTeX would otherwise call a double superscript.
        int primes = latex_ && facts.prime ? 1 : 0;
        while (pos_ < tex_.size() && tex_[pos_] == '\'') {
            ++primes;
            ++pos_;
        }
        const scripts sc = read_scripts();
        last_ = facts;
        if (primes > 0 || sc.has_sub || sc.has_sup) last_.spacing = math_class::ordinary;
        if (latex_ && facts.prime && !sc.has_sup) {
            std::string up;
            for (int i = 0; i < primes; ++i) up += "\\prime";
            return "{}^{" + up + "}" + (sc.has_sub ? "_" + script(ungrouped(sc.sub)) : "");
        }
        const std::string* sup = sc.has_sup ? &sc.sup : nullptr;
        const std::string* sub = sc.has_sub ? &sc.sub : nullptr;
        return latex_ ? scripts_latex(base, primes, sup, sub) : scripts_markup(base, primes, sup, sub);
    }

    /// The subscript and superscript after an atom, each at most once.
    struct scripts {
        std::string sub;
        std::string sup;
        bool has_sub = false;
        bool has_sup = false;
    };

    scripts read_scripts() {
        scripts sc;
        for (int i = 0; i < 2 && pos_ < tex_.size() && (tex_[pos_] == '_' || tex_[pos_] == '^'); ++i) {
            const bool is_sub = tex_[pos_] == '_';
            ++pos_;
            if (is_sub ? sc.has_sub : sc.has_sup) fail("double script");
            skip_space();
            if (pos_ >= tex_.size() || tex_[pos_] == '$' || tex_[pos_] == '}') fail("script without an argument");
            if (tex_[pos_] == '^' || tex_[pos_] == '_') fail("double script");
            ++script_depth_;
            (is_sub ? sc.sub : sc.sup) = atom();
            --script_depth_;
            (is_sub ? sc.has_sub : sc.has_sup) = true;
        }
        return sc;
    }

    /// A base with primes and scripts, as LaTeX: TeX's ' is ^\prime, so primes and a
    /// superscript share one superscript.
    static std::string scripts_latex(std::string out, int primes, const std::string* sup, const std::string* sub) {
        if (sup) {
            std::string up;
            for (int i = 0; i < primes; ++i) up += "\\prime ";
            out += "^" + script(up + ungrouped(*sup));
        } else {
            out += std::string(static_cast<std::size_t>(primes), '\'');
        }
        if (sub) out += "_" + script(ungrouped(*sub));
        return out;
    }

    /// A base with primes and scripts, as markup or plain text.
    std::string scripts_markup(std::string out, int primes, const std::string* sup_in, const std::string* sub) const {
        std::string sup = sup_in ? *sup_in : "";
        bool has_sup = sup_in != nullptr;
        if (primes > 0) {
            // Computer Modern Unicode has the modifier letter prime (U+02B9), not the prime.
            static const char* const marks[] = {"\u02b9", "\u02b9\u02b9", "\u02b9\u02b9\u02b9"};
            static const char* const plain[] = {"\u2032", "\u2033", "\u2034"};
            if (markup_ && primes <= 3) {
                // TeX's prime is a superscript: the renderer stacks the subscript under it.
                sup = marks[primes - 1] + sup;
                has_sup = true;
            } else {
                out += primes <= 3 ? plain[primes - 1] : std::string(static_cast<std::size_t>(primes), '\'');
            }
        }
        // ^\circ is the degree sign.
        if (has_sup) out += sup == "\u2218" ? std::string("\u00b0") : wrap("sup", sup);
        if (sub) out += wrap("sub", *sub);
        return out;
    }

    void skip_space() {
        while (pos_ < tex_.size() && tex_[pos_] == ' ') ++pos_;
    }

    /// A letter, digit, symbol, macro or braced group; last_ tells what it was.
    std::string atom() {
        const nesting level(*this);
        atom_facts facts;
        std::string out = atom_body(facts);
        last_ = facts;
        return out;
    }

    std::string atom_body(atom_facts& facts) {
        skip_space();
        if (pos_ >= tex_.size()) fail("incomplete math");
        const char c = tex_[pos_];
        if (c == '{') {
            ++pos_;
            std::string inner = math('}', &facts.sum);
            if (pos_ >= tex_.size()) fail("unbalanced {");
            ++pos_;
            facts.group = true;
            return latex_ ? "{" + inner + "}" : inner;
        }
        if (c == '\\') return macro(facts);
        if (static_cast<unsigned char>(c) >= 0x80) {
            // UTF-8 passes through whole: a typed ϑ or π is italic like its macro.
            const std::string ch = utf8_character();
            if (latex_) return math_character(ch, std::string(tex_));
            return ch == "\u03d1" || ch == "\u03c0" || ch == "\u03b8" ? italic(ch) : ch;
        }
        ++pos_;
        if (std::isalpha(static_cast<unsigned char>(c))) return italic(std::string(1, c));
        if (latex_) {
            if (std::isdigit(static_cast<unsigned char>(c))) return std::string(1, c);
            facts.prime = c == '\'';
            return c == '\'' ? "{}" : escape(std::string(1, c));
        }
        if (c == '-') return "\u2212";
        if (c == '*') return "\u2217";
        if (c == '\'') return "\u2032";
        return escape(std::string(1, c));
    }

    /// An operator name (\sin, \log, \exp, ...): a symbol drawn as a word of letters.
    static bool is_operator_name(const tex_macro& m) {
        return m.markup.size() > 1 && std::all_of(m.markup.begin(), m.markup.end(), [](char ch) {
                   return std::isalpha(static_cast<unsigned char>(ch)) != 0;
               });
    }

    /// True at "\left" (a whole macro name), where character c is.
    bool at_left(char c) const {
        return c == '\\' && tex_.compare(pos_, 5, "\\left") == 0 &&
               (pos_ + 5 >= tex_.size() || !std::isalpha(static_cast<unsigned char>(tex_[pos_ + 5])));
    }

    /// A macro, looked up in the table: unknown ones are refused, naming the nearest name.
    std::string macro(atom_facts& facts) {
        ++pos_;  // the backslash
        if (pos_ >= tex_.size()) fail("lone backslash");
        std::size_t end = pos_ + 1;
        if (std::isalpha(static_cast<unsigned char>(tex_[pos_]))) {
            while (end < tex_.size() && std::isalpha(static_cast<unsigned char>(tex_[end]))) ++end;
        }
        const std::string name(tex_.substr(pos_, end - pos_));
        pos_ = end;
        const tex_macro* m = find_macro(name);
        if (!m) fail(unknown_macro(name));
        switch (m->kind) {
            case macro_kind::symbol:
                facts.spacing = m->spacing;
                facts.operator_name = is_operator_name(*m);
                if (latex_) return std::string(m->latex);
                return m->italic ? italic(escape_markup_or_plain(std::string(m->markup)))
                                 : escape_markup_or_plain(std::string(m->markup));
            case macro_kind::accent: return accent(*m);
            case macro_kind::font: return face(*m);
            case macro_kind::function: break;
        }
        facts.fraction = m->name.ends_with("frac");
        return function(*m);
    }

    /// \dot{x} and the other accents: a combining mark after the argument (inside the
    /// italic of the letter it sits on), or an overline.
    std::string accent(const tex_macro& m) {
        std::string base = atom();
        const bool group = last_.group;
        if (latex_) return std::string(m.latex) + (group ? base : "{" + base + "}");
        if (m.markup.empty()) return markup_ ? "<span overline=\"single\">" + base + "</span>" : base;
        const std::string mark(m.markup);
        // TeX's \imath and \jmath: an accent on i or j replaces its dot.
        if (base == "<i>i</i>" || base == "<i>j</i>") base = base == "<i>i</i>" ? "<i>\u0131</i>" : "<i>\u0237</i>";
        const std::string close = "</i>";
        if (markup_ && base.size() > close.size() && base.ends_with(close)) {
            return base.insert(base.size() - close.size(), mark);
        }
        return base + mark;
    }

    /// \mathrm{...} and the other faces: the argument as it is, in the face.
    std::string face(const tex_macro& m) {
        skip_space();
        if (pos_ >= tex_.size() || tex_[pos_] != '{') fail("\\" + std::string(m.name) + " needs {...}");
        const std::size_t close = tex_.find('}', pos_);
        if (close == std::string_view::npos) fail("unbalanced {");
        const std::string inner(tex_.substr(pos_ + 1, close - pos_ - 1));
        pos_ = close + 1;
        if (latex_) {
            const bool in_math = m.name != "text" && m.name != "textrm";
            return std::string(m.latex) + "{" + literal_latex(inner, in_math) + "}";
        }
        return m.markup.empty() ? escape_markup_or_plain(inner) : wrap(std::string(m.markup).c_str(), escape_markup_or_plain(inner));
    }

    /// \sqrt, \frac, \left ... \right, \big.
    std::string function(const tex_macro& m) {
        if (m.name == "sqrt") return root(m);
        if (m.name == "left") return delimited();
        if (m.name == "right") fail("\\right without \\left");
        if (m.name == "big" || m.name == "Big") return atom();  // the engine draws delimiters at the text's size
        return fraction(m);
    }

    /// The argument's LaTeX inside one pair of braces.
    std::string braced_latex(const std::string& argument) const {
        return last_.group ? argument : "{" + argument + "}";
    }

    /// \sqrt{x} as √ and the radicand under an overline; \sqrt[n]{x} with n raised before.
    std::string root(const tex_macro& m) {
        skip_space();
        std::string index;
        const bool has_index = pos_ < tex_.size() && tex_[pos_] == '[';
        if (has_index) {
            ++pos_;
            ++script_depth_;
            index = math(']');
            --script_depth_;
            if (pos_ >= tex_.size()) fail("\\sqrt[ without ]");
            ++pos_;
        }
        const std::string body = atom();
        if (latex_) return std::string(m.latex) + (has_index ? "[" + index + "]" : "") + braced_latex(body);
        // The index raised before the sign, a thin space clear of what precedes it.
        const std::string raised = has_index ? "\u2009" + wrap("sup", index) : "";
        if (markup_) return raised + "\u221a<span overline=\"single\">" + body + "</span>";
        return raised + "\u221a" + (last_.group ? "(" + body + ")" : body);
    }

    /// \frac{a}{b}: as markup a <frac> (\dfrac: <dfrac>) the layout stacks, its parts
    /// <num> and <den>, or <pnum> and <pden> where a part written in line needs parentheses;
    /// as plain text in line as a/b, a or b in parentheses where it is a sum, a relation, or
    /// a quotient or product written with / or * (\frac{1}{x/2} is 1/(x/2)).
    std::string fraction(const tex_macro& m) {
        const std::string num = atom();
        const atom_facts top = last_;
        const std::string num_latex = braced_latex(num);
        const std::string den = atom();
        if (latex_) return std::string(m.latex) + num_latex + braced_latex(den);
        if (markup_) {
            const std::string kind = m.name == "dfrac" ? "dfrac" : "frac";
            const auto part = [](const std::string& name, const std::string& s, bool sum) {
                const std::string tag = sum ? "p" + name : name;
                return "<" + tag + ">" + s + "</" + tag + ">";
            };
            return "<" + kind + ">" + part("num", num, top.sum) + part("den", den, last_.sum) + "</" + kind + ">";
        }
        const auto part = [](const std::string& s, bool sum) { return sum ? "(" + s + ")" : s; };
        return part(num, top.sum) + "/" + part(den, last_.sum);
    }

    /// A delimiter of \left or \right: its markup (or plain text) and its LaTeX.
    std::pair<std::string, std::string> delimiter() {
        skip_space();
        if (pos_ < tex_.size()) {
            const char c = tex_[pos_];
            if (std::string_view("()[]|.").find(c) != std::string_view::npos) {
                ++pos_;
                return {c == '.' ? "" : std::string(1, c), std::string(1, c)};
            }
            if (c == '\\' && pos_ + 1 < tex_.size() && std::string_view("{}|").find(tex_[pos_ + 1]) != std::string_view::npos) {
                const char d = tex_[pos_ + 1];
                pos_ += 2;
                return {d == '|' ? "\u2016" : std::string(1, d), std::string("\\") + d};
            }
        }
        fail("\\left and \\right take a delimiter: ( ) [ ] \\{ \\} | \\| or . (none)");
    }

    /// \left( ... \right): the delimiters at the text's size, as the engine draws them.
    std::string delimited() {
        const auto open = delimiter();
        const std::string inner = math(right_);
        if (!at_right()) fail("\\left" + open.second + " without \\right");
        pos_ += 6;
        const auto close = delimiter();
        if (latex_) return "\\left" + open.second + inner + "\\right" + close.second;
        return escape_markup_or_plain(open.first) + inner + escape_markup_or_plain(close.first);
    }

    /// A script's LaTeX without the braces of a group, which the script adds again.
    static std::string ungrouped(const std::string& s) {
        return s.size() >= 2 && s.front() == '{' && s.back() == '}' ? s.substr(1, s.size() - 2) : s;
    }

    /// A script's argument: one letter or digit as it is, anything else in braces.
    static std::string script(const std::string& s) {
        return s.size() == 1 && std::isalnum(static_cast<unsigned char>(s[0])) ? s : "{" + s + "}";
    }

    std::string escape_markup_or_plain(const std::string& s) const { return markup_ ? escape_markup(s) : s; }

    /// The argument of \\text, \\mathrm and the like, which the engine shows as it is, as
    /// LaTeX: each character escaped, in math mode (\\mathrm) or text mode (\\text).
    std::string literal_latex(const std::string& inner, bool in_math) const {
        std::string out;
        for (std::size_t i = 0; i < inner.size();) {
            std::size_t end = i + 1;
            while (end < inner.size() && (static_cast<unsigned char>(inner[end]) & 0xc0) == 0x80) ++end;
            const std::string ch = inner.substr(i, end - i);
            i = end;
            if (in_math) {
                out += ch == " " ? "\\ " : math_character(ch, std::string(tex_));
            } else {
                out += ch.size() > 1 ? text_latex(ch) : text(ch);
            }
        }
        return out;
    }

    std::string_view tex_;
    bool markup_;
    bool latex_;
    std::size_t pos_ = 0;
    int script_depth_ = 0;
    int depth_ = 0;
    atom_facts last_;  // what the last atom was
};

/// One piece of parsed markup: a character (italic or not) or a script with its contents.
struct markup_node {
    enum class kind { character, sub, sup } type = kind::character;
    std::string text;  // one UTF-8 character
    bool italic = false;
    std::vector<markup_node> inner;
};

/// Pango markup as characters and scripts; <span>, <b> and the like carry nothing LaTeX needs.
class markup_parser {
public:
    explicit markup_parser(std::string_view m) : m_(m) {}

    std::vector<markup_node> parse(const std::string& until = "") {
        std::vector<markup_node> out;
        while (pos_ < m_.size()) {
            if (m_[pos_] != '<') {
                out.push_back(character());
                continue;
            }
            const std::size_t end = m_.find('>', pos_);
            if (end == std::string_view::npos) throw bad_input("unclosed tag in '" + std::string(m_) + "'");
            const std::string tag(m_.substr(pos_ + 1, end - pos_ - 1));
            pos_ = end + 1;
            if (!until.empty() && tag == until) return out;
            if (tag == "i") ++italic_;
            if (tag == "/i") --italic_;
            if (tag == "sub" || tag == "sup") {
                markup_node n;
                n.type = tag == "sub" ? markup_node::kind::sub : markup_node::kind::sup;
                n.inner = parse(std::string("/").append(tag));
                out.push_back(std::move(n));
            }
        }
        return out;
    }

private:
    /// The character or entity at pos_, italic or not.
    markup_node character() {
        markup_node n;
        n.italic = italic_ > 0;
        if (m_[pos_] == '&') {
            const std::size_t end = m_.find(';', pos_);
            const std::string entity(m_.substr(pos_ + 1, end == std::string_view::npos ? 0 : end - pos_ - 1));
            pos_ = end == std::string_view::npos ? m_.size() : end + 1;
            const char c = entity == "amp" ? '&' : entity == "lt" ? '<' : entity == "gt" ? '>' : entity == "quot" ? '"' : '\'';
            n.text.assign(1, c);
        } else {
            std::size_t end = pos_ + 1;
            while (end < m_.size() && (static_cast<unsigned char>(m_[end]) & 0xc0) == 0x80) ++end;
            n.text = std::string(m_.substr(pos_, end - pos_));
            pos_ = end;
        }
        return n;
    }

    std::string_view m_;
    std::size_t pos_ = 0;
    int italic_ = 0;
};

/// A character in math mode.
std::string math_character(const std::string& c, const std::string& whole) {
    if (c.size() == 1) {
        static const std::string specials = "%#&$_{}";
        if (specials.find(c[0]) != std::string::npos) return "\\" + c;
        if (c == "~") return "\\sim ";
        if (c == "^") return "\\hat{}";
        if (c == "\\") return "\\backslash ";
        return c;
    }
    static const std::pair<std::string_view, std::string_view> extra[] = {
        {"\u2212", "-"},          {"\u2032", "'"},         {"\u02b9", "'"},          {"\u2033", "''"},
        {"\u2034", "'''"},        {"\u00b0", "^{\\circ}"}, {"\u2217", "*"},          {"\u2009", "\\,"},
        {"\u2005", "\\;"},        {"\u2003", "\\quad "},   {"\u2016", "\\|"},        {"\u22c5", "\\cdot "},
        {"\u00b7", "\\cdot "},    {"\u2218", "\\circ "},   {"\u00a0", "~"}};
    for (const auto& [from, to] : extra) {
        if (c == from) return std::string(to);
    }
    for (const auto& m : macro_table) {
        if (m.kind == macro_kind::symbol && m.markup == c && static_cast<unsigned char>(m.markup[0]) >= 0x80) {
            return std::string(m.latex);
        }
    }
    throw bad_input("label '" + whole + "': no LaTeX for the character '" + c + "'");
}

std::string math_of(const std::vector<markup_node>& nodes, const std::string& whole) {
    std::string out;
    for (const auto& n : nodes) {
        if (n.type == markup_node::kind::character) {
            out += math_character(n.text, whole);
            continue;
        }
        const bool primes = !n.inner.empty() && std::all_of(n.inner.begin(), n.inner.end(), [](const markup_node& k) {
            return k.type == markup_node::kind::character && (k.text == "\u02b9" || k.text == "\u2032");
        });
        std::string inner;
        if (primes) {
            for (std::size_t i = 0; i < n.inner.size(); ++i) inner += "\\prime ";
        } else {
            inner = math_of(n.inner, whole);
        }
        out += (n.type == markup_node::kind::sub ? "_{" : "^{") + inner + "}";
    }
    return out;
}

/// Typographic characters of text mode, as LaTeX writes them.
std::string text_character(const std::string& c) {
    static const std::pair<std::string_view, std::string_view> text[] = {
        {"\u2013", "--"}, {"\u2014", "---"}, {"\u2019", "'"}, {"\u2018", "`"}, {"\u201c", "``"}, {"\u201d", "''"},
        {"\u00a0", "~"},  {"\u2009", "\\,"}};
    for (const auto& [from, to] : text) {
        if (c == from) return std::string(to);
    }
    // Latin letters with accents, as LaTeX's accent commands write them in the OT1 and T1 encodings.
    static const std::pair<std::string_view, std::string_view> letters[] = {
        {"\u00c0", "\\`{A}"}, {"\u00c1", "\\'{A}"}, {"\u00c2", "\\^{A}"}, {"\u00c3", "\\~{A}"},
        {"\u00c4", "\\\"{A}"}, {"\u00c5", "\\r{A}"}, {"\u00c6", "\\AE{}"}, {"\u00c7", "\\c{C}"},
        {"\u00c8", "\\`{E}"}, {"\u00c9", "\\'{E}"}, {"\u00ca", "\\^{E}"}, {"\u00cb", "\\\"{E}"},
        {"\u00cc", "\\`{I}"}, {"\u00cd", "\\'{I}"}, {"\u00ce", "\\^{I}"}, {"\u00cf", "\\\"{I}"},
        {"\u00d1", "\\~{N}"}, {"\u00d2", "\\`{O}"}, {"\u00d3", "\\'{O}"}, {"\u00d4", "\\^{O}"},
        {"\u00d5", "\\~{O}"}, {"\u00d6", "\\\"{O}"}, {"\u00d8", "\\O{}"}, {"\u00d9", "\\`{U}"},
        {"\u00da", "\\'{U}"}, {"\u00db", "\\^{U}"}, {"\u00dc", "\\\"{U}"}, {"\u00dd", "\\'{Y}"},
        {"\u00df", "\\ss{}"}, {"\u00e0", "\\`{a}"}, {"\u00e1", "\\'{a}"}, {"\u00e2", "\\^{a}"},
        {"\u00e3", "\\~{a}"}, {"\u00e4", "\\\"{a}"}, {"\u00e5", "\\r{a}"}, {"\u00e6", "\\ae{}"},
        {"\u00e7", "\\c{c}"}, {"\u00e8", "\\`{e}"}, {"\u00e9", "\\'{e}"}, {"\u00ea", "\\^{e}"},
        {"\u00eb", "\\\"{e}"}, {"\u00ec", "\\`{\\i}"}, {"\u00ed", "\\'{\\i}"}, {"\u00ee", "\\^{\\i}"},
        {"\u00ef", "\\\"{\\i}"}, {"\u00f1", "\\~{n}"}, {"\u00f2", "\\`{o}"}, {"\u00f3", "\\'{o}"},
        {"\u00f4", "\\^{o}"}, {"\u00f5", "\\~{o}"}, {"\u00f6", "\\\"{o}"}, {"\u00f8", "\\o{}"},
        {"\u00f9", "\\`{u}"}, {"\u00fa", "\\'{u}"}, {"\u00fb", "\\^{u}"}, {"\u00fc", "\\\"{u}"},
        {"\u00fd", "\\'{y}"}, {"\u00ff", "\\\"{y}"}, {"\u0100", "\\={A}"}, {"\u0101", "\\={a}"},
        {"\u0102", "\\u{A}"}, {"\u0103", "\\u{a}"}, {"\u0106", "\\'{C}"}, {"\u0107", "\\'{c}"},
        {"\u0108", "\\^{C}"}, {"\u0109", "\\^{c}"}, {"\u010a", "\\.{C}"}, {"\u010b", "\\.{c}"},
        {"\u010c", "\\v{C}"}, {"\u010d", "\\v{c}"}, {"\u010e", "\\v{D}"}, {"\u010f", "\\v{d}"},
        {"\u0112", "\\={E}"}, {"\u0113", "\\={e}"}, {"\u0114", "\\u{E}"}, {"\u0115", "\\u{e}"},
        {"\u0116", "\\.{E}"}, {"\u0117", "\\.{e}"}, {"\u011a", "\\v{E}"}, {"\u011b", "\\v{e}"},
        {"\u011c", "\\^{G}"}, {"\u011d", "\\^{g}"}, {"\u011e", "\\u{G}"}, {"\u011f", "\\u{g}"},
        {"\u0120", "\\.{G}"}, {"\u0121", "\\.{g}"}, {"\u0122", "\\c{G}"}, {"\u0123", "\\c{g}"},
        {"\u0124", "\\^{H}"}, {"\u0125", "\\^{h}"}, {"\u0128", "\\~{I}"}, {"\u0129", "\\~{\\i}"},
        {"\u012a", "\\={I}"}, {"\u012b", "\\={\\i}"}, {"\u012c", "\\u{I}"}, {"\u012d", "\\u{\\i}"},
        {"\u0130", "\\.{I}"}, {"\u0131", "\\i{}"}, {"\u0134", "\\^{J}"}, {"\u0135", "\\^{j}"},
        {"\u0136", "\\c{K}"}, {"\u0137", "\\c{k}"}, {"\u0139", "\\'{L}"}, {"\u013a", "\\'{l}"},
        {"\u013b", "\\c{L}"}, {"\u013c", "\\c{l}"}, {"\u013d", "\\v{L}"}, {"\u013e", "\\v{l}"},
        {"\u0141", "\\L{}"}, {"\u0142", "\\l{}"}, {"\u0143", "\\'{N}"}, {"\u0144", "\\'{n}"},
        {"\u0145", "\\c{N}"}, {"\u0146", "\\c{n}"}, {"\u0147", "\\v{N}"}, {"\u0148", "\\v{n}"},
        {"\u014c", "\\={O}"}, {"\u014d", "\\={o}"}, {"\u014e", "\\u{O}"}, {"\u014f", "\\u{o}"},
        {"\u0150", "\\H{O}"}, {"\u0151", "\\H{o}"}, {"\u0152", "\\OE{}"}, {"\u0153", "\\oe{}"},
        {"\u0154", "\\'{R}"}, {"\u0155", "\\'{r}"}, {"\u0156", "\\c{R}"}, {"\u0157", "\\c{r}"},
        {"\u0158", "\\v{R}"}, {"\u0159", "\\v{r}"}, {"\u015a", "\\'{S}"}, {"\u015b", "\\'{s}"},
        {"\u015c", "\\^{S}"}, {"\u015d", "\\^{s}"}, {"\u015e", "\\c{S}"}, {"\u015f", "\\c{s}"},
        {"\u0160", "\\v{S}"}, {"\u0161", "\\v{s}"}, {"\u0162", "\\c{T}"}, {"\u0163", "\\c{t}"},
        {"\u0164", "\\v{T}"}, {"\u0165", "\\v{t}"}, {"\u0168", "\\~{U}"}, {"\u0169", "\\~{u}"},
        {"\u016a", "\\={U}"}, {"\u016b", "\\={u}"}, {"\u016c", "\\u{U}"}, {"\u016d", "\\u{u}"},
        {"\u016e", "\\r{U}"}, {"\u016f", "\\r{u}"}, {"\u0170", "\\H{U}"}, {"\u0171", "\\H{u}"},
        {"\u0174", "\\^{W}"}, {"\u0175", "\\^{w}"}, {"\u0176", "\\^{Y}"}, {"\u0177", "\\^{y}"},
        {"\u0178", "\\\"{Y}"}, {"\u0179", "\\'{Z}"}, {"\u017a", "\\'{z}"}, {"\u017b", "\\.{Z}"},
        {"\u017c", "\\.{z}"}, {"\u017d", "\\v{Z}"}, {"\u017e", "\\v{z}"}};
    for (const auto& [from, to] : letters) {
        if (c == from) return std::string(to);
    }
    return "";
}

/// How LaTeX's text mode writes an ASCII character it would otherwise read as markup;
/// empty for one it sets as it is.
std::string_view text_escape(char c) {
    static const std::pair<char, std::string_view> escapes[] = {
        {'\\', "\\textbackslash{}"}, {'{', "\\{"},           {'}', "\\}"},           {'$', "\\$"},
        {'&', "\\&"},                {'#', "\\#"},           {'%', "\\%"},           {'_', "\\_"},
        {'^', "\\^{}"},              {'~', "\\~{}"},         {'|', "\\textbar{}"},   {'<', "\\textless{}"},
        {'>', "\\textgreater{}"}};
    for (const auto& [from, to] : escapes) {
        if (c == from) return to;
    }
    return {};
}

bool is_plain(const markup_node& n) {
    return n.type == markup_node::kind::character && !n.italic && n.text.size() == 1;
}

/// A word set in text mode: plain ASCII as text, anything else as math.
std::string text_of(const std::vector<markup_node>& nodes, const std::string& whole) {
    std::string out;
    std::vector<markup_node> math;
    const auto flush = [&] {
        if (!math.empty()) {
            out += '$';
            out += math_of(math, whole);
            out += '$';
        }
        math.clear();
    };
    for (const auto& n : nodes) {
        const std::string typographic = n.type == markup_node::kind::character && !n.italic ? text_character(n.text) : "";
        if (!typographic.empty()) {
            flush();
            out += typographic;
            continue;
        }
        if (!is_plain(n)) {
            math.push_back(n);
            continue;
        }
        flush();
        const std::string_view escaped = text_escape(n.text[0]);
        out += escaped.empty() ? n.text : std::string(escaped);
    }
    flush();
    return out;
}

}  // namespace

std::string text_problem(std::string_view text, std::size_t max_bytes) {
    if (text.size() > max_bytes) {
        return "has " + std::to_string(text.size()) + " bytes; at most " + std::to_string(max_bytes);
    }
    for (std::size_t i = 0; i < text.size();) {
        const auto [cp, length] = utf8_at(text, i);
        if (length == 0) {
            char shown[64];
            std::snprintf(shown, sizeof shown, "is not valid UTF-8 (byte 0x%02x at byte %zu)",
                          static_cast<unsigned char>(text[i]), i + 1);
            return shown;
        }
        if (cp < 0x20 || (cp >= 0x7f && cp <= 0x9f)) {
            return "has the control character " + code_point(cp) + " (text here is one line of printable characters)";
        }
        if ((cp >= 0xfdd0 && cp <= 0xfdef) || (cp & 0xfffe) == 0xfffe) {
            return "has the noncharacter " + code_point(cp) + ", which no document may hold";
        }
        i += length;
    }
    return {};
}

std::span<const tex_macro> tex_macros() { return macro_table; }

namespace {

/// Text for a man page: \ as \e, a leading . or ' kept from being a request, other
/// characters than ASCII as groff's \[uXXXX].
std::string roff_text(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const auto [cp, length] = utf8_at(text, i);
        if (length == 0) break;
        i += length;
        if (cp == '\\') {
            out += "\\e";
        } else if (cp == '-') {
            out += "\\-";
        } else if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else {
            char code[16];
            std::snprintf(code, sizeof code, "\\[u%04X]", static_cast<unsigned>(cp));
            out += code;
        }
    }
    // A tbl cell of only _ or = would be a rule.
    const bool guard = out.empty() || out[0] == '.' || out[0] == '\'' || out == "_" || out == "=";
    return guard ? "\\&" + out : out;
}

/// The spaces of the table, in words.
constexpr std::pair<std::string_view, std::string_view> spaces[] = {
    {"", "a negative thin space"}, {" ", "a space"}, {"\u2009", "a thin space, 1/6 em"},
    {"\u2005", "a medium space, 1/4 em"}, {"\u2003", "a space of 1 em"}, {"\u2003\u2003", "a space of 2 em"}};

/// What the man page says a macro draws.
std::string man_draws(const tex_macro& m) {
    switch (m.kind) {
        case macro_kind::symbol:
            for (const auto& [space, words] : spaces) {
                if (m.markup == space) return std::string(words);
            }
            return roff_text(m.markup) + (m.italic ? " (italic)" : "");
        case macro_kind::accent:
            return m.markup.empty() ? "a line over its argument" : roff_text(std::string("\u25cc") + std::string(m.markup)) + " over its argument";
        case macro_kind::font:
            return "its argument as it is, " + std::string(m.markup == "i" ? "italic" : m.markup == "b" ? "bold" : "upright");
        case macro_kind::function: return roff_text(m.markup);
    }
    return {};
}

}  // namespace

std::string tex_macros_man() {
    static const char* const kinds[] = {"symbol", "function", "accent", "font"};
    std::string out = ".TS\nl l l.\nmacro\tkind\tdraws\n_\n";
    for (const auto& m : macro_table) {
        out += roff_text("\\" + std::string(m.name)) + "\t" + kinds[static_cast<int>(m.kind)] + "\t" + man_draws(m) + "\n";
    }
    return out + ".TE\n";
}

std::string tex_to_markup(std::string_view tex) { return converter(tex, target::markup).run(); }

std::string tex_to_latex(std::string_view tex) { return converter(tex, target::latex).run(); }

label tex_label(std::string_view tex) {
    label l(converter(tex, target::markup).run());
    try {
        l.latex = tex_to_latex(tex);
    } catch (const std::invalid_argument&) {
        // A character LaTeX has no form for: the overlay, if one is written, names it.
        l.latex.clear();
    }
    return l;
}

std::string label_latex(const label& l) { return l.latex.empty() ? markup_to_latex(l.markup) : l.latex; }

label join(const label& a, const label& b) {
    label out(a.markup + b.markup);
    if (a.latex.empty() && b.latex.empty()) return out;
    // A program's markup loses the spaces at its ends on its way to LaTeX: keep them.
    const auto ends_spaced = [](const label& l) {
        std::string latex = label_latex(l);
        if (l.latex.empty() && l.markup.ends_with(' ') && !latex.ends_with(' ')) latex += ' ';
        if (l.latex.empty() && l.markup.starts_with(' ') && !latex.starts_with(' ')) latex.insert(0, 1, ' ');
        return latex;
    };
    try {
        out.latex = ends_spaced(a) + ends_spaced(b);
    } catch (const std::invalid_argument&) {
        out.latex.clear();
    }
    return out;
}

std::string markup_to_latex(std::string_view markup) {
    const std::string whole(markup);
    // Words (split at spaces) with a plain letter are text; the others, and runs of them,
    // are one piece of math, so that TeX spaces "T - 1" and "= pi/2" as math.
    std::vector<std::vector<markup_node>> words(1);
    for (auto& n : markup_parser(inline_fractions(whole)).parse()) {
        if (n.type == markup_node::kind::character && n.text == " ") {
            words.emplace_back();
        } else {
            words.back().push_back(std::move(n));
        }
    }
    std::string out;
    std::string math;
    const auto flush = [&] {
        if (!math.empty()) out += (out.empty() ? "$" : " $") + math + "$";
        math.clear();
    };
    for (const auto& w : words) {
        if (w.empty()) continue;
        const bool text = std::any_of(w.begin(), w.end(), [](const markup_node& n) {
            return is_plain(n) && std::isalpha(static_cast<unsigned char>(n.text[0]));
        });
        if (!text) {
            if (!math.empty()) math += ' ';
            math += math_of(w, whole);
            continue;
        }
        flush();
        if (!out.empty()) out += ' ';
        out += text_of(w, whole);
    }
    flush();
    return out;
}

std::string tex_to_plain(std::string_view tex) { return converter(tex, target::plain).run(); }

}  // namespace plot
