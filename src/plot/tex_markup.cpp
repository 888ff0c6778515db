// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/tex_markup.hpp"

#include "plot/errors.hpp"
#include "plot/figure.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <mutex>
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
        throw bad_input("label '" + std::string(tex_) + "': " + why);
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

/// The TeX each markup was made from, for LaTeX overlays that set labels verbatim. One map
/// for the process: markup is made while a figure is built and read while it is drawn.
std::map<std::string, std::string>& sources(std::unique_lock<std::mutex>& lock) {
    static std::mutex mutex;
    static std::map<std::string, std::string> map;
    lock = std::unique_lock(mutex);
    return map;
}

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
                    n.inner = parse("/" + tag);
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
                n.text = entity == "amp" ? "&" : entity == "lt" ? "<" : entity == "gt" ? ">" : entity == "quot" ? "\"" : "'";
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

/// A label's TeX as LaTeX: the same, with what the label language reads as a literal
/// character (%, #, &, ~, _ and ^ outside math, UTF-8 letters) escaped for LaTeX.
std::string label_as_latex(const std::string& tex) {
    std::string out;
    bool math = false;
    for (std::size_t i = 0; i < tex.size();) {
        const char c = tex[i];
        if (c == '\\' && i + 1 < tex.size()) {
            // A macro, or an escaped character, passes as it is (\$ and \\ included).
            out += tex.substr(i, 2);
            i += 2;
            continue;
        }
        if (c == '$') {
            math = !math;
            out += c;
            ++i;
            continue;
        }
        if (static_cast<unsigned char>(c) >= 0x80) {
            std::size_t end = i + 1;
            while (end < tex.size() && (static_cast<unsigned char>(tex[end]) & 0xc0) == 0x80) ++end;
            const std::string ch = tex.substr(i, end - i);
            const std::string t = math ? "" : text_character(ch);
            out += !t.empty() ? t : math ? math_character(ch, tex) : "$" + math_character(ch, tex) + "$";
            i = end;
            continue;
        }
        // Outside math, as text mode writes it (a lone backslash at the end is a literal one:
        // raw, it would escape the brace after it); in math only %, # and & need a backslash.
        const std::string_view escaped = math ? std::string_view() : text_escape(c);
        if (!escaped.empty()) {
            out += escaped;
        } else if (math && (c == '%' || c == '#' || c == '&')) {
            out += std::string("\\") + c;
        } else {
            out += c;
        }
        ++i;
    }
    return out;
}

bool is_plain(const markup_node& n) {
    return n.type == markup_node::kind::character && !n.italic && n.text.size() == 1;
}

/// A word set in text mode: plain ASCII as text, anything else as math.
std::string text_of(const std::vector<markup_node>& nodes, const std::string& whole) {
    std::string out;
    std::vector<markup_node> math;
    const auto flush = [&] {
        if (!math.empty()) out += "$" + math_of(math, whole) + "$";
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

std::string tex_to_markup(std::string_view tex) {
    std::string markup = converter(tex, true).run();
    std::unique_lock<std::mutex> lock;
    sources(lock).emplace(markup, std::string(tex));
    return markup;
}

std::string markup_to_latex(std::string_view markup) {
    const std::string whole(markup);
    {
        std::unique_lock<std::mutex> lock;
        const auto& map = sources(lock);
        if (const auto it = map.find(whole); it != map.end()) return label_as_latex(it->second);
    }
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
            math += (math.empty() ? "" : " ") + math_of(w, whole);
            continue;
        }
        flush();
        out += (out.empty() ? "" : " ") + text_of(w, whole);
    }
    flush();
    return out;
}

std::string tex_to_plain(std::string_view tex) { return converter(tex, false).run(); }

}  // namespace plot
