// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/tex_markup.hpp"

#include "plot/errors.hpp"
#include "plot/figure.hpp"

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

struct symbol {
    std::string_view name;
    std::string_view text;
    bool italic;
};

// Lowercase Greek is italic in TeX's math, uppercase upright.
constexpr std::array<symbol, 62> symbols = {{
    {"alpha", "\u03b1", true},     {"beta", "\u03b2", true},     {"gamma", "\u03b3", true},
    {"delta", "\u03b4", true},     {"epsilon", "\u03f5", true},  {"varepsilon", "\u03b5", true},
    {"zeta", "\u03b6", true},      {"eta", "\u03b7", true},      {"theta", "\u03b8", true},
    {"vartheta", "\u03d1", true},  {"iota", "\u03b9", true},     {"kappa", "\u03ba", true},
    {"lambda", "\u03bb", true},    {"mu", "\u03bc", true},       {"nu", "\u03bd", true},
    {"xi", "\u03be", true},        {"pi", "\u03c0", true},       {"rho", "\u03c1", true},
    {"sigma", "\u03c3", true},     {"tau", "\u03c4", true},      {"upsilon", "\u03c5", true},
    {"phi", "\u03d5", true},       {"varphi", "\u03c6", true},   {"chi", "\u03c7", true},
    {"psi", "\u03c8", true},       {"omega", "\u03c9", true},    {"Gamma", "\u0393", false},
    {"Delta", "\u0394", false},    {"Theta", "\u0398", false},   {"Lambda", "\u039b", false},
    {"Xi", "\u039e", false},       {"Pi", "\u03a0", false},      {"Sigma", "\u03a3", false},
    {"Phi", "\u03a6", false},      {"Psi", "\u03a8", false},     {"Omega", "\u03a9", false},
    {"cdot", "\u22c5", false},     {"times", "\u00d7", false},   {"pm", "\u00b1", false},
    {"mp", "\u2213", false},       {"le", "\u2264", false},      {"leq", "\u2264", false},
    {"ge", "\u2265", false},       {"geq", "\u2265", false},     {"approx", "\u2248", false},
    {"sim", "\u223c", false},      {"infty", "\u221e", false},   {"circ", "\u2218", false},
    {"prime", "\u2032", false},    {"ldots", "\u2026", false},   {"dots", "\u2026", false},
    {"to", "\u2192", false},       {"propto", "\u221d", false},  {"partial", "\u2202", true},
    {"ln", "ln", false},           {"log", "log", false},        {"exp", "exp", false},
    {"sin", "sin", false},         {"cos", "cos", false},        {"tan", "tan", false},
    {"lvert", "|", false},         {"rvert", "|", false},
}};

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
            } else {
                out += text(std::string(1, c));
                ++pos_;
            }
        }
        return out;
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

    /// Math up to `closing` ('$' or '}'), which is left for the caller. Spaces in the
    /// source are ignored, as TeX does; binary + and - and the relations get a space each
    /// side, a sign (unary + or -) none, and nothing in scripts.
    std::string math(char closing) {
        std::string out;
        bool after_operand = false;
        for (;;) {
            skip_space();
            if (pos_ >= tex_.size()) return out;
            const char c = tex_[pos_];
            if (c == closing) return out;
            if (c == '$' || c == '}') fail(c == '$' ? "unbalanced $" : "unbalanced }");
            const bool binary = (c == '+' || c == '-') && after_operand;
            const bool relation = c == '=' || c == '<' || c == '>';
            std::string item = atom_with_scripts();
            if ((binary || relation) && script_depth_ == 0 && !latex_) {
                out += " " + item + " ";
                after_operand = false;
            } else {
                out += item;
                after_operand = !(c == '(' || c == '+' || c == '-' || c == '/' || c == '*' || c == ',');
            }
        }
    }

    /// One atom and the primes and scripts that follow it.
    std::string atom_with_scripts() {
        std::string base = atom();
        int primes = 0;
        while (pos_ < tex_.size() && tex_[pos_] == '\'') {
            ++primes;
            ++pos_;
        }
        std::string sub;
        std::string sup;
        bool has_sub = false;
        bool has_sup = false;
        for (int i = 0; i < 2 && pos_ < tex_.size() && (tex_[pos_] == '_' || tex_[pos_] == '^'); ++i) {
            const bool is_sub = tex_[pos_] == '_';
            ++pos_;
            if ((is_sub && has_sub) || (!is_sub && has_sup)) fail("double script");
            skip_space();
            if (pos_ >= tex_.size() || tex_[pos_] == '$' || tex_[pos_] == '}') fail("script without an argument");
            if (tex_[pos_] == '^' || tex_[pos_] == '_') fail("double script");
            ++script_depth_;
            (is_sub ? sub : sup) = atom();
            --script_depth_;
            (is_sub ? has_sub : has_sup) = true;
        }
        if (latex_) {
            // TeX's ' is ^\prime: primes and a superscript share one superscript.
            std::string out = base;
            if (has_sup) {
                std::string up;
                for (int i = 0; i < primes; ++i) up += "\\prime ";
                out += "^" + script(up + ungrouped(sup));
            } else {
                out += std::string(static_cast<std::size_t>(primes), '\'');
            }
            if (has_sub) out += "_" + script(ungrouped(sub));
            return out;
        }
        std::string out = base;
        if (primes > 0) {
            // Computer Modern Unicode has the modifier letter prime (U+02B9), not the prime.
            static const char* const marks[] = {"\u02b9", "\u02b9\u02b9", "\u02b9\u02b9\u02b9"};
            static const char* const plain[] = {"\u2032", "\u2033", "\u2034"};
            if (markup_ && primes <= 3) {
                // TeX's prime is a superscript: the renderer stacks the subscript under it.
                sup = marks[primes - 1] + (has_sup ? sup : "");
                has_sup = true;
            } else {
                out += primes <= 3 ? plain[primes - 1] : std::string(primes, '\'');
            }
        }
        // ^\circ is the degree sign.
        if (has_sup) out += sup == "\u2218" ? std::string("\u00b0") : wrap("sup", sup);
        if (has_sub) out += wrap("sub", sub);
        return out;
    }

    void skip_space() {
        while (pos_ < tex_.size() && tex_[pos_] == ' ') ++pos_;
    }

    /// A letter, digit, symbol, macro or braced group.
    std::string atom() {
        const nesting level(*this);
        skip_space();
        if (pos_ >= tex_.size()) fail("incomplete math");
        const char c = tex_[pos_];
        if (c == '{') {
            ++pos_;
            std::string inner = math('}');
            if (pos_ >= tex_.size()) fail("unbalanced {");
            ++pos_;
            return latex_ ? "{" + inner + "}" : inner;
        }
        if (c == '\\') return macro();
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
            return c == '\'' ? "{}^{\\prime}" : escape(std::string(1, c));
        }
        if (c == '-') return "\u2212";
        if (c == '*') return "\u2217";
        if (c == '\'') return "\u2032";
        return escape(std::string(1, c));
    }

    std::string macro() {
        ++pos_;  // the backslash
        if (pos_ >= tex_.size()) fail("lone backslash");
        const char c = tex_[pos_];
        if (!std::isalpha(static_cast<unsigned char>(c))) {
            ++pos_;
            if (latex_) {
                // The spaces and escaped characters this file knows, and nothing else.
                static const std::string_view known = ",:>;! {}%$&#_|";
                if (known.find(c) == std::string_view::npos) fail(std::string("unknown macro \\") + c);
                return c == ' ' ? "\\ " : std::string("\\") + c;
            }
            switch (c) {
                case ',': return "\u2009";
                case ':':
                case '>':
                case ';': return "\u2005";
                case '!': return "";
                case ' ': return " ";
                case '{':
                case '}':
                case '%':
                case '$':
                case '&':
                case '#':
                case '_': return escape(std::string(1, c));
                case '|': return "\u2016";
                default: fail(std::string("unknown macro \\") + c);
            }
        }
        std::size_t end = pos_;
        while (end < tex_.size() && std::isalpha(static_cast<unsigned char>(tex_[end]))) ++end;
        const std::string name(tex_.substr(pos_, end - pos_));
        pos_ = end;
        for (const auto& s : symbols) {
            if (s.name == name) {
                if (latex_) return "\\" + std::string(s.name) + " ";
                return s.italic ? italic(std::string(s.text)) : std::string(s.text);
            }
        }
        if (latex_ && (name == "dot" || name == "ddot")) return "\\" + name + "{" + atom() + "}";
        if (name == "dot" || name == "ddot") {
            // A combining dot or diaeresis, inside the italic of the letter it sits on.
            std::string base = atom();
            const std::string mark = name == "dot" ? "\u0307" : "\u0308";
            const std::string close = "</i>";
            if (markup_ && base.size() > close.size() && base.ends_with(close)) {
                return base.insert(base.size() - close.size(), mark);
            }
            return base + mark;
        }
        if (name == "quad" || name == "qquad") return latex_ ? "\\" + name + " " : name == "quad" ? "\u2003" : "\u2003\u2003";
        // The engine draws a delimiter at the size of the text: so does the overlay.
        if (name == "left" || name == "right" || name == "big" || name == "Big") return atom();
        if (name == "mathrm" || name == "text" || name == "textrm" || name == "operatorname" || name == "mathit") {
            skip_space();
            if (pos_ >= tex_.size() || tex_[pos_] != '{') fail("\\" + name + " needs {...}");
            const std::size_t close = tex_.find('}', pos_);
            if (close == std::string_view::npos) fail("unbalanced {");
            const std::string inner(tex_.substr(pos_ + 1, close - pos_ - 1));
            pos_ = close + 1;
            if (latex_) return "\\" + name + "{" + literal_latex(inner, name == "mathrm" || name == "mathit" || name == "operatorname") + "}";
            return name == "mathit" ? italic(escape_markup_or_plain(inner)) : escape_markup_or_plain(inner);
        }
        fail("unknown macro \\" + name);
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
            if (m_[pos_] == '<') {
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
                continue;
            }
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
            out.push_back(std::move(n));
        }
        return out;
    }

private:
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
    for (const auto& sym : symbols) {
        if (sym.text == c && static_cast<unsigned char>(sym.text[0]) >= 0x80) return "\\" + std::string(sym.name) + " ";
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
    for (auto& n : markup_parser(markup).parse()) {
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
