// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/angle.hpp"

#include "cli/errors.hpp"
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pendulum::cli {

namespace {

const std::string_view allowed =
    "expected a number, pi, or an expression such as 1.2, pi/2, 9pi/10, 0.9pi or 162deg";

/// Recursive-descent evaluator; `pos` walks the text.
class parser {
public:
    explicit parser(std::string_view text) : text_(text) {}

    double parse_all(bool allow_units) {
        skip_space();
        if (pos_ == text_.size()) fail("empty value");
        double v = sum();
        skip_space();
        if (allow_units) {
            if (take("deg") || take("\u00b0")) {
                v = v / 180.0 * std::numbers::pi;
            } else {
                take("rad");
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
        throw usage_error("invalid value '" + shown + "': " + why + "; " + std::string(allowed));
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
                v += product();
            } else if (take("-")) {
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
                v *= unary();
            } else if (take("/")) {
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
        if (take("-")) return -unary();
        if (take("+")) return unary();
        return primary();
    }

    double primary() {
        skip_space();
        if (take("(")) {
            const nesting level(*this);
            const double v = sum();
            if (!take(")")) fail("missing ')'");
            return v;
        }
        if (take("pi") || take("\u03c0")) return std::numbers::pi;
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
        return v;
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    int depth_ = 0;
};

}  // namespace

double parse_expression(std::string_view text) { return parser(text).parse_all(false); }

double parse_angle(std::string_view text) { return parser(text).parse_all(true); }

std::vector<std::string> split_list(std::string_view text) {
    std::vector<std::string> items;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        items.emplace_back(text.substr(start, comma - start));
        if (comma == std::string_view::npos) return items;
        start = comma + 1;
    }
}

}  // namespace pendulum::cli
