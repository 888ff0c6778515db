// SPDX-License-Identifier: GPL-3.0-or-later
// The one parser of the core's expression languages: a precedence climber over a language's
// rows (expression_parser.hpp).
#include "pendulum/expression_parser.hpp"

#include "common/suggest.hpp"
#include "common/terminal_text.hpp"
#include "pendulum/angle.hpp"
#include "pendulum/expression_lexer.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace pendulum::grammar {

std::size_t invalid_utf8(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
        char32_t cp = 0;
        const std::size_t length = common::utf8_sequence(text.substr(i), cp);
        if (length == 0) return i;
        i += length;
    }
    return i;
}

namespace {

/// Rows with the same leaf joined by " or ", groups by ", ".
template <class Rows, class Same>
std::string grouped(const Rows& rows, Same same) {
    std::string out;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const bool joined = i > 0 && same(rows[i - 1], rows[i]);
        out += (i == 0 ? "" : joined ? " or " : ", ") + std::string(rows[i].name);
    }
    return out;
}

/// A byte that may start a name: a letter, "_", or the first byte of θ or π.
bool name_start(char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u < 0x80 && (std::isalpha(u) != 0)) || c == '_' || u == 0xce || u == 0xcf;
}

/// A byte that may go on an ASCII name.
bool name_byte(char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x80 && (std::isalnum(u) != 0 || c == '_');
}

/// \xNN for one byte.
std::string hex_byte(char c) {
    constexpr char hex[] = "0123456789abcdef";
    const auto u = static_cast<unsigned char>(c);
    return std::string("\\x") + hex[u >> 4] + hex[u & 15];
}

class parser {
public:
    parser(std::string_view text, const language& lang, std::vector<lexeme>* lexemes)
        : text_(text), lang_(lang), lexemes_(lexemes) {}

    tree run() {
        check_characters();
        skip_space();
        if (pos_ == text_.size()) fail(pos_, std::string(lang_.empty));
        expr(0);
        read_unit();
        skip_space();
        if (pos_ != text_.size()) {
            if (text_[pos_] == ')') fail(pos_, "unmatched ')'");
            fail(pos_, "unexpected '" + message_text(rest_word()) + "' after a complete expression");
        }
        return std::move(tree_);
    }

private:
    [[noreturn]] void fail(std::size_t at, const std::string& why) const {
        throw domain_error(lang_.message(text_, at, why));
    }

    void check_characters() const {
        if (text_.size() > lang_.max_bytes) {
            fail(lang_.max_bytes, std::string(lang_.a_noun) + " takes at most " + std::to_string(lang_.max_bytes) +
                                      " bytes, this one has " + std::to_string(text_.size()));
        }
        for (std::size_t i = 0; i < text_.size(); ++i) {
            const auto u = static_cast<unsigned char>(text_[i]);
            if (u < 0x20 || u == 0x7f) fail(i, "control character " + hex_byte(text_[i]) + " in " + std::string(lang_.a_noun));
        }
        if (const std::size_t bad = invalid_utf8(text_); bad < text_.size()) {
            fail(bad, "byte " + hex_byte(text_[bad]) + " is not UTF-8; write the " + std::string(lang_.noun) + " in UTF-8");
        }
    }

    void record(lexeme::kind k, std::size_t from, std::size_t to) {
        if (lexemes_) lexemes_->push_back({k, text_.substr(from, to - from)});
    }

    /// The next character (all its bytes), for a message.
    std::string rest_word() const {
        std::size_t end = pos_ + 1;
        while (end < text_.size() && (static_cast<unsigned char>(text_[end]) & 0xc0) == 0x80) ++end;
        return std::string(text_.substr(pos_, end - pos_));
    }

    void skip_space() { pos_ = lexer::skip_space(text_, pos_); }

    bool take(char c, lexeme::kind k) {
        skip_space();
        if (pos_ >= text_.size() || text_[pos_] != c) return false;
        record(k, pos_, pos_ + 1);
        ++pos_;
        return true;
    }

    int add(formula_node n) {
        if (tree_.nodes.size() >= lang_.max_nodes) {
            fail(pos_, std::string(lang_.a_noun) + " has at most " + std::to_string(lang_.max_nodes) +
                           " numbers, names and operations");
        }
        tree_.nodes.push_back(std::move(n));
        return static_cast<int>(tree_.nodes.size()) - 1;
    }

    int node(op what, int a, int b = -1) {
        formula_node n;
        n.what = what;
        n.a = a;
        n.b = b;
        return add(std::move(n));
    }

    /// One level of nesting (parentheses, a call, a sign, an exponent) for the rest of a call.
    struct nesting {
        nesting(parser& p, std::size_t at) : p_(p) {
            if (++p_.depth_ > p_.lang_.max_depth) {
                p_.fail(at, "nested too deeply (at most " + std::to_string(p_.lang_.max_depth) + " levels of " +
                                std::string(p_.lang_.nesting) + ")");
            }
        }
        ~nesting() { --p_.depth_; }
        nesting(const nesting&) = delete;
        nesting& operator=(const nesting&) = delete;
        parser& p_;
    };

    /// The operator row at pos, or null.
    const operator_row* next_operator() {
        skip_space();
        if (pos_ >= text_.size()) return nullptr;
        for (const auto& row : lang_.operators) {
            if (row.symbol == text_[pos_]) return &row;
        }
        return nullptr;
    }

    /// The unit row the rest of the text is (after spaces, to its end but for spaces), or null.
    const unit_row* unit_here() const {
        const std::size_t from = lexer::skip_space(text_, pos_);
        std::size_t to = text_.size();
        while (to > from && (text_[to - 1] == ' ' || text_[to - 1] == '\t')) --to;
        for (const auto& row : lang_.units) {
            if (text_.substr(from, to - from) == row.name) return &row;
        }
        return nullptr;
    }

    void read_unit() {
        const unit_row* row = unit_here();
        if (!row) return;
        skip_space();
        record(lexeme::kind::unit, pos_, pos_ + row->name.size());
        pos_ += row->name.size();
        tree_.what = row->what;
    }

    /// True where a primary starts here (a product without a sign: "2pi", "3(theta0)").
    bool starts_primary() {
        skip_space();
        return pos_ < text_.size() && (text_[pos_] == '(' || name_start(text_[pos_])) && !unit_here();
    }

    /// Operands joined by operators binding at least min_binding.
    int expr(int min_binding) {
        int v = operand();
        for (;;) {
            const std::size_t at = lexer::skip_space(text_, pos_);
            if (const operator_row* row = next_operator(); row && row->binding >= min_binding) {
                take(row->symbol, lexeme::kind::binary);
                if (row->right) {
                    const nesting level(*this, at);
                    v = node(row->what, v, expr(row->binding));
                } else {
                    v = node(row->what, v, expr(row->binding + 1));
                }
            } else if (implicit_binding >= min_binding && starts_primary()) {
                v = node(op::mul, v, expr(sign_binding + 1));
            } else {
                return v;
            }
        }
    }

    int operand() {
        skip_space();
        const std::size_t at = pos_;
        for (const char sign : {'-', '+'}) {
            if (!take(sign, lexeme::kind::sign)) continue;
            const nesting level(*this, at);
            const int v = expr(sign_binding);
            return sign == '-' ? node(op::neg, v) : v;
        }
        return primary();
    }

    int primary() {
        skip_space();
        const std::size_t at = pos_;
        if (pos_ == text_.size()) {
            fail(pos_, "incomplete " + std::string(lang_.noun) + ": a number, a name or '(' is missing at the end");
        }
        if (take('(', lexeme::kind::open)) {
            const nesting level(*this, at);
            const int v = expr(0);
            if (!take(')', lexeme::kind::close)) {
                fail(pos_, pos_ == text_.size() ? "missing ')' for the '(' at column " + column_of(at)
                                                : "expected ')' or an operator, not '" + message_text(rest_word()) + "'");
            }
            return v;
        }
        if (lexer::number_start(text_[pos_])) return number();
        if (name_start(text_[pos_])) return name();
        fail(pos_, "unexpected '" + message_text(rest_word()) + "'; expected a number, a name or '('");
    }

    std::string column_of(std::size_t at) const {
        std::size_t column = 1;
        for (std::size_t i = 0; i < at; ++i) {
            if ((static_cast<unsigned char>(text_[i]) & 0xc0) != 0x80) ++column;
        }
        return std::to_string(column);
    }

    int number() {
        const std::size_t start = pos_;
        const std::size_t end = lexer::number_end(text_, pos_);
        formula_node n;
        n.digits = std::string(text_.substr(start, end - start));
        if (!lexer::has_digit(lexer::mantissa_of(n.digits))) fail(start, "'" + n.digits + "' is not a number");
        errno = 0;
        n.value = std::strtod(n.digits.c_str(), nullptr);
        if (errno == ERANGE && std::isinf(n.value)) fail(start, "number " + n.digits + " is beyond a double's range");
        pos_ = end;
        record(lexeme::kind::number, start, end);
        return add(std::move(n));
    }

    /// A name: ASCII letters, digits and "_", or one character of several bytes (θ, π)
    /// followed by digits ("θ0"), so "πrad" is π and rad.
    std::string_view identifier() {
        const std::size_t start = pos_;
        if (static_cast<unsigned char>(text_[pos_]) >= 0x80) {
            ++pos_;
            while (pos_ < text_.size() && (static_cast<unsigned char>(text_[pos_]) & 0xc0) == 0x80) ++pos_;
            while (pos_ < text_.size() && lexer::digit(text_[pos_])) ++pos_;
        } else {
            while (pos_ < text_.size() && name_byte(text_[pos_])) ++pos_;
        }
        return text_.substr(start, pos_ - start);
    }

    [[noreturn]] void unknown(std::size_t at, std::string_view word) const {
        std::vector<std::string_view> known;
        for (const auto& f : lang_.functions) known.push_back(f.name);
        for (const auto& n : lang_.names) known.push_back(n.name);
        for (const auto& u : lang_.units) known.push_back(u.name);
        std::string why = "unknown name '" + message_text(word) + "'";
        if (const auto guess = common::nearest_name(word, known, 3); !guess.empty()) why += "; did you mean '" + guess + "'?";
        why += " (names: " + names_of(lang_);
        if (!lang_.functions.empty()) why += "; functions: " + functions_of(lang_);
        if (!lang_.units.empty()) why += "; units at the end: " + units_of(lang_);
        fail(at, why + ")");
    }

    int name() {
        const std::size_t at = pos_;
        const std::string_view word = identifier();
        skip_space();
        const bool call = pos_ < text_.size() && text_[pos_] == '(';
        for (const auto& f : lang_.functions) {
            if (f.name != word) continue;
            if (!call) fail(pos_, std::string(word) + " is a function: write " + std::string(word) + "(...)");
            record(lexeme::kind::name, at, at + word.size());
            return call_of(f, at);
        }
        for (const auto& [n, what] : lang_.names) {
            if (n != word) continue;
            if (what == op::t) tree_.uses_t = true;
            record(lexeme::kind::name, at, at + word.size());
            formula_node leaf;
            leaf.what = what;
            return add(std::move(leaf));
        }
        unknown(at, word);
    }

    int call_of(const function_row& f, std::size_t at) {
        const nesting level(*this, at);
        take('(', lexeme::kind::open);
        std::vector<int> args;
        std::vector<std::size_t> starts;
        for (;;) {
            starts.push_back(lexer::skip_space(text_, pos_));
            args.push_back(expr(0));
            if (take(',', lexeme::kind::comma)) continue;
            if (take(')', lexeme::kind::close)) break;
            fail(pos_, pos_ == text_.size() ? "missing ')' for " + std::string(f.name) + "("
                                            : "expected ',' or ')' in " + std::string(f.name) + "(...), not '" +
                                                  message_text(rest_word()) + "'");
        }
        if (static_cast<int>(args.size()) != f.arguments) {
            fail(at, std::string(f.name) + " takes " + std::to_string(f.arguments) +
                         (f.arguments == 1 ? " argument" : " arguments") + ", not " + std::to_string(args.size()));
        }
        formula_node n;
        n.what = f.what;
        n.a = args[0];
        if (f.arguments > 1) n.b = args[1];
        if (f.order_first) {
            n.order = order(f, args[0], starts[0]);
            n.a = args[1];
            n.b = -1;
        }
        return add(std::move(n));
    }

    /// An order_first argument: a constant whole number within the language's max_order.
    int order(const function_row& f, int arg, std::size_t at) const {
        const std::string call = std::string(f.name) + std::string(f.shown);
        if (uses_variable(arg)) fail(at, call + " needs n to be a constant whole number, not a formula in theta0 or t");
        const double n = lang_.constant(tree_.nodes, arg);
        if (!(n == std::nearbyint(n)) || std::fabs(n) > lang_.max_order) {
            fail(at, call + " takes a whole number n with |n| <= " + std::to_string(lang_.max_order) + ", not " + format_double(n));
        }
        return static_cast<int>(n);
    }

    bool uses_variable(int i) const {
        if (i < 0) return false;
        const auto& n = tree_.nodes[static_cast<std::size_t>(i)];
        return n.what == op::theta0 || n.what == op::t || uses_variable(n.a) || uses_variable(n.b);
    }

    std::string_view text_;
    const language& lang_;
    std::vector<lexeme>* lexemes_;
    tree tree_;
    std::size_t pos_ = 0;
    int depth_ = 0;
};

}  // namespace

tree parse(std::string_view text, const language& lang, std::vector<lexeme>* lexemes) {
    return parser(text, lang, lexemes).run();
}

std::string names_of(const language& lang) {
    return grouped(lang.names, [](const name_row& a, const name_row& b) { return a.what == b.what; });
}

std::string units_of(const language& lang) {
    return grouped(lang.units, [](const unit_row& a, const unit_row& b) { return a.what == b.what; });
}

std::string functions_of(const language& lang) {
    std::string out;
    for (const auto& f : lang.functions) out += (out.empty() ? "" : ", ") + std::string(f.name) + std::string(f.shown);
    if (!lang.functions_note.empty()) out += " " + std::string(lang.functions_note);
    return out;
}

}  // namespace pendulum::grammar
