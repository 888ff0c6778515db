// SPDX-License-Identifier: GPL-3.0-or-later
// The formula language: a recursive-descent parser into a flat tree, and its evaluation in
// doubles. The grammar (lowest precedence first):
//   sum     = product { ("+" | "-") product }
//   product = unary { ("*" | "/") unary | power }      (a power right after: "2pi", "3(x)")
//   unary   = ("-" | "+") unary | power                 ("-2^2" is -(2^2), as in maths)
//   power   = primary [ "^" unary ]                     (right-associative: 2^3^2 = 2^9)
//   primary = number | name | name "(" sum { "," sum } ")" | "(" sum ")"
#include "pendulum/formula.hpp"

#include "common/suggest.hpp"
#include "pendulum/angle.hpp"
#include "pendulum/expression_lexer.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <utility>

namespace pendulum {

namespace {

using op = formula_node::op;

/// A function a formula may call: its name, operation and number of arguments.
struct function_row {
    std::string_view name;
    op what;
    int arguments;
};

constexpr std::array<function_row, 18> functions = {{
    {"sqrt", op::sqrt, 1},   {"exp", op::exp, 1},       {"log", op::log, 1},       {"sin", op::sin, 1},
    {"cos", op::cos, 1},     {"tan", op::tan, 1},       {"asin", op::asin, 1},     {"acos", op::acos, 1},
    {"atan", op::atan, 1},   {"sinh", op::sinh, 1},     {"cosh", op::cosh, 1},     {"tanh", op::tanh, 1},
    {"abs", op::abs, 1},     {"ellipk", op::ellipk, 1}, {"ellipe", op::ellipe, 1}, {"agm", op::agm, 2},
    {"besselj", op::besselj, 2}, {"pi", op::pi, 0},
}};

/// The variables and constants by name ("θ0" and "π" are their Greek spellings).
constexpr std::array<std::pair<std::string_view, op>, 5> names = {{
    {"theta0", op::theta0}, {"\u03b80", op::theta0}, {"t", op::t}, {"pi", op::pi}, {"\u03c0", op::pi},
}};

/// The nearest known name within two edits, or empty.
std::string nearest_name(std::string_view word) {
    std::vector<std::string_view> known;
    for (const auto& f : functions) known.push_back(f.name);
    known.push_back("theta0");
    known.push_back("t");
    return common::nearest_name(word, known, 3);
}

/// A byte that may start a name: a letter, "_", or the first byte of θ or π.
bool name_start(char c) {
    const auto u = static_cast<unsigned char>(c);
    return std::isalpha(u) || c == '_' || u == 0xce || u == 0xcf;
}


class parser {
public:
    parser(std::string_view text, std::vector<formula_node>& nodes) : text_(text), nodes_(nodes) {}

    /// Parses the whole text; returns true where it uses t.
    bool parse_all() {
        check_characters();
        skip_space();
        if (pos_ == text_.size()) fail(pos_, "empty formula; write T/T0 in theta0, e.g. 1/sqrt(cos(theta0/2))");
        sum();
        skip_space();
        if (pos_ != text_.size()) {
            if (text_[pos_] == ')') fail(pos_, "unmatched ')'");
            fail(pos_, "unexpected '" + message_text(rest_word()) + "' after a complete expression");
        }
        return uses_t_;
    }

private:
    /// "formula:1:COLUMN: why": the column counts characters from 1.
    [[noreturn]] void fail(std::size_t at, const std::string& why) const {
        std::size_t column = 1;
        for (std::size_t i = 0; i < at && i < text_.size(); ++i) {
            if ((static_cast<unsigned char>(text_[i]) & 0xc0) != 0x80) ++column;
        }
        throw domain_error("formula:1:" + std::to_string(column) + ": " + why);
    }

    void check_characters() const {
        if (text_.size() > max_formula_bytes) {
            fail(max_formula_bytes, "a formula takes at most " + std::to_string(max_formula_bytes) + " bytes, this one has " +
                                        std::to_string(text_.size()));
        }
        for (std::size_t i = 0; i < text_.size(); ++i) {
            const auto u = static_cast<unsigned char>(text_[i]);
            if (u < 0x20 || u == 0x7f) fail(i, "control character " + message_text(text_.substr(i, 1)) + " in a formula");
        }
    }

    /// The next few characters, for a message.
    std::string rest_word() const {
        std::size_t end = pos_ + 1;
        while (end < text_.size() && (static_cast<unsigned char>(text_[end]) & 0xc0) == 0x80) ++end;
        return std::string(text_.substr(pos_, end - pos_));
    }

    void skip_space() { pos_ = lexer::skip_space(text_, pos_); }

    bool take(char c) {
        skip_space();
        if (pos_ < text_.size() && text_[pos_] == c) {
            ++pos_;
            return true;
        }
        return false;
    }

    int add(formula_node n) {
        if (nodes_.size() >= max_formula_nodes) {
            fail(pos_, "a formula has at most " + std::to_string(max_formula_nodes) + " numbers, names and operations");
        }
        nodes_.push_back(std::move(n));
        return static_cast<int>(nodes_.size()) - 1;
    }

    int binary(op what, int a, int b) {
        formula_node n;
        n.what = what;
        n.a = a;
        n.b = b;
        return add(std::move(n));
    }

    /// One level of nesting (parentheses, a call, a sign, an exponent) for the rest of a call.
    struct nesting {
        nesting(parser& p, std::size_t at) : p_(p) {
            if (++p_.depth_ > max_formula_depth) {
                p_.fail(at, "nested too deeply (at most " + std::to_string(max_formula_depth) +
                                " levels of parentheses, calls, signs and exponents)");
            }
        }
        ~nesting() { --p_.depth_; }
        nesting(const nesting&) = delete;
        nesting& operator=(const nesting&) = delete;
        parser& p_;
    };

    int sum() {
        int v = product();
        for (;;) {
            if (take('+')) {
                v = binary(op::add, v, product());
            } else if (take('-')) {
                v = binary(op::sub, v, product());
            } else {
                return v;
            }
        }
    }

    /// True where a primary starts here (an implicit product: "2pi", "3(theta0)").
    bool starts_primary() {
        skip_space();
        return pos_ < text_.size() && (text_[pos_] == '(' || name_start(text_[pos_]));
    }

    int product() {
        int v = unary();
        for (;;) {
            if (take('*')) {
                v = binary(op::mul, v, unary());
            } else if (take('/')) {
                v = binary(op::div, v, unary());
            } else if (starts_primary()) {
                v = binary(op::mul, v, power());
            } else {
                return v;
            }
        }
    }

    int unary() {
        skip_space();
        const std::size_t at = pos_;
        if (take('-')) {
            const nesting level(*this, at);
            return binary(op::neg, unary(), -1);
        }
        if (take('+')) {
            const nesting level(*this, at);
            return unary();
        }
        return power();
    }

    int power() {
        const int base = primary();
        skip_space();
        const std::size_t at = pos_;
        if (!take('^')) return base;
        const nesting level(*this, at);
        return binary(op::pow, base, unary());
    }

    int primary() {
        skip_space();
        const std::size_t at = pos_;
        if (pos_ == text_.size()) fail(pos_, "incomplete formula: a number, a name or '(' is missing at the end");
        if (take('(')) {
            const nesting level(*this, at);
            const int v = sum();
            if (!take(')')) fail(pos_, pos_ == text_.size() ? "missing ')' for the '(' at column " + column_of(at)
                                                            : "expected ')' or an operator, not '" + message_text(rest_word()) + "'");
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
        const std::string mantissa = lexer::mantissa_of(text_.substr(start, end - start));
        if (!lexer::has_digit(mantissa)) fail(start, "'" + mantissa + "' is not a number");
        formula_node n;
        n.digits = std::string(text_.substr(start, end - start));
        errno = 0;
        n.value = std::strtod(n.digits.c_str(), nullptr);
        if (errno == ERANGE && std::isinf(n.value)) fail(start, "number " + n.digits + " is beyond a double's range");
        pos_ = end;
        return add(std::move(n));
    }

    std::string_view identifier() {
        const std::size_t start = pos_;
        while (pos_ < text_.size()) {
            const auto u = static_cast<unsigned char>(text_[pos_]);
            if (std::isalnum(u) || text_[pos_] == '_') {
                ++pos_;
            } else if (u >= 0x80) {
                // A character of several bytes (θ, π) is taken whole, so a message shows it whole.
                ++pos_;
                while (pos_ < text_.size() && (static_cast<unsigned char>(text_[pos_]) & 0xc0) == 0x80) ++pos_;
            } else {
                break;
            }
        }
        return text_.substr(start, pos_ - start);
    }

    [[noreturn]] void unknown(std::size_t at, std::string_view word) const {
        std::string why = "unknown name '" + message_text(word) + "'";
        if (const auto guess = nearest_name(word); !guess.empty()) why += "; did you mean '" + guess + "'?";
        fail(at, why + " (names: theta0 or \u03b80, t, pi or \u03c0; functions: " + formula_functions() + ")");
    }

    int name() {
        const std::size_t at = pos_;
        const std::string_view word = identifier();
        skip_space();
        const bool call = pos_ < text_.size() && text_[pos_] == '(';
        for (const auto& f : functions) {
            if (f.name == word && f.arguments > 0) {
                if (!call) fail(pos_, std::string(word) + " is a function: write " + std::string(word) + "(...)");
                return call_of(f, at);
            }
        }
        for (const auto& [n, what] : names) {
            if (n != word) continue;
            if (what == op::t) uses_t_ = true;
            formula_node node;
            node.what = what;
            return add(std::move(node));
        }
        unknown(at, word);
    }

    int call_of(const function_row& f, std::size_t at) {
        const nesting level(*this, at);
        take('(');
        std::vector<int> args;
        std::vector<std::size_t> starts;
        for (;;) {
            skip_space();
            starts.push_back(pos_);
            args.push_back(sum());
            if (take(',')) continue;
            if (take(')')) break;
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
        if (f.what == op::agm) n.b = args[1];
        if (f.what == op::besselj) {
            n.order = bessel_order(args[0], starts[0]);
            n.a = args[1];
        }
        return add(std::move(n));
    }

    /// besselj's n: a constant whole number within max_bessel_order.
    int bessel_order(int arg, std::size_t at) const {
        if (uses_variable(arg)) fail(at, "besselj(n, x) needs n to be a constant whole number, not a formula in theta0 or t");
        const double n = evaluate(nodes_, arg, 0, 0);
        if (!(n == std::nearbyint(n)) || std::fabs(n) > max_bessel_order) {
            fail(at, "besselj(n, x) takes a whole number n with |n| <= " + std::to_string(max_bessel_order) +
                         ", not " + format_double(n));
        }
        return static_cast<int>(n);
    }

    bool uses_variable(int i) const {
        if (i < 0) return false;
        const auto& n = nodes_[static_cast<std::size_t>(i)];
        return n.what == op::theta0 || n.what == op::t || uses_variable(n.a) || uses_variable(n.b);
    }

public:
    /// The double value of node i (declared here so that bessel_order can use it).
    static double evaluate(const std::vector<formula_node>& nodes, int i, double theta0, double t);

private:
    std::string_view text_;
    std::vector<formula_node>& nodes_;
    std::size_t pos_ = 0;
    int depth_ = 0;
    bool uses_t_ = false;
};

// ---- Doubles.

double agm_double(double a, double b) {
    if (std::isnan(a) || std::isnan(b) || a < 0 || b < 0) return std::nan("");
    if (a == 0 || b == 0) return 0;
    if (std::isinf(a) || std::isinf(b)) return std::numeric_limits<double>::infinity();
    for (int i = 0; i < 100 && a != b; ++i) {
        const double next = (a + b) / 2;
        b = std::sqrt(a * b);
        if (next == a) break;
        a = next;
    }
    return a;
}

double ellipk_double(double m) {
    if (m == 1) return std::numeric_limits<double>::infinity();
    if (!(m < 1)) return std::nan("");
    return std::numbers::pi / (2 * agm_double(1, std::sqrt(1 - m)));
}

/// E(m) = K(m) (1 - sum 2^(n-1) c_n^2) along the AGM of 1 and sqrt(1 - m), c_0^2 = m.
double ellipe_double(double m) {
    if (m == 1) return 1;
    if (!(m < 1)) return std::nan("");
    if (std::isinf(m)) return std::numeric_limits<double>::infinity();
    double a = 1;
    double b = std::sqrt(1 - m);
    double sum = m / 2;
    double weight = 0.5;
    for (int i = 0; i < 100; ++i) {
        const double c = (a - b) / 2;
        const double next = (a + b) / 2;
        b = std::sqrt(a * b);
        a = next;
        weight *= 2;
        sum += weight * c * c;
        if (std::fabs(weight * c * c) <= 1e-17 * std::fabs(sum) || c == 0) break;
    }
    return std::numbers::pi / (2 * a) * (1 - sum);
}

double one_argument(op what, double x) {
    switch (what) {
        case op::sqrt: return std::sqrt(x);
        case op::exp: return std::exp(x);
        case op::log: return std::log(x);
        case op::sin: return std::sin(x);
        case op::cos: return std::cos(x);
        case op::tan: return std::tan(x);
        case op::asin: return std::asin(x);
        case op::acos: return std::acos(x);
        case op::atan: return std::atan(x);
        case op::sinh: return std::sinh(x);
        case op::cosh: return std::cosh(x);
        case op::tanh: return std::tanh(x);
        case op::abs: return std::fabs(x);
        case op::ellipk: return ellipk_double(x);
        case op::ellipe: return ellipe_double(x);
        case op::neg: return -x;
        default: return std::nan("");
    }
}

double parser::evaluate(const std::vector<formula_node>& nodes, int i, double theta0, double t) {
    const auto& n = nodes[static_cast<std::size_t>(i)];
    const auto arg = [&](int j) { return evaluate(nodes, j, theta0, t); };
    switch (n.what) {
        case op::number: return n.value;
        case op::pi: return std::numbers::pi;
        case op::theta0: return theta0;
        case op::t: return t;
        case op::add: return arg(n.a) + arg(n.b);
        case op::sub: return arg(n.a) - arg(n.b);
        case op::mul: return arg(n.a) * arg(n.b);
        case op::div: return arg(n.a) / arg(n.b);
        case op::pow: return std::pow(arg(n.a), arg(n.b));
        case op::agm: return agm_double(arg(n.a), arg(n.b));
        case op::besselj: return jn(n.order, arg(n.a));
        default: return one_argument(n.what, arg(n.a));
    }
}

}  // namespace

std::string formula_functions() {
    std::string out;
    for (const auto& f : functions) {
        if (f.arguments == 0) continue;
        out += (out.empty() ? "" : ", ") + std::string(f.name) + (f.what == op::besselj ? "(n, x)" : f.what == op::agm ? "(a, b)" : "");
    }
    return out + " (ellipk and ellipe take the parameter m = k^2)";
}

formula::formula(std::string_view text) : text_(text) {
    uses_t_ = parser(text, nodes_).parse_all();
}

double formula::value(double theta0, double t) const {
    return parser::evaluate(nodes_, static_cast<int>(nodes_.size()) - 1, theta0, t);
}

}  // namespace pendulum
