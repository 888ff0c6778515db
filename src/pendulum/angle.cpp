// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/angle.hpp"

#include "pendulum/amplitude.hpp"

#include <cerrno>
#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pendulum {

namespace {

/// Control characters and NUL as \xNN: a message is a C string, and NUL would cut it short.
std::string escaped(const std::string& text) {
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

const std::string_view allowed =
    "expected a number, pi, or an expression such as 1.2, pi/2, 9pi/10, 0.9pi or 162deg";

/// Recursive-descent evaluator; `pos` walks the text.
class parser {
public:
    explicit parser(std::string_view text, std::vector<angle_token>* tokens = nullptr)
        : text_(text), tokens_(tokens) {}

    double parse_all(bool allow_units) {
        skip_space();
        if (pos_ == text_.size()) fail("empty value");
        double v = sum();
        skip_space();
        if (allow_units) {
            if (take("deg") || take("\u00b0")) {
                v = v / 180.0 * std::numbers::pi;
                emit(angle_token::kind::degrees);
            } else if (take("rad")) {
                emit(angle_token::kind::radians);
            }
            skip_space();
        }
        if (pos_ != text_.size()) fail("unexpected '" + std::string(text_.substr(pos_)) + "'");
        if (!std::isfinite(v)) fail("value is not finite");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& why) const {
        // A long value is shown by its ends.
        const std::string shown = text_.size() <= 80 ? std::string(text_)
                                                      : std::string(text_.substr(0, 40)) + "..." +
                                                            std::string(text_.substr(text_.size() - 20));
        throw domain_error("invalid value '" + escaped(shown) + "': " + escaped(why) + "; " + std::string(allowed));
    }

    /// Records a piece for angle_tokens.
    void emit(angle_token::kind k) {
        if (tokens_) tokens_->push_back({k, {}, {}, false});
    }

    void skip_space() {
        while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
    }

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

    double sum() {
        double v = product();
        for (;;) {
            if (take("+")) {
                emit(angle_token::kind::plus);
                v += product();
            } else if (take("-")) {
                emit(angle_token::kind::minus);
                v -= product();
            } else {
                return v;
            }
        }
    }

    double product() {
        double v = unary();
        for (;;) {
            if (take("*")) {
                emit(angle_token::kind::times);
                v *= unary();
            } else if (take("/")) {
                emit(angle_token::kind::divide);
                const double d = unary();
                if (d == 0.0) fail("division by zero");
                v /= d;
            } else if (starts_primary()) {
                v *= primary();
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

    double unary() {
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

    double primary() {
        skip_space();
        if (take("(")) {
            emit(angle_token::kind::open);
            const nesting level(*this);
            const double v = sum();
            if (!take(")")) fail("missing ')'");
            emit(angle_token::kind::close);
            return v;
        }
        if (take("pi") || take("\u03c0")) {
            emit(angle_token::kind::pi);
            return std::numbers::pi;
        }
        if (pos_ < text_.size() &&
            ((text_[pos_] >= '0' && text_[pos_] <= '9') || text_[pos_] == '.')) {
            return number();
        }
        if (pos_ == text_.size()) fail("incomplete expression");
        fail("unexpected '" + std::string(text_.substr(pos_)) + "'");
    }

    double number() {
        // Only digits, one dot and an exponent are taken, so strtod never sees "inf" or hex.
        std::size_t end = pos_;
        while (end < text_.size() && std::isdigit(static_cast<unsigned char>(text_[end]))) ++end;
        if (end < text_.size() && text_[end] == '.') {
            ++end;
            while (end < text_.size() && std::isdigit(static_cast<unsigned char>(text_[end]))) ++end;
        }
        if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
            std::size_t exp = end + 1;
            if (exp < text_.size() && (text_[exp] == '+' || text_[exp] == '-')) ++exp;
            if (exp < text_.size() && std::isdigit(static_cast<unsigned char>(text_[exp]))) {
                end = exp;
                while (end < text_.size() && std::isdigit(static_cast<unsigned char>(text_[end]))) ++end;
            }
        }
        const std::string digits(text_.substr(pos_, end - pos_));
        // A number has a digit before its exponent: ".e5" is no number.
        const std::string mantissa = digits.substr(0, digits.find_first_of("eE"));
        if (mantissa.find_first_of("0123456789") == std::string::npos) {
            fail("'" + digits + "' is not a number");
        }
        errno = 0;
        const double v = std::strtod(digits.c_str(), nullptr);
        if (errno == ERANGE && std::isinf(v)) fail("number " + digits + " is out of range");
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
    std::size_t pos_ = 0;
    int depth_ = 0;
};

}  // namespace

double parse_expression(std::string_view text) { return parser(text).parse_all(false); }

double parse_angle(std::string_view text) { return parser(text).parse_all(true); }

std::vector<angle_token> angle_tokens(std::string_view text) {
    std::vector<angle_token> tokens;
    parser(text, &tokens).parse_all(true);
    return tokens;
}

}  // namespace pendulum
