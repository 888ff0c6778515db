// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/amplitude.hpp"

#include <cfloat>
#include <charconv>
#include <cmath>
#include <numbers>

namespace pendulum {

std::string format_double(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, end);
}

void check_amplitude(double theta0, std::string_view name) {
    // The double nearest pi lies just below pi; it still means "pi" to the user, who
    // asked for the unstable equilibrium, so it is rejected like pi itself.
    if (!(theta0 > 0.0 && theta0 < std::numbers::pi)) {
        throw domain_error(std::string(name) + " must be strictly between 0 and pi, got " +
                           format_double(theta0));
    }
}

namespace {

/// pi = pi_hi + pi_lo + O(3e-33): pi_hi is the double nearest pi.
constexpr double pi_hi = std::numbers::pi;
constexpr double pi_lo = 1.2246467991473532e-16;

}  // namespace

amplitude::amplitude(double theta0) {
    check_amplitude(theta0);
    theta0_ = theta0;
    source_ = source::theta0;
    // pi_hi - theta0 is exact for theta0 >= pi/2 (Sterbenz) and the one rounding is the last.
    d_ = (pi_hi - theta0) + pi_lo;
}

double amplitude::modulus(bool complementary) const {
    // Half of the smaller of theta0 and d: the sine and cosine of it are exact to rounding.
    const bool small = theta0_ <= 0.5 * pi_hi;
    const double half = 0.5 * (small ? theta0_ : d_);
    return small == complementary ? std::cos(half) : std::sin(half);
}

long double amplitude::radians_extended() const {
    return source_ != source::theta0 && near_pi() ? std::numbers::pi_v<long double> - d_ : theta0_;
}

long double amplitude::moduli_extended(bool complementary) const {
    if (source_ == source::parts) return complementary ? kp() : k();
    // Half of the smaller of theta0 and d, in extended precision from the exact one: for a
    // double theta0 above pi/2, pi_hi - theta0 is exact and pi's next 64 bits follow.
    constexpr long double pi_lo_extended = 1.2246467991473531772260659281409368386e-16L;
    const bool small = source_ == source::theta0 && theta0_ <= 0.5 * pi_hi;
    long double half = 0;
    if (small) {
        half = 0.5L * theta0_;
    } else if (source_ == source::distance) {
        half = 0.5L * d_;
    } else {
        half = 0.5L * (static_cast<long double>(pi_hi - theta0_) + pi_lo_extended);
    }
    return small == complementary ? std::cos(half) : std::sin(half);
}

amplitude amplitude::from_pi(double d) {
    if (!(d >= DBL_MIN && d < pi_hi)) {
        throw domain_error("the distance from pi must be between 2.2250738585072014e-308 and pi, got " +
                           format_double(d));
    }
    amplitude a;
    a.d_ = d;
    a.source_ = source::distance;
    a.theta0_ = (pi_hi - d) + pi_lo;
    return a;
}

std::string format_amplitude(const amplitude& theta0) {
    return theta0.near_pi() ? "pi - " + format_double(theta0.from_pi()) : format_double(theta0.radians());
}

amplitude amplitude::from_parts(double theta0, double d, double k, double kp) {
    amplitude a;
    a.theta0_ = theta0;
    a.d_ = d;
    a.k_ = k;
    a.kp_ = kp;
    return a;
}

}  // namespace pendulum
