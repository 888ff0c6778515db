// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"

#include <vector>

namespace pendulum {

/// The exact simple pendulum theta'' + sin(theta) = 0, theta(0) = theta0, theta'(0) = 0.
///
/// Time is measured as w0 t (so the small-amplitude period is 2 pi). Every quantity is
/// computed from the modulus k = sin(theta0/2) and the complementary modulus
/// k' = cos(theta0/2), never from 1 - k^2, so it stays accurate next to the separatrix.
/// The most intervals exact_solution::coefficient_by_quadrature() uses.
inline constexpr int max_quadrature_intervals = 1 << 16;

class exact_solution {
public:
    /// Prepares the solution for amplitude theta0 (a double converts, and is checked to lie
    /// in (0, pi)); k and k' come from the amplitude, exact close to pi.
    explicit exact_solution(const pendulum::amplitude& theta0);

    /// The amplitude theta0.
    double amplitude() const { return theta0_; }
    /// The modulus k = sin(theta0/2).
    double modulus() const { return k_; }
    /// The complementary modulus k' = cos(theta0/2).
    double complementary_modulus() const { return kp_; }
    /// The quarter period K(k), in units of 1/w0.
    double quarter_period() const { return quarter_; }
    /// The period ratio T/T0 = 2 K(k) / pi.
    double period_ratio() const;
    /// The frequency ratio w/w0 = pi / (2 K(k)).
    double frequency_ratio() const;
    /// The nome q = exp(-pi K(k') / K(k)).
    double nome() const;

    /// theta at time w0 t (any real value).
    double theta(double w0_t) const;
    /// theta at time t = s T, with s = t/T in periods of the exact motion.
    double theta_at_fraction(double s) const;

    /// The Fourier coefficient c_{2n+1} (n >= 0) from its closed form through the nome.
    double coefficient(int n) const;
    /// The coefficient c_{2n+1} by quadrature of the exact solution (the paper's Eq. Lamb.12.1,
    /// the trapezoidal rule, geometrically convergent for this periodic integrand), right to
    /// about 1e-15 theta0 absolute: a coefficient far below theta0 (c5 at small amplitudes)
    /// keeps fewer digits than coefficient(), which is exact to rounding. Throws
    /// std::runtime_error where max_quadrature_intervals do not reach that.
    double coefficient_by_quadrature(int n) const;

private:
    double theta_in_quarter(double r, double sign) const;
    double small_theta(double phase, bool complementary) const;

    double theta0_;
    double k_;
    double kp_;
    double quarter_;
    double period_ratio_;      // 1/AGM(1, k') rounded once
    double frequency_ratio_;   // AGM(1, k') rounded once
    long double kp_extended_;  // k' in extended precision, for the nome
    long double log_nome_;     // ln q in extended precision
    double small_c1_ = 0;  // c1 and c3 below small_amplitude
    double small_c3_ = 0;
};

/// The exact period ratio T/T0 for amplitude theta0.
double period_ratio(const amplitude& theta0);

/// The exact Fourier coefficients c1, c3, ..., c_{2 count - 1} for amplitude theta0.
std::vector<double> fourier_coefficients(const amplitude& theta0, int count);

/// Jacobi elliptic functions sn, cn, dn of u for the complementary modulus k'.
struct jacobi_values {
    double sn;  ///< sn(u|m)
    double cn;  ///< cn(u|m)
    double dn;  ///< dn(u|m)
};

/// sn, cn, dn of u for parameter m = 1 - kp^2, given through kp so that m near 1 keeps its digits.
jacobi_values jacobi(double u, double kp);

/// The arithmetic-geometric mean of a > 0 and b > 0.
double agm(double a, double b);

}  // namespace pendulum
