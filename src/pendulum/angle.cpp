// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/angle.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/expression_lexer.hpp"
#include "pendulum/mp_real.hpp"
#include "pendulum/written_mp.hpp"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pendulum {

/// Control characters and NUL as \xNN: a message is a C string, and NUL would cut it short.
std::string message_text(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) {
            constexpr char hex[] = "0123456789abcdef";
            out += "\\x";
            out += hex[u >> 4];
            out += hex[u & 15];
        } else {
            out += c;
        }
    }
    return out;
}

namespace {


const std::string_view allowed =
    "expected a number, pi, or an expression such as 1.2, pi/2, 9pi/10, 0.9pi or 162deg";

using mp::real;

/// Recursive-descent evaluator with `bits` of precision, correctly rounded; `pos` walks the text.
class parser {
public:
    explicit parser(std::string_view text, mpfr_prec_t bits, std::vector<angle_token>* tokens = nullptr)
        : text_(text), tokens_(tokens), bits_(bits) {}

    real parse_all(bool allow_units) {
        skip_space();
        if (pos_ == text_.size()) fail("empty value");
        real v = sum();
        skip_space();
        if (allow_units) {
            if (take("deg") || take("\u00b0")) {
                v = v / 180.0 * mp::pi(bits_);
                emit(angle_token::kind::degrees);
            } else if (take("rad")) {
                emit(angle_token::kind::radians);
            }
            skip_space();
        }
        if (pos_ != text_.size()) fail("unexpected '" + std::string(text_.substr(pos_)) + "'");
        if (!std::isfinite(v.to_double())) fail("value is not finite");
        return v;
    }

    [[noreturn]] void fail(const std::string& why) const {
        // A long value is shown by its ends.
        const std::string shown = text_.size() <= 80 ? std::string(text_)
                                                      : std::string(text_.substr(0, 40)) + "..." +
                                                            std::string(text_.substr(text_.size() - 20));
        throw domain_error("invalid value '" + message_text(shown) + "': " + message_text(why) + "; " + std::string(allowed));
    }

    /// Records a piece for angle_tokens.
    void emit(angle_token::kind k) {
        if (tokens_) tokens_->push_back({k, {}, {}, false});
    }

    void skip_space() { pos_ = lexer::skip_space(text_, pos_); }

    bool take(std::string_view word) {
        skip_space();
        if (text_.substr(pos_, word.size()) == word) {
            pos_ += word.size();
            return true;
        }
        return false;
    }

    bool starts_primary() {
        skip_space();
        if (pos_ >= text_.size()) return false;
        const std::string_view rest = text_.substr(pos_);
        return rest.starts_with("(") || rest.starts_with("pi") || rest.starts_with("\u03c0");
    }

private:
    real sum() {
        real v = product();
        for (;;) {
            if (take("+")) {
                emit(angle_token::kind::plus);
                v = v + product();
            } else if (take("-")) {
                emit(angle_token::kind::minus);
                v = v - product();
            } else {
                return v;
            }
        }
    }

    real product() {
        real v = unary();
        for (;;) {
            if (take("*")) {
                emit(angle_token::kind::times);
                v = v * unary();
            } else if (take("/")) {
                emit(angle_token::kind::divide);
                const real d = unary();
                if (d.is_zero()) fail("division by zero");
                v = v / d;
            } else if (starts_primary()) {
                v = v * primary();
            } else {
                return v;
            }
        }
    }

    /// Parentheses and signs nest; deeper than this is no angle anyone types, and it would
    /// exhaust the stack.
    static constexpr int max_depth = 500;

    /// Counts one level of nesting for the rest of the enclosing call.
    struct nesting {
        explicit nesting(parser& p) : p_(p) {
            if (++p_.depth_ > max_depth) p_.fail("expression nested too deeply (at most " + std::to_string(max_depth) + " levels)");
        }
        ~nesting() { --p_.depth_; }
        nesting(const nesting&) = delete;
        nesting& operator=(const nesting&) = delete;
        parser& p_;
    };

    real unary() {
        const nesting level(*this);
        if (take("-")) {
            emit(angle_token::kind::sign_minus);
            return -unary();
        }
        if (take("+")) {
            emit(angle_token::kind::sign_plus);
            return unary();
        }
        return primary();
    }

    real primary() {
        skip_space();
        if (take("(")) {
            emit(angle_token::kind::open);
            const nesting level(*this);
            real v = sum();
            if (!take(")")) fail("missing ')'");
            emit(angle_token::kind::close);
            return v;
        }
        if (take("pi") || take("\u03c0")) {
            emit(angle_token::kind::pi);
            return mp::pi(bits_);
        }
        if (pos_ < text_.size() && lexer::number_start(text_[pos_])) return number();
        if (pos_ == text_.size()) fail("incomplete expression");
        fail("unexpected '" + std::string(text_.substr(pos_)) + "'");
    }

    real number() {
        const std::size_t end = lexer::number_end(text_, pos_);
        const std::string digits(text_.substr(pos_, end - pos_));
        // A number has a digit before its exponent: ".e5" is no number.
        const std::string mantissa = lexer::mantissa_of(digits);
        if (!lexer::has_digit(mantissa)) fail("'" + digits + "' is not a number");
        errno = 0;
        const double rounded = std::strtod(digits.c_str(), nullptr);
        if (errno == ERANGE && std::isinf(rounded)) fail("number " + digits + " is out of range");
        real v(bits_);
        mpfr_strtofr(v.get(), digits.c_str(), nullptr, 10, MPFR_RNDN);
        pos_ = end;
        if (tokens_) {
            angle_token t{angle_token::kind::number, mantissa, {}, false};
            if (mantissa.size() < digits.size()) {
                std::string e = digits.substr(mantissa.size() + 1);
                if (!e.empty() && (e[0] == '+' || e[0] == '-')) {
                    t.negative_exponent = e[0] == '-';
                    e.erase(0, 1);
                }
                e.erase(0, std::min(e.find_first_not_of('0'), e.size() - 1));
                t.exponent = e;
            }
            tokens_->push_back(std::move(t));
        }
        return v;
    }

    std::string_view text_;
    std::vector<angle_token>* tokens_;
    mpfr_prec_t bits_;
    std::size_t pos_ = 0;
    int depth_ = 0;
};

/// Two evaluations, the second with twice the bits: where they round to different doubles,
/// cancellation has eaten the first one's digits, and the value is not vouched for.
constexpr mpfr_prec_t working_bits = 1280;

/// A plain decimal number ("2.5", "1e-3", no sign, no spaces), as from_chars reads it: that
/// rounds correctly already, and a million of them are read without MPFR.
std::optional<double> plain_value(std::string_view t) {
    if (t.empty() || !lexer::number_start(t[0])) return std::nullopt;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const char c = t[i];
        if (lexer::number_start(c) || c == 'e' || c == 'E') continue;
        if ((c == '+' || c == '-') && (t[i - 1] == 'e' || t[i - 1] == 'E')) continue;
        return std::nullopt;
    }
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

/// True where x is exactly the double d.
bool equals(const real& x, double d) { return mpfr_cmp_d(x.get(), d) == 0; }

/// Refuses a value that is not 0 but rounds to 0: a double cannot hold it, and 0 would be
/// another number (the rule for every number read: never a silent 0).
void check_held(std::string_view text, const real& value) {
    if (!value.is_zero() && value.to_double() == 0) {
        parser(text, working_bits)
            .fail("its size is below the smallest double, 4.9406564584124654e-324, and it is not 0: a double "
                  "cannot hold it (write 0, or a larger value)");
    }
}

/// The value of a text rounded once, checked against twice the bits; `exact` says whether
/// that double is the value itself.
double evaluate(std::string_view text, bool allow_units, bool* exact = nullptr) {
    if (const auto v = plain_value(text)) {
        if (exact) *exact = equals(parser(text, working_bits).parse_all(allow_units), *v);
        return *v;
    }
    const real coarse = parser(text, working_bits).parse_all(allow_units);
    const real fine = parser(text, 2 * working_bits).parse_all(allow_units);
    check_held(text, fine);
    if (coarse.to_double() != fine.to_double()) {
        parser(text, working_bits).fail("it cancels beyond " + std::to_string(2 * working_bits) + " bits");
    }
    if (exact) *exact = equals(fine, fine.to_double());
    return fine.to_double();
}

}  // namespace

double parse_expression(std::string_view text) { return evaluate(text, false); }

written_number::written_number(double x) : value_(x) {}

written_number written_number::parse(std::string_view text, bool units) {
    written_number w;
    w.text_ = std::string(text);
    w.units_ = units;
    w.value_ = evaluate(text, units, &w.exact_);
    return w;
}

written_number written_number::angle(std::string_view text) { return parse(text, true); }

written_number written_number::expression(std::string_view text) { return parse(text, false); }

mp::real evaluate_written(const written_number& x, mpfr_prec_t bits) {
    if (x.text().empty() || x.exact_double()) return real(x.value(), bits);
    return parser(x.text(), bits).parse_all(x.angle_units());
}

double parse_angle(std::string_view text) { return evaluate(text, true); }

amplitude parse_amplitude(std::string_view text, std::string_view name) {
    // A plain number below 3 (d > 0.14): its double is all there is to know, and its distance
    // from pi and k' follow from it to rounding (a million amplitudes read without MPFR).
    if (const auto v = plain_value(text); v && *v < 3.0 && *v > 0) {
        check_amplitude(*v, name);
        return amplitude(*v);
    }
    // 128 bits (checked against 256) for plain numbers and most expressions, the working
    // precision where those disagree: where they cancel, as pi - 1e-300 does.
    for (const mpfr_prec_t bits : {mpfr_prec_t{128}, working_bits}) {
        const real coarse = parser(text, bits).parse_all(true);
        const real fine = parser(text, 2 * bits).parse_all(true);
        const real d_coarse = mp::pi(bits) - coarse;
        const real d_fine = mp::pi(2 * bits) - fine;
        const double theta0 = fine.to_double();
        const double d = d_fine.to_double();
        const bool agree = coarse.to_double() == theta0 && d_coarse.to_double() == d;
        if (bits != working_bits && (!agree || d_coarse.is_zero() || d_fine.is_zero())) continue;
        if (!(fine > 0.0) || !(d_fine > 0.0)) {
            // At or beyond pi (or 0) the rounded value says which: pi itself rounds to the
            // double below pi, which check_amplitude rejects as pi.
            check_amplitude(theta0, name);
            check_amplitude(fine > 0.0 ? std::numbers::pi : 0.0, name);
        }
        if (!agree) parser(text, bits).fail("it cancels beyond " + std::to_string(2 * bits) + " bits");
        check_held(text, fine);
        // A value that is a double ("3", "+1", "2/2") is that double, read as a plain number
        // is: one amplitude, whichever way it is written.
        if (equals(fine, theta0) && theta0 < std::numbers::pi) return amplitude(theta0);
        if (d < DBL_MIN) {
            throw domain_error(std::string(name) + " must be at least 2.2250738585072014e-308 below pi, got pi - " +
                               format_double(d));
        }
        // k = sin(theta0/2), k' = sin(d/2): each from the exact value, rounded once.
        const real k = mp::sin(fine / 2.0);
        const real kp = mp::sin(d_fine / 2.0);
        return amplitude::from_parts(theta0, d, k.to_double(), kp.to_double());
    }
    throw domain_error("unreachable");  // the loop returns or throws at the working precision
}

std::vector<angle_token> angle_tokens(std::string_view text) {
    std::vector<angle_token> tokens;
    parser(text, working_bits, &tokens).parse_all(true);
    return tokens;
}

}  // namespace pendulum
