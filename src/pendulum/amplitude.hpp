// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pendulum {

/// Thrown for an argument outside a function's domain; the message names the value.
class domain_error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// Formats a double so that it reads back to the same value (shortest round-trip form).
std::string format_double(double x);

/// Throws domain_error unless 0 < theta0 < pi; `name` is used in the message.
void check_amplitude(double theta0, std::string_view name = "theta0");

/// An amplitude theta0 in (0, pi) with its distance from pi and its moduli, each to the last
/// bit: close to pi the double theta0 itself cannot tell pi - 1e-300 from pi - 1e-17, but its
/// distance d = pi - theta0 and k' = cos(theta0/2) = sin(d/2) can, and every quantity that
/// diverges at pi is computed from them.
class amplitude {
public:
    /// The amplitude theta0 (a double, exact as it is); throws domain_error unless
    /// 0 < theta0 < pi (the double nearest pi means pi and is rejected too).
    amplitude(double theta0);  // NOLINT: a double is an amplitude
    /// The amplitude pi - d for 2.2e-308 <= d < pi; throws domain_error otherwise.
    static amplitude from_pi(double d);
    /// An amplitude whose four numbers were computed elsewhere (correctly rounded).
    static amplitude from_parts(double theta0, double d, double k, double kp);

    /// theta0 rounded to a double.
    double radians() const { return theta0_; }
    /// d = pi - theta0, rounded to a double from the exact amplitude.
    double from_pi() const { return d_; }
    /// The modulus k = sin(theta0/2).
    double k() const { return std::isnan(k_) ? modulus(false) : k_; }
    /// The complementary modulus k' = cos(theta0/2) = sin(d/2).
    double kp() const { return std::isnan(kp_) ? modulus(true) : kp_; }
    /// True where the amplitude is closer to pi than to 0, and pi - d is the exact value.
    bool near_pi() const { return d_ < theta0_; }
    /// True where the amplitude is the double theta0 itself (not pi - d, nor an expression's
    /// rounded numbers).
    bool exact_radians() const { return source_ == source::theta0; }
    /// True where the amplitude is a double itself, theta0 or pi - d (as written: "3",
    /// "pi - 1e-9" has d = 1e-9 to its last bit only as a double d), false where its numbers
    /// were rounded from an expression such as 9pi/10.
    bool exact() const { return source_ != source::parts; }
    /// theta0 in extended precision: pi - d close to pi unless theta0 is the exact number.
    long double radians_extended() const;
    /// k in extended precision, from whichever of theta0 and d is exact (as k() where the
    /// moduli were given).
    long double k_extended() const { return moduli_extended(false); }
    /// k' in extended precision, the same way.
    long double kp_extended() const { return moduli_extended(true); }

private:
    amplitude() = default;
    /// k or k' from theta0 and d, where they were not given (most users need neither).
    double modulus(bool complementary) const;
    /// k or k' in extended precision.
    long double moduli_extended(bool complementary) const;
    /// Which of the numbers is the amplitude itself (the others were rounded from it).
    enum class source { theta0, distance, parts };
    source source_ = source::parts;
    double theta0_ = 0;
    double d_ = 0;
    double k_ = std::numeric_limits<double>::quiet_NaN();   // NaN: computed when asked for
    double kp_ = std::numeric_limits<double>::quiet_NaN();
};

/// The amplitude as a round-trip text: "pi - 1e-06" close to pi (its exact distance),
/// the double theta0 otherwise.
std::string format_amplitude(const amplitude& theta0);

}  // namespace pendulum
