// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/exact.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/extended_periods.hpp"
#include "pendulum/gsl_support.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pendulum {

using std::numbers::pi;

double agm(double a, double b) {
    if (!(a > 0 && b > 0 && std::isfinite(a) && std::isfinite(b))) {
        throw domain_error("agm needs positive finite arguments, got " + format_double(a) + " and " + format_double(b));
    }
    // Quadratic convergence: the loop ends within a handful of steps even for b ~ 1e-300.
    for (int i = 0; i < 64 && std::fabs(a - b) > 2e-16 * a; ++i) {
        const double next = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = next;
    }
    return 0.5 * (a + b);
}

long double agm_extended(long double a, long double b) {
    for (int i = 0; i < 64 && std::fabs(a - b) > 1e-19L * a; ++i) {
        const long double next = 0.5L * (a + b);
        b = std::sqrt(a * b);
        a = next;
    }
    return 0.5L * (a + b);
}

long double exact_period_extended(const pendulum::amplitude& theta0) {
    return 1 / agm_extended(1, theta0.kp_extended());
}

namespace {

/// sn, cn, dn next to m = 1 (k' below 1e-9) while k'^2 cosh^2 u <= k': the expansion in
/// m1 = k'^2 to its first term (Abramowitz and Stegun 16.15), whose next is k'^2 smaller.
/// There dn and cn fall to sqrt(k') (1e-150 at k' = 1e-300), and the Landen recursion, which
/// forms them from cos of an argument near pi/2, keeps only their absolute digits: at
/// (1e-300, 2) 1e15 T0 on, omega = 6.3580399324612655e-143 came out 6.359484957786013e-143.
std::optional<jacobi_values> jacobi_near_separatrix(double u, double kp) {
    if (!(kp < 1e-9)) return std::nullopt;
    const double a = std::fabs(u);
    if (a < 1e-8) return std::nullopt;  // the Maclaurin series
    const double ch = std::cosh(a);
    if (!(kp * ch * ch <= 1.0)) return std::nullopt;
    const double sh = std::sinh(a);
    const double t = std::tanh(a);
    const double sech = 1.0 / ch;
    const double q = 0.25 * kp * kp;
    const double sc = sh * ch;
    const double sn = t + q * (sc - a) * sech * sech;
    const double cn = sech - q * (sc - a) * t * sech;
    const double dn = sech + q * (sc + a) * t * sech;
    return jacobi_values{std::copysign(sn, u), cn, dn};
}

}  // namespace

jacobi_values jacobi(double u, double kp) {
    if (!std::isfinite(u)) throw domain_error("jacobi needs a finite argument, got " + format_double(u));
    if (!(kp >= 0.0 && kp <= 1.0)) {
        throw domain_error("complementary modulus must be in [0, 1], got " + format_double(kp));
    }
    // Descending Landen transformation seeded with k' itself (the AGM of 1 and k'), so a
    // parameter m = 1 - k'^2 that rounds to 1 in double precision still gives exact values.
    if (kp == 0.0) {
        const double sech = 1.0 / std::cosh(u);
        return {std::tanh(u), sech, sech};
    }
    if (const auto near_one = jacobi_near_separatrix(u, kp)) return *near_one;
    if (std::fabs(u) < 1e-8) {
        // The Maclaurin series: the next terms are u^2/6 and u^4/24 times smaller, below
        // rounding. (The Landen recursion below would overflow for |u| < 1e-154.)
        const double m = (1.0 - kp) * (1.0 + kp);
        return {u, 1.0 - 0.5 * u * u, 1.0 - 0.5 * m * u * u};
    }
    std::array<double, 32> em{};
    std::array<double, 32> en{};
    double a = 1.0;
    double b = kp;
    double c = 0.5 * (a + b);
    int last = 0;
    for (int i = 0; i < static_cast<int>(em.size()); ++i) {
        em[i] = a;
        en[i] = b;
        c = 0.5 * (a + b);
        last = i;
        if (std::fabs(a - b) <= 1e-10 * a) break;
        b = std::sqrt(a * b);
        a = c;
    }
    const double v = u * c;
    double sn = std::sin(v);
    double cn = std::cos(v);
    double dn = 1.0;
    if (sn == 0.0) return {sn, cn, dn};
    a = cn / sn;
    c *= a;
    for (int i = last; i >= 0; --i) {
        b = em[i];
        a *= c;
        c *= dn;
        dn = (en[i] + a) / (b + a);
        a = c / b;
    }
    a = 1.0 / std::sqrt(c * c + 1.0);
    sn = std::copysign(a, sn);
    cn = c * sn;
    return {sn, cn, dn};
}

exact_solution::exact_solution(const pendulum::amplitude& a) : theta0_(a.radians()) {
    const double theta0 = theta0_;
    k_ = a.k();
    kp_ = a.kp();
    kp_extended_ = a.kp_extended();
    // In extended precision from the exact amplitude, rounded once.
    constexpr long double pi_extended = std::numbers::pi_v<long double>;
    const long double agm_kp = agm_extended(1, kp_extended_);
    quarter_ = static_cast<double>(0.5L * pi_extended / agm_kp);
    period_ratio_ = static_cast<double>(1 / agm_kp);
    frequency_ratio_ = static_cast<double>(agm_kp);
    if (theta0 < small_amplitude) {
        // q = (k/4)^2 (1 + k^2/2 + ...) with k = theta0/2 (1 - theta0^2/24): ln q to double,
        // for subnormal theta0 too (where k itself would round).
        log_nome_ = 2.0 * std::log(theta0) - std::log(64.0);
        small_c1_ = theta0 + theta0 * theta0 * theta0 / 192.0;
        small_c3_ = -theta0 * theta0 * theta0 / 192.0;
        return;
    }
    // K(k')/K(k) = AGM(1, k')/AGM(1, k). In doubles the rounding of k and k' alone costs
    // 10 ulps in c5 at pi/2 (|ln q| (n + 1/2) = 7.9 times their relative error).
    log_nome_ = -pi_extended * agm_kp / agm_extended(1, a.k_extended());
}

double exact_solution::period_ratio() const { return period_ratio_; }

double exact_solution::frequency_ratio() const { return frequency_ratio_; }

double exact_solution::nome() const { return static_cast<double>(std::exp(log_nome_)); }

double exact_solution::small_theta(double phase, bool complementary) const {
    // theta = c1 cos x + c3 cos 3x; with y = pi/2 - x, cos x = sin y and cos 3x = -sin 3y.
    if (complementary) return small_c1_ * std::sin(phase) - small_c3_ * std::sin(3.0 * phase);
    return small_c1_ * std::cos(phase) + small_c3_ * std::cos(3.0 * phase);
}

double exact_solution::theta_in_quarter(double r, double sign) const {
    if (theta0_ < small_amplitude) {
        // Two harmonics are exact to double here (c5/c1 < 1e-33), and k = sin(theta0/2)
        // would lose digits for subnormal theta0. w/w0 = pi/(2K).
        const double w = frequency_ratio();
        return r <= 0.5 * quarter_ ? sign * small_theta(w * r, false) : sign * small_theta(w * (quarter_ - r), true);
    }
    // r in [0, K]. The cn form is exact where cn is far from its zero (first half of the
    // quarter); the sn/dn form with u = K - r small is exact in the second half.
    if (r <= 0.5 * quarter_) {
        const auto j = jacobi(r, kp_);
        return sign * 2.0 * std::atan2(k_ * j.cn, kp_);
    }
    const auto j = jacobi(quarter_ - r, kp_);
    return sign * 2.0 * std::atan2(k_ * j.sn, j.dn);
}

double exact_solution::theta(double w0_t) const {
    if (!std::isfinite(w0_t)) {
        throw domain_error("time must be finite, got " + format_double(w0_t));
    }
    // Symmetries: even about 0, period 4K, odd about K.
    const double period = 4.0 * quarter_;
    double r = std::fabs(w0_t);
    if (r >= period) r = std::fmod(r, period);
    if (r > 2.0 * quarter_) r = period - r;
    double sign = 1.0;
    if (r > quarter_) {
        sign = -1.0;
        r = 2.0 * quarter_ - r;
    }
    return theta_in_quarter(r, sign);
}

double exact_solution::theta_at_fraction(double s) const {
    if (!std::isfinite(s)) {
        throw domain_error("time must be finite, got " + format_double(s));
    }
    // Each step below is exact in floating point, so the reduction adds no error.
    s = std::fabs(s);
    s -= std::floor(s);
    if (s > 0.5) s = 1.0 - s;
    double sign = 1.0;
    if (s > 0.25) {
        sign = -1.0;
        s = 0.5 - s;
    }
    if (s <= 0.125) return theta_in_quarter(4.0 * quarter_ * s, sign);
    if (theta0_ < small_amplitude) return sign * small_theta(0.5 * pi * (1.0 - 4.0 * s), true);
    // u = K (1 - 4 s) is formed without cancellation, then handed over as r = K - u.
    const auto j = jacobi(quarter_ * (1.0 - 4.0 * s), kp_);
    return sign * 2.0 * std::atan2(k_ * j.sn, j.dn);
}

double exact_solution::coefficient(int n) const {
    if (n < 0) throw domain_error("harmonic index must be >= 0, got " + std::to_string(n));
    if (theta0_ < small_amplitude) {
        // Small amplitudes: the nome's closed form loses digits like eps |ln q|; the series
        // c_{2n+1} = 8 (-1)^n (theta0/8)^(2n+1) / (2n+1) (1 + O(theta0^2)) is exact to double
        // here (c1 = theta0 + theta0^3/192, c3 = -theta0^3/192 to within theta0^2/16).
        if (n == 0) return theta0_ + theta0_ * theta0_ * theta0_ / 192.0;
        const double h = 2.0 * n + 1.0;
        const double sign = (n % 2 == 0) ? 1.0 : -1.0;
        return sign * 8.0 * std::pow(0.125 * theta0_, h) / h;
    }
    // In extended precision, rounded once: q^(n + 1/2) carries (n + 1/2) times the relative
    // error of q.
    using real = long double;
    const real h = 2 * n + 1;
    const real sign = (n % 2 == 0) ? 1 : -1;
    if (theta0_ <= 0.5 * pi) {
        // exp((n + 1/2) ln q) would carry the rounding of ln q times |ln q| (18 at 1e-3): 350
        // ulps in c5 near 1e-8. The nome's own series (DLMF 19.5.5) in
        // lambda = (1 - sqrt k')/(2 (1 + sqrt k')) = (1 - k')/(2 (1 + sqrt k')^2), with
        // 1 - k' = 2 sin^2(theta0/4), has no cancellation; lambda <= 0.0433 here, so the
        // terms through lambda^21 leave an error below 1e-23 of q.
        const real s = std::sin(0.25L * theta0_);
        const real root_kp = std::sqrt(kp_extended_);
        const real lambda = s * s / ((1 + root_kp) * (1 + root_kp));
        const real l4 = (lambda * lambda) * (lambda * lambda);
        const real q = lambda * (1 + l4 * (2 + l4 * (15 + l4 * (150 + l4 * (1707 + l4 * 20910)))));
        // q^(n + 1/2) by products (powl is slow), and q^(2n + 1) its square.
        real root = std::sqrt(q);
        for (int i = 0; i < n; ++i) root *= q;
        return static_cast<double>(sign * 8 * root / (h * (1 + root * root)));
    }
    const real root = std::exp((n + 0.5L) * log_nome_);
    return static_cast<double>(sign * 8 * root / (h * (1 + root * root)));
}

double exact_solution::coefficient_by_quadrature(int n) const {
    if (n < 0) throw domain_error("harmonic index must be >= 0, got " + std::to_string(n));
    // c_{2n+1} = (4/pi) int_0^{pi/2} theta(2 K x / pi) cos((2n+1) x) dx, by the symmetries
    // of theta (even, odd about a quarter period). The integrand is smooth and periodic, so
    // the trapezoidal rule on the quarter period (the rule on the whole period, folded)
    // converges geometrically: the number of intervals L is doubled until two rules agree to
    // an absolute accuracy just above the integrand's rounding (it is of size theta0).
    const double harmonic = 2 * n + 1;
    const double tolerance = 1e-15 * theta0_;
    const auto integrand = [&](double x) { return theta_at_fraction(x / (2.0 * pi)) * std::cos(harmonic * x); };
    // The rule with L intervals from its node sum (the end pi/2 contributes zero: every odd
    // harmonic vanishes there): (4/pi) (pi/(2L)) sum = (2/L) sum.
    int intervals = 16;
    double sum = 0.5 * integrand(0.0);
    for (int m = 1; m < intervals; ++m) sum += integrand(0.5 * pi * m / intervals);
    double coarse = 2.0 * sum / intervals;
    for (; intervals < max_quadrature_intervals; intervals *= 2) {
        // The finer rule adds the midpoints of the coarse one's intervals.
        for (int m = 1; m < 2 * intervals; m += 2) sum += integrand(0.25 * pi * m / intervals);
        const double fine = sum / intervals;
        if (std::fabs(fine - coarse) <= tolerance) return fine;
        coarse = fine;
    }
    throw std::runtime_error("quadrature of c" + std::to_string(2 * n + 1) + " did not converge with " +
                             std::to_string(max_quadrature_intervals) + " intervals");
}

double period_ratio(const amplitude& theta0) {
    // As exact_solution's, without the nome (a second AGM) that only the coefficients need.
    return static_cast<double>(exact_period_extended(theta0));
}

std::vector<double> fourier_coefficients(const amplitude& theta0, int count) {
    const exact_solution solution(theta0);
    std::vector<double> c;
    c.reserve(count > 0 ? count : 0);
    for (int n = 0; n < count; ++n) c.push_back(solution.coefficient(n));
    return c;
}

}  // namespace pendulum
