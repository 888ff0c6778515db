// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/tex_markup.hpp"

#include "plot/figure.hpp"

#include <array>
#include <cctype>
#include <stdexcept>
#include <utility>

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

class converter {
public:
    converter(std::string_view tex, bool markup) : tex_(tex), markup_(markup) {}

    std::string run() {
        std::string out;
        while (pos_ < tex_.size()) {
            const char c = tex_[pos_];
            if (c == '$') {
                ++pos_;
                out += math('$');
                if (pos_ >= tex_.size() || tex_[pos_] != '$') fail("unbalanced $");
                ++pos_;
            } else if (c == '\\' && pos_ + 1 < tex_.size() && (tex_[pos_ + 1] == '$' || tex_[pos_ + 1] == '\\')) {
                out += escape(std::string(1, tex_[pos_ + 1]));
                pos_ += 2;
            } else {
                out += escape(std::string(1, c));
                ++pos_;
            }
        }
        return out;
    }

private:
    [[noreturn]] void fail(const std::string& why) const {
        throw std::invalid_argument("label '" + std::string(tex_) + "': " + why);
    }

    std::string escape(const std::string& s) const { return markup_ ? escape_markup(s) : s; }
    std::string italic(const std::string& s) const { return markup_ ? "<i>" + s + "</i>" : s; }
    std::string wrap(const char* tag, const std::string& s) const {
        if (!markup_) return s;
        return std::string("<") + tag + ">" + s + "</" + tag + ">";
    }

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
            if ((binary || relation) && script_depth_ == 0) {
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
        skip_space();
        if (pos_ >= tex_.size()) fail("incomplete math");
        const char c = tex_[pos_];
        if (c == '{') {
            ++pos_;
            std::string inner = math('}');
            if (pos_ >= tex_.size()) fail("unbalanced {");
            ++pos_;
            return inner;
        }
        if (c == '\\') return macro();
        ++pos_;
        if (std::isalpha(static_cast<unsigned char>(c))) return italic(std::string(1, c));
        if (c == '-') return "\u2212";
        if (c == '*') return "\u2217";
        if (c == '\'') return "\u2032";
        if (static_cast<unsigned char>(c) >= 0x80) {
            // UTF-8 passes through whole: a typed ϑ or π is italic like its macro.
            std::size_t end = pos_;
            while (end < tex_.size() && (static_cast<unsigned char>(tex_[end]) & 0xc0) == 0x80) ++end;
            std::string ch(tex_.substr(pos_ - 1, end - pos_ + 1));
            pos_ = end;
            return ch == "\u03d1" || ch == "\u03c0" || ch == "\u03b8" ? italic(ch) : ch;
        }
        return escape(std::string(1, c));
    }

    std::string macro() {
        ++pos_;  // the backslash
        if (pos_ >= tex_.size()) fail("lone backslash");
        const char c = tex_[pos_];
        if (!std::isalpha(static_cast<unsigned char>(c))) {
            ++pos_;
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
            if (s.name == name) return s.italic ? italic(std::string(s.text)) : std::string(s.text);
        }
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
        if (name == "quad") return "\u2003";
        if (name == "qquad") return "\u2003\u2003";
        if (name == "left" || name == "right" || name == "big" || name == "Big") return atom();
        if (name == "mathrm" || name == "text" || name == "textrm" || name == "operatorname" || name == "mathit") {
            skip_space();
            if (pos_ >= tex_.size() || tex_[pos_] != '{') fail("\\" + name + " needs {...}");
            const std::size_t close = tex_.find('}', pos_);
            if (close == std::string_view::npos) fail("unbalanced {");
            const std::string inner(tex_.substr(pos_ + 1, close - pos_ - 1));
            pos_ = close + 1;
            return name == "mathit" ? italic(escape(inner)) : escape(inner);
        }
        fail("unknown macro \\" + name);
    }

    std::string_view tex_;
    bool markup_;
    std::size_t pos_ = 0;
    int script_depth_ = 0;
};

}  // namespace

std::string tex_to_markup(std::string_view tex) { return converter(tex, true).run(); }

std::string tex_to_plain(std::string_view tex) { return converter(tex, false).run(); }

}  // namespace plot
