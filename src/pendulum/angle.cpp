// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/angle.hpp"

#include "common/terminal_text.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/expression_lexer.hpp"
#include "pendulum/expression_parser.hpp"
#include "pendulum/mp_real.hpp"
#include "pendulum/written_mp.hpp"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <algorithm>
#include <array>
#include <limits>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace pendulum {

/// Control characters, bidirectional controls and bytes that are not UTF-8 escaped, as
/// every message that reaches a terminal shows them (common::terminal_text).
std::string message_text(std::string_view text) { return common::terminal_text(text); }

namespace {

const std::string_view allowed =
    "expected a number, pi, or an expression such as 1.2, pi/2, 9pi/10, 0.9pi or 162deg";

using mp::real;
using op = formula_node::op;

/// A text for a message: control characters and bytes that are not UTF-8 as \xNN.
std::string shown_text(std::string_view text) {
    std::string out;
    while (!text.empty()) {
        const std::size_t bad = grammar::invalid_utf8(text);
        out += message_text(text.substr(0, bad));
        if (bad == text.size()) break;
        constexpr char hex[] = "0123456789abcdef";
        const auto u = static_cast<unsigned char>(text[bad]);
        out += std::string("\\x") + hex[u >> 4] + hex[u & 15];
        text.remove_prefix(bad + 1);
    }
    return out;
}

/// "invalid value 'TEXT': why; what is allowed" (a long value shown by its ends).
std::string angle_message(std::string_view text, std::size_t /*at*/, const std::string& why) {
    const std::string shown = text.size() <= 80 ? shown_text(text)
                                                : shown_text(text.substr(0, 40)) + "..." + shown_text(text.substr(text.size() - 20));
    return "invalid value '" + shown + "': " + why + "; " + std::string(allowed);
}

/// Refuses an angle's text with why.
[[noreturn]] void angle_fail(std::string_view text, const std::string& why) { throw domain_error(angle_message(text, 0, why)); }

constexpr std::array<grammar::name_row, 2> angle_names = {{{"pi", op::pi}, {"\u03c0", op::pi}}};

constexpr std::array<grammar::operator_row, 4> angle_operators = {{
    {'+', op::add, 1, false}, {'-', op::sub, 1, false}, {'*', op::mul, 2, false}, {'/', op::div, 2, false},
}};

constexpr std::array<grammar::unit_row, 3> angle_units = {{
    {"deg", grammar::unit::degrees}, {"\u00b0", grammar::unit::degrees}, {"rad", grammar::unit::radians},
}};

/// An expression: numbers, pi, + - * / and parentheses.
constexpr grammar::language number_language{
    .names = angle_names,
    .functions = {},
    .operators = angle_operators,
    .units = {},
    .max_bytes = std::numeric_limits<std::size_t>::max(),
    .max_depth = grammar::max_angle_depth,
    .max_nodes = std::numeric_limits<std::size_t>::max(),
    .max_order = 0,
    .noun = "expression",
    .a_noun = "an expression",
    .nesting = "parentheses and signs",
    .empty = "empty value",
    .functions_note = "",
    .message = angle_message,
    .constant = nullptr,
};

/// An angle: an expression and a unit at its end.
constexpr grammar::language angle_language = [] {
    grammar::language l = number_language;
    l.units = angle_units;
    return l;
}();

const grammar::language& language_of(bool units) { return units ? angle_language : number_language; }

/// A number's value with `bits`, never a silent 0: a number beyond MPFR's exponent range
/// (1e-9999999999) is refused as one below the smallest double is (check_held).
real number_value(std::string_view text, const std::string& digits, mpfr_prec_t bits) {
    real v(bits);
    mpfr_strtofr(v.get(), digits.c_str(), nullptr, 10, MPFR_RNDN);
    const bool nonzero = lexer::mantissa_of(digits).find_first_not_of("0.") != std::string::npos;
    if (nonzero && (v.is_zero() || !mpfr_number_p(v.get()))) {
        // Past MPFR's exponents (where a huge one wraps to infinity): strtod says which end.
        if (std::strtod(digits.c_str(), nullptr) != 0) angle_fail(text, "number " + digits + " is beyond a double's range");
        angle_fail(text, "number " + digits + " is below the smallest double, 4.9406564584124654e-324, and it is not "
                         "0: a double cannot hold it (write 0, or a larger value)");
    }
    return v;
}

/// The value of a tree with `bits`, correctly rounded; children come before their parents,
/// so one pass with a stack evaluates it without recursion, however long the text.
real evaluate_tree(std::string_view text, const grammar::tree& t, mpfr_prec_t bits) {
    std::vector<real> stack;
    for (const auto& n : t.nodes) {
        if (n.what == op::number || n.what == op::pi) {
            stack.push_back(n.what == op::pi ? mp::pi(bits) : number_value(text, n.digits, bits));
            continue;
        }
        if (n.what == op::neg) {
            stack.back() = -stack.back();
            continue;
        }
        real b = std::move(stack.back());
        stack.pop_back();
        real& a = stack.back();
        if (n.what == op::div && b.is_zero()) angle_fail(text, "division by zero");
        a = n.what == op::add ? a + b : n.what == op::sub ? a - b : n.what == op::mul ? a * b : a / b;
    }
    real v = std::move(stack.back());
    if (t.what == grammar::unit::degrees) v = v / 180.0 * mp::pi(bits);
    if (!std::isfinite(v.to_double())) angle_fail(text, "value is not finite");
    return v;
}

/// A text read once, evaluated at any precision.
class reading {
public:
    reading(std::string_view text, bool units) : text_(text), tree_(grammar::parse(text, language_of(units))) {}
    real at(mpfr_prec_t bits) const { return evaluate_tree(text_, tree_, bits); }
    [[noreturn]] void fail(const std::string& why) const { angle_fail(text_, why); }

private:
    std::string_view text_;
    grammar::tree tree_;
};

/// Two evaluations, the second with twice the bits: where they round to different doubles,
/// cancellation has eaten the first one's digits, and the value is not vouched for.
constexpr mpfr_prec_t working_bits = 1280;

/// A plain decimal number ("2.5", "1e-3", no sign, no spaces), as from_chars reads it: that
/// rounds correctly already, and a million of them are read without MPFR. A digit or point
/// first (no sign, inf or nan) and the whole text read leave digits, one point and an
/// exponent only: from_chars' general format takes no hexadecimal.
std::optional<double> plain_value(std::string_view t) {
    if (t.empty() || !lexer::number_start(t[0])) return std::nullopt;
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
        angle_fail(text, "its size is below the smallest double, 4.9406564584124654e-324, and it is not 0: a double "
                  "cannot hold it (write 0, or a larger value)");
    }
}

/// The value of a text rounded once, checked against twice the bits; `exact` says whether
/// that double is the value itself.
double evaluate(std::string_view text, bool allow_units, bool* exact = nullptr) {
    if (const auto v = plain_value(text)) {
        if (exact) *exact = equals(reading(text, allow_units).at(working_bits), *v);
        return *v;
    }
    const reading r(text, allow_units);
    const real coarse = r.at(working_bits);
    const real fine = r.at(2 * working_bits);
    check_held(text, fine);
    if (coarse.to_double() != fine.to_double()) r.fail("it cancels beyond " + std::to_string(2 * working_bits) + " bits");
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
    // exact_double() was checked at 2560 bits at most: past them the text itself is evaluated
    // (2-1e-800 is 2 to 2560 bits, and a start's regime may need more; start_energy.hpp).
    if (x.text().empty() || (x.exact_double() && bits <= 2 * working_bits)) return real(x.value(), bits);
    return reading(x.text(), x.angle_units()).at(bits);
}

namespace {

/// A decimal number as written ("2.5", "1e-19800", ".5E3") as an exact rational; false where
/// its exponent is beyond 100000 in size (10^100000 is 41 kB, and no start needs more).
bool decimal_rational(const std::string& digits, mpq_ptr out) {
    const auto e = digits.find_first_of("eE");
    const std::string mantissa = digits.substr(0, e);
    long exponent = 0;
    if (e != std::string::npos) {
        errno = 0;
        exponent = std::strtol(digits.c_str() + e + 1, nullptr, 10);
        if (errno != 0 || exponent > 100000 || exponent < -100000) return false;
    }
    std::string whole;
    long fraction = 0;
    bool after_point = false;
    for (const char c : mantissa) {
        if (c == '.') {
            after_point = true;
        } else if (c >= '0' && c <= '9') {
            whole += c;
            fraction += after_point ? 1 : 0;
        }
    }
    if (whole.empty()) return false;
    mpz_t scale;
    mpz_init(scale);
    mpq_set_str(out, whole.c_str(), 10);
    const long shift = exponent - fraction;
    mpz_ui_pow_ui(scale, 10, static_cast<unsigned long>(shift < 0 ? -shift : shift));
    if (shift >= 0) mpz_mul(mpq_numref(out), mpq_numref(out), scale);
    else mpz_mul(mpq_denref(out), mpq_denref(out), scale);
    mpz_clear(scale);
    mpq_canonicalize(out);
    return true;
}

/// a * b for exact values, where one of them has no multiple of pi; nothing otherwise.
std::optional<rational_pi> exact_product(const rational_pi& x, const rational_pi& y) {
    const bool x_rational = mpq_sgn(x.b.get()) == 0;
    if (!x_rational && mpq_sgn(y.b.get()) != 0) return std::nullopt;  // a multiple of pi^2
    const rational_pi& scaled = x_rational ? y : x;
    const rational& by = x_rational ? x.a : y.a;
    rational_pi out = scaled;
    mpq_mul(out.a.get(), out.a.get(), by.get());
    mpq_mul(out.b.get(), out.b.get(), by.get());
    return out;
}

/// x / y for exact values, where y is a rational other than 0; nothing otherwise.
std::optional<rational_pi> exact_quotient(const rational_pi& x, const rational_pi& y) {
    if (mpq_sgn(y.b.get()) != 0 || mpq_sgn(y.a.get()) == 0) return std::nullopt;
    rational_pi out = x;
    mpq_div(out.a.get(), out.a.get(), y.a.get());
    mpq_div(out.b.get(), out.b.get(), y.a.get());
    return out;
}

/// One operation of the angle language on exact values: the result, or nothing.
std::optional<rational_pi> exact_step(op what, const rational_pi& x, const rational_pi& y) {
    rational_pi out = x;
    switch (what) {
        case op::add:
            mpq_add(out.a.get(), x.a.get(), y.a.get());
            mpq_add(out.b.get(), x.b.get(), y.b.get());
            return out;
        case op::sub:
            mpq_sub(out.a.get(), x.a.get(), y.a.get());
            mpq_sub(out.b.get(), x.b.get(), y.b.get());
            return out;
        case op::mul: return exact_product(x, y);
        case op::div: return exact_quotient(x, y);
        default: return std::nullopt;
    }
}

/// True where every numerator and denominator of v is within max_exact_bits.
bool within_exact_bits(const rational_pi& v) {
    for (mpq_srcptr q : {v.a.get(), v.b.get()}) {
        if (mpz_sizeinbase(mpq_numref(q), 2) > max_exact_bits || mpz_sizeinbase(mpq_denref(q), 2) > max_exact_bits) {
            return false;
        }
    }
    return true;
}

}  // namespace

std::optional<rational_pi> exact_written(const written_number& x) {
    if (x.text().empty()) {
        rational_pi v;
        mpq_set_d(v.a.get(), x.value());
        return v;
    }
    const grammar::tree t = grammar::parse(x.text(), language_of(x.angle_units()));
    std::vector<rational_pi> stack;
    for (const auto& n : t.nodes) {
        if (n.what == op::number || n.what == op::pi) {
            stack.emplace_back();
            if (n.what == op::pi) mpq_set_ui(stack.back().b.get(), 1, 1);
            else if (!decimal_rational(n.digits, stack.back().a.get())) return std::nullopt;
            continue;
        }
        if (n.what == op::neg) {
            mpq_neg(stack.back().a.get(), stack.back().a.get());
            mpq_neg(stack.back().b.get(), stack.back().b.get());
            continue;
        }
        if (stack.size() < 2) return std::nullopt;
        const rational_pi y = stack.back();
        stack.pop_back();
        auto result = exact_step(n.what, stack.back(), y);
        if (!result || !within_exact_bits(*result)) return std::nullopt;
        stack.back() = *result;
    }
    if (stack.size() != 1) return std::nullopt;
    rational_pi v = stack.back();
    if (t.what == grammar::unit::degrees) {
        // d degrees are d/180 pi.
        if (mpq_sgn(v.b.get()) != 0) return std::nullopt;
        rational one_eighty;
        mpq_set_ui(one_eighty.get(), 180, 1);
        mpq_div(v.b.get(), v.a.get(), one_eighty.get());
        mpq_set_ui(v.a.get(), 0, 1);
    }
    return v;
}

namespace {

/// k = sin(theta0/2) and k' = sin(d/2), each from the exact value, rounded once: the sine of
/// the smaller half-angle (at most pi/4), and the other as sqrt(1 - s^2), where s^2 is at
/// most 1/2 and nothing cancels (one sine instead of two, the costlier one left).
std::pair<double, double> moduli(const real& theta0, const real& d) {
    const bool closer_to_pi = d < theta0;
    const real s = mp::sin((closer_to_pi ? d : theta0) / 2.0);
    const double c = mp::sqrt(1.0 - s * s).to_double();
    return closer_to_pi ? std::pair{c, s.to_double()} : std::pair{s.to_double(), c};
}

/// A plain decimal's text as M / 10^q, with M below 2^64 and 0 <= q <= 19 (at most 19
/// digits); nothing for a longer one or another scale.
struct scaled_decimal {
    std::uint64_t m = 0;  ///< the digits as an integer
    int q = 0;            ///< the power of ten below them
};

/// The text of a plain number (plain_value read all of it) as M / 10^q, if it fits.
std::optional<scaled_decimal> scaled_of(std::string_view t) {
    scaled_decimal s;
    int after_point = 0;
    bool point = false;
    std::size_t i = 0;
    for (; i < t.size() && t[i] != 'e' && t[i] != 'E'; ++i) {
        if (t[i] == '.') {
            point = true;
            continue;
        }
        const auto digit = static_cast<std::uint64_t>(t[i] - '0');
        if (s.m > (std::numeric_limits<std::uint64_t>::max() - digit) / 10) return std::nullopt;
        s.m = s.m * 10 + digit;
        after_point += point ? 1 : 0;
    }
    long exponent = 0;
    if (i < t.size()) {
        const char* first = t.data() + i + 1 + (t[i + 1] == '+' ? 1 : 0);
        const auto [end, ec] = std::from_chars(first, t.data() + t.size(), exponent);
        if (ec != std::errc() || end != t.data() + t.size() || exponent < -19 || exponent > 19) return std::nullopt;
    }
    const long q = after_point - exponent;
    if (q < 0 || q > 19) return std::nullopt;
    s.q = static_cast<int>(q);
    return s;
}

/// A 128-bit integer (a GCC and Clang extension): M 2^51 and T 10^q are exact in it.
__extension__ using int128 = __int128;

/// A number as the unevaluated sum hi + lo of two doubles, |lo| at most half an ulp of hi.
struct two_doubles {
    double hi = 0;
    double lo = 0;
};

/// a + b exactly (Knuth's two-sum).
two_doubles two_sum(double a, double b) {
    const double s = a + b;
    const double v = s - a;
    return {s, (a - (s - v)) + (b - v)};
}

/// a + b exactly where |a| >= |b| (or a is 0).
two_doubles fast_two_sum(double a, double b) {
    const double s = a + b;
    return {s, b - (s - a)};
}

/// a b exactly (the rounding error by a fused multiply-add).
two_doubles two_product(double a, double b) {
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
}

/// The double x rounds to where every number within err of it rounds to that same double
/// (x.hi, since |x.lo| is at most half an ulp); nothing where the interval reaches a midpoint.
std::optional<double> rounded_within(two_doubles x, double err) {
    // The two half-gaps to the neighbours of hi (unequal at a power of 2), with a margin for
    // the roundings of lo +- err themselves.
    const double below = 0.5 * (x.hi - std::nextafter(x.hi, 0.0));
    const double above = 0.5 * (std::nextafter(x.hi, 2 * x.hi) - x.hi);
    const double margin = err * 1.001 + std::fabs(x.lo) * 0x1p-50;
    if (x.lo - margin <= -below || x.lo + margin >= above) return std::nullopt;
    return x.hi;
}

/// k' = sin x and k = cos x for 0 < x <= 0.071 given as xh + xl, by their Taylor series to
/// x^11 and x^12 (the rest below 2^-74) in doubles about the leading 1 and x, which two-sums
/// keep exact; each within `err` of the pair returned (2^-59 of x and of 1 for the series and
/// its roundings, and what x's relative error `rel` moves them by: x and x^2 of it).
std::pair<two_doubles, two_doubles> small_sin_cos(two_doubles x, double rel, double& sin_err, double& cos_err) {
    const double y = x.hi * x.hi;
    const double p = y * (1.0 / 6 - y * (1.0 / 120 - y * (1.0 / 5040 - y * (1.0 / 362880 - y / 39916800))));
    const double q =
        y * (0.5 - y * (1.0 / 24 - y * (1.0 / 720 - y * (1.0 / 40320 - y * (1.0 / 3628800 - y / 479001600)))));
    const two_doubles t = two_product(x.hi, p);  // x - t is sin x
    const two_doubles s = two_sum(x.hi, -t.hi);
    const two_doubles c = two_sum(1.0, -q);
    sin_err = x.hi * (0x1p-59 + 2 * rel);
    cos_err = 0x1p-59 + 2 * y * rel;
    return {fast_two_sum(s.hi, s.lo - t.lo + x.lo * (1 - 0.5 * y)), fast_two_sum(c.hi, c.lo - x.lo * x.hi)};
}

/// The amplitude of a plain number of at most 19 digits, v its double in [3, pi), without
/// MPFR: d = pi - text as two doubles (pi_hi - v exact by Sterbenz, pi's next bits, and the
/// text's excess over v, exact as an integer), k' = sin(d/2) and k = cos(d/2), each bounded
/// and rounded once, as MPFR rounds them; nothing where a bound reaches a midpoint between
/// doubles or the text is not such a number (the MPFR path decides those).
std::optional<amplitude> plain_near_pi(std::string_view text, double v) {
    constexpr double pi_hi = std::numbers::pi;
    constexpr double pi_lo = 1.2246467991473532e-16;     // pi - pi_hi, rounded
    constexpr double pi_lo2 = -2.9947698097183397e-33;   // pi - pi_hi - pi_lo, rounded
    const auto s = scaled_of(text);
    if (!s || !(v >= 3.0 && v <= pi_hi)) return std::nullopt;
    // text - v = (M 2^51 - T 10^q) / (10^q 2^51), where v = T 2^-51: at most half an ulp of v.
    int128 ten_q = 1;
    for (int i = 0; i < s->q; ++i) ten_q *= 10;
    const auto t = static_cast<int128>(std::ldexp(v, 51));
    const int128 excess = (static_cast<int128>(s->m) << 51) - t * ten_q;
    if (excess == 0) return amplitude(v);  // the text is the double itself, as equals() finds
    if (excess > (int128{1} << 62) || excess < -(int128{1} << 62)) return std::nullopt;
    // r = excess / 10^q / 2^51 to 2^-104: excess is e_hi + e_lo exactly, 10^q a double.
    const auto e = static_cast<std::int64_t>(excess);
    const auto e_hi = static_cast<double>(e);
    const auto e_lo = static_cast<double>(e - static_cast<std::int64_t>(e_hi));
    const auto ten = static_cast<double>(ten_q);
    const double r_hi = e_hi / ten;
    const double r_lo = (std::fma(-r_hi, ten, e_hi) + e_lo) / ten;
    const two_doubles r = fast_two_sum(std::ldexp(r_hi, -51), std::ldexp(r_lo, -51));
    // d = (pi_hi - v) + pi_lo + pi_lo2 - r: the roundings of the low parts, 2^-102 of the sizes.
    const double dh = pi_hi - v;  // exact
    const two_doubles a = two_sum(dh, pi_lo);
    const two_doubles b = two_sum(a.hi, -r.hi);
    const two_doubles d = fast_two_sum(b.hi, (a.lo + b.lo) + (pi_lo2 - r.lo));
    const double d_err = 0x1p-98 * (std::fabs(dh) + pi_lo + std::fabs(r.hi));
    if (!(d.hi > 2 * d_err)) return std::nullopt;
    double sin_err = 0;
    double cos_err = 0;
    const auto [sine, cosine] = small_sin_cos({0.5 * d.hi, 0.5 * d.lo}, d_err / (d.hi - d_err), sin_err, cos_err);
    const auto dd = rounded_within(d, d_err);
    const auto kp = rounded_within(sine, sin_err);
    const auto k = rounded_within(cosine, cos_err);
    if (!dd || !kp || !k) return std::nullopt;
    return amplitude::from_parts(v, *dd, *k, *kp);
}

}  // namespace

double parse_angle(std::string_view text) { return evaluate(text, true); }

amplitude parse_amplitude(std::string_view text, std::string_view name) {
    // A plain number below 3 (d > 0.14): its double is all there is to know, and its distance
    // from pi and k' follow from it to rounding (a million amplitudes read without MPFR).
    const auto v = plain_value(text);
    if (v && *v < 3.0 && *v > 0) {
        check_amplitude(*v, name);
        return amplitude(*v);
    }
    // A plain number from 3 to pi: its exact digits, without MPFR where the bounds decide.
    if (v) {
        if (auto a = plain_near_pi(text, *v)) return *a;
    }
    // 128 bits (checked against 256) for plain numbers and most expressions, the working
    // precision where those disagree: where they cancel, as pi - 1e-300 does.
    const reading r(text, true);
    for (const mpfr_prec_t bits : {mpfr_prec_t{128}, working_bits}) {
        const real coarse = r.at(bits);
        const real fine = r.at(2 * bits);
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
        if (!agree) r.fail("it cancels beyond " + std::to_string(2 * bits) + " bits");
        check_held(text, fine);
        // A value that is a double ("3", "+1", "2/2") is that double, read as a plain number
        // is: one amplitude, whichever way it is written.
        if (equals(fine, theta0) && theta0 < std::numbers::pi) return amplitude(theta0);
        if (d < DBL_MIN) {
            throw domain_error(std::string(name) + " must be at least 2.2250738585072014e-308 below pi, got pi - " +
                               format_double(d));
        }
        const auto [k, kp] = moduli(fine, d_fine);
        return amplitude::from_parts(theta0, d, k, kp);
    }
    throw domain_error("unreachable");  // the loop returns or throws at the working precision
}

namespace {

/// The piece a lexeme is, for angle_tokens.
angle_token token_of(const grammar::lexeme& l) {
    using kind = angle_token::kind;
    using lk = grammar::lexeme::kind;
    const std::string_view t = l.text;
    switch (l.type) {
        case lk::name: return {kind::pi, {}, {}, false};
        case lk::unit: return {t == "rad" ? kind::radians : kind::degrees, {}, {}, false};
        case lk::sign: return {t == "-" ? kind::sign_minus : kind::sign_plus, {}, {}, false};
        case lk::open: return {kind::open, {}, {}, false};
        case lk::close: return {kind::close, {}, {}, false};
        case lk::binary: return {t == "+" ? kind::plus : t == "-" ? kind::minus : t == "*" ? kind::times : kind::divide, {}, {}, false};
        default: break;
    }
    angle_token n{kind::number, lexer::mantissa_of(t), {}, false};
    if (n.mantissa.size() < t.size()) {
        std::string e(t.substr(n.mantissa.size() + 1));
        if (!e.empty() && (e[0] == '+' || e[0] == '-')) {
            n.negative_exponent = e[0] == '-';
            e.erase(0, 1);
        }
        e.erase(0, std::min(e.find_first_not_of('0'), e.size() - 1));
        n.exponent = e;
    }
    return n;
}

}  // namespace

std::vector<angle_token> angle_tokens(std::string_view text) {
    std::vector<grammar::lexeme> lexemes;
    const reading checked(text, true);
    (void)checked.at(working_bits);  // refused as parse_angle refuses it
    grammar::parse(text, angle_language, &lexemes);
    std::vector<angle_token> tokens;
    for (const auto& l : lexemes) tokens.push_back(token_of(l));
    return tokens;
}

}  // namespace pendulum
