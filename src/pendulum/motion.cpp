// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/motion.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/gsl_support.hpp"
#include "pendulum/mp_real.hpp"
#include "pendulum/phase.hpp"


#include <cmath>
#include <numbers>
#include <string>

namespace pendulum {

using std::numbers::pi;

namespace {

constexpr regime_row rows[3] = {
    {regime::libration, "libration", "E < 2", "period T"},
    {regime::separatrix, "separatrix", "E = 2", "no period: the top is reached as t -> infinity"},
    {regime::rotation, "rotation", "E > 2", "revolution period T_rev"},
};

/// 2 pi = two_pi_hi + two_pi_lo + O(1e-32).
constexpr double two_pi_hi = 2.0 * std::numbers::pi;
constexpr double two_pi_lo = 2.4492935982947064e-16;

/// The number of whole turns nearest theta, and theta less those turns, in (-pi, pi] up to
/// rounding (the subtraction uses 2 pi in two parts, so the reduced angle keeps its digits).
struct reduced_angle {
    double turns;
    double angle;
};

reduced_angle reduce(double theta) {
    const double turns = std::nearbyint(theta / two_pi_hi);
    if (turns == 0) return {0.0, theta};
    return {turns, std::fma(-turns, two_pi_hi, theta) - turns * two_pi_lo};
}

/// Working precision for the energy of a state: a double's square and the cosine of a
/// double angle carry 106 and 53 bits; the gap between them is exact far below any double.
constexpr mpfr_prec_t energy_bits = 320;

/// am(r | k) for r in [-K, K], in [-pi/2, pi/2]: beyond K/2 through u = K - r, where
/// sn(K - u) = cn(u)/dn(u) and cn(K - u) = k' sn(u)/dn(u) keep their digits next to k = 1.
double am_reduced(double r, double quarter, double kp) {
    const double sign = r < 0 ? -1.0 : 1.0;
    r = std::fabs(r);
    if (r <= 0.5 * quarter) {
        const auto j = jacobi(r, kp);
        return sign * std::atan2(j.sn, j.cn);
    }
    const auto j = jacobi(quarter - r, kp);
    return sign * std::atan2(j.cn, kp * j.sn);
}

/// dn(r | k) for r in [-K, K]: dn(K - u) = k'/dn(u) beyond K/2.
double dn_reduced(double r, double quarter, double kp) {
    r = std::fabs(r);
    if (r <= 0.5 * quarter) return jacobi(r, kp).dn;
    return kp / jacobi(quarter - r, kp).dn;
}

}  // namespace

const regime_row (&regime_rows())[3] { return rows; }

const regime_row& row_of(regime kind) {
    for (const auto& row : rows) {
        if (row.kind == kind) return row;
    }
    throw std::logic_error("regime without a row");
}

double elliptic_f(double s, double c, double kp) {
    if (!(s >= 0 && (s > 0 || c != 0) && std::isfinite(s) && std::isfinite(c))) {
        throw domain_error("elliptic_f needs s >= 0 and (s, c) nonzero, got " + format_double(s) + ", " +
                           format_double(c));
    }
    const auto rf = carlson_rf;
    if (s == 0) return c > 0 ? 0.0 : std::numbers::pi / agm(1.0, kp);
    const double half = s * rf(c * c, c * c + kp * s * kp * s, s * s + c * c);
    if (c >= 0) return half;
    // Beyond pi/2: F(psi) = 2 K - F(pi - psi).
    return std::numbers::pi / agm(1.0, kp) - half;
}

motion motion::from_state(pendulum_state start) {
    if (!std::isfinite(start.theta) || !std::isfinite(start.omega)) {
        throw domain_error("a start needs a finite angle and velocity, got theta = " + format_double(start.theta) +
                           ", omega = " + format_double(start.omega));
    }
    // E = omega^2/2 + 2 sin^2(theta/2), 2 - E = 2 cos^2(theta/2) - omega^2/2: both exact here
    // far below rounding, so a state within 1e-12 of the separatrix keeps its gap's digits.
    const mp::real half_angle = mp::real(start.theta, energy_bits) / 2.0;
    const mp::real kinetic = mp::real(start.omega, energy_bits) * mp::real(start.omega, energy_bits) / 2.0;
    const mp::real s = mp::sin(half_angle);
    const mp::real c = mp::cos(half_angle);
    const mp::real energy = kinetic + 2.0 * s * s;
    const mp::real gap = 2.0 * c * c - kinetic;
    if (energy.is_zero()) {
        throw domain_error("the pendulum at rest at the bottom does not move: give a start with theta or omega "
                           "not 0 (or an energy > 0)");
    }
    motion m;
    m.start_ = start;
    m.prepare(energy.to_double(), gap.to_double(), 0.5 * std::fabs(start.omega));
    return m;
}

motion motion::from_energy(double energy) {
    if (!(energy > 0 && std::isfinite(energy))) {
        throw domain_error("the energy must be > 0 (in units of m g L, from the bottom; 2 is the separatrix), got " +
                           format_double(energy));
    }
    motion m;
    m.origin_ = origin::energy;
    m.start_ = {0.0, std::sqrt(2.0 * energy)};
    // From the bottom, |omega|/2 = sqrt(E/2) = k for a libration, without the rounding of omega.
    m.prepare(energy, 2.0 - energy, std::sqrt(0.5 * energy));
    return m;
}

motion motion::from_amplitude(const pendulum::amplitude& theta0) {
    motion m;
    const double k = theta0.k();
    const double kp = theta0.kp();
    m.origin_ = origin::amplitude;
    m.start_ = {theta0.radians(), 0.0};
    m.kind_ = regime::libration;
    m.energy_ = 2.0 * k * k;
    m.gap_ = 2.0 * kp * kp;
    m.k_ = k;
    m.kp_ = kp;
    m.libration_.emplace(theta0);
    m.given_.emplace(theta0);
    m.quarter_ = m.libration_->quarter_period();
    return m;
}

void motion::prepare(double energy, double gap, double half_speed) {
    energy_ = energy;
    gap_ = gap;
    // The motion backwards is the mirror image of the motion forwards from the mirrored start.
    mirror_ = start_.omega < 0 ? -1.0 : 1.0;
    const auto [turns, angle] = reduce(mirror_ * start_.theta);
    turns_ = turns;
    if (gap > 0) {
        kind_ = regime::libration;
        k_ = std::sqrt(0.5 * energy);
        kp_ = std::sqrt(0.5 * gap);
        // The amplitude from its moduli: theta0 = 2 atan2(k, k'), pi - theta0 = 2 atan2(k', k).
        libration_.emplace(amplitude::from_parts(2.0 * std::atan2(k_, kp_), 2.0 * std::atan2(kp_, k_), k_, kp_));
        quarter_ = libration_->quarter_period();
        // Time from the turning point +theta0 down to the start: psi = am(tau) with
        // sn : cn = |omega|/2 : k' sin(theta/2) (from theta = 2 atan2(k cn, k'),
        // theta'/w0 = -2 k k' sn/dn). Moving forwards, the start is that time before it.
        offset_ = -elliptic_f(half_speed, kp_ * std::sin(0.5 * angle), kp_);
        return;
    }
    if (gap == 0) {
        kind_ = regime::separatrix;
        k_ = 1.0;
        kp_ = 0.0;
        // theta = 2 atan(sinh tau): tau = asinh(tan(theta/2)).
        offset_ = std::asinh(std::tan(0.5 * angle));
        return;
    }
    kind_ = regime::rotation;
    k_ = std::sqrt(2.0 / energy);
    kp_ = std::sqrt(-gap / energy);
    quarter_ = 0.5 * pi / agm(1.0, kp_);
    // theta = 2 am(tau / k): tau = k F(theta/2 | k), with theta/2 in (-pi/2, pi/2].
    const double half = 0.5 * angle;
    const double f = elliptic_f(std::fabs(std::sin(half)), std::cos(half), kp_);
    offset_ = k_ * std::copysign(f, half);
}

double motion::period() const {
    switch (kind_) {
    case regime::libration: return 4.0 * quarter_;
    case regime::rotation: return 2.0 * k_ * quarter_;
    case regime::separatrix: break;
    }
    throw domain_error("the separatrix (E = 2) has no period: the pendulum approaches the top in infinite time");
}

double motion::period_ratio() const { return period() / (2.0 * pi); }

amplitude motion::amplitude() const {
    if (kind_ != regime::libration) {
        throw domain_error("a " + std::string(row_of(kind_).name) + " (" + std::string(row_of(kind_).energy) +
                           ", here E = " + format_double(energy_) +
                           ") has no amplitude: only a libration (E < 2) swings between turning points");
    }
    // Released at rest from an amplitude: that amplitude, with whichever of theta0 and pi -
    // theta0 is exact; from a state or an energy: the moduli are all there is.
    if (given_) return *given_;
    return amplitude::from_parts(libration_->amplitude(), 2.0 * std::atan2(kp_, k_), k_, kp_);
}

const exact_solution& motion::libration() const {
    if (kind_ != regime::libration) (void)amplitude();  // throws, naming the regime
    return *libration_;
}

double motion::libration_clock(double w0_t) const {
    (void)libration();
    // Backwards, theta = -theta_lib(t + offset) = theta_lib(t + offset + 2 K).
    return w0_t + offset_ + (mirror_ < 0 ? 2.0 * quarter_ : 0.0);
}

double motion::libration_center() const {
    (void)libration();
    return mirror_ * turns_ * two_pi_hi + mirror_ * turns_ * two_pi_lo;
}

double start_phase(const motion& m, const fourier_solution& solution) {
    return std::remainder(solution.frequency_ratio * m.libration_clock(0.0), 2 * pi);
}

double motion::forward_theta(double tau) const {
    switch (kind_) {
    case regime::libration: return libration_->theta(tau);
    case regime::separatrix: return 2.0 * std::atan(std::sinh(tau));
    case regime::rotation: {
        // One revolution takes 2 k K; within it, u = tau/k in [-K, K] and theta = 2 am(u).
        const double revolution = 2.0 * k_ * quarter_;
        const double n = std::nearbyint(tau / revolution);
        const double r = (tau - n * revolution) / k_;
        return n * 2.0 * pi + 2.0 * am_reduced(r, quarter_, kp_);
    }
    }
    return 0.0;
}

double motion::forward_velocity(double tau) const {
    switch (kind_) {
    case regime::libration: return velocity_at_fraction(*libration_, tau / (4.0 * quarter_));
    case regime::separatrix: return 2.0 / std::cosh(tau);
    case regime::rotation: {
        const double revolution = 2.0 * k_ * quarter_;
        const double r = (tau - std::nearbyint(tau / revolution) * revolution) / k_;
        return 2.0 / k_ * dn_reduced(r, quarter_, kp_);
    }
    }
    return 0.0;
}

double motion::theta(double w0_t) const {
    if (!std::isfinite(w0_t)) throw domain_error("time must be finite, got " + format_double(w0_t));
    // At the start the angle is what was given, not its round trip through the time offset.
    if (w0_t == 0) return start_.theta;
    return mirror_ * (turns_ * two_pi_hi + forward_theta(w0_t + offset_) + turns_ * two_pi_lo);
}

double motion::velocity(double w0_t) const {
    if (!std::isfinite(w0_t)) throw domain_error("time must be finite, got " + format_double(w0_t));
    if (w0_t == 0) return start_.omega;
    return mirror_ * forward_velocity(w0_t + offset_);
}

}  // namespace pendulum
