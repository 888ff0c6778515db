// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/motion.hpp"

#include "pendulum/amplitude.hpp"
#include "pendulum/gsl_support.hpp"
#include "pendulum/mp_real.hpp"
#include "pendulum/phase.hpp"
#include "pendulum/start_energy.hpp"
#include "pendulum/written_mp.hpp"


#include <cfloat>
#include <cmath>
#include <cstdio>
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

/// A double-double: hi + lo with |lo| below half an ulp of hi (to rounding).
struct double_double {
    double hi;
    double lo;
};

/// a + b exactly as a double-double (Knuth's two-sum).
double_double two_sum(double a, double b) {
    const double s = a + b;
    const double v = s - a;
    return {s, (a - (s - v)) + (b - v)};
}

/// x + y for double-doubles, to about 2^-104 of the larger.
double_double add(double_double x, double_double y) {
    const double_double s = two_sum(x.hi, y.hi);
    return two_sum(s.hi, s.lo + x.lo + y.lo);
}

/// x / y for double-doubles, y > 0: the quotient's double and, by an exact fma, its remainder.
double_double divide(double_double x, double_double y) {
    const double q = x.hi / y.hi;
    const double rest = std::fma(-q, y.hi, x.hi);
    return two_sum(q, (rest + x.lo - q * y.lo) / y.hi);
}

/// dn(x | k) at the double-double x: dn at its double, less k^2 sn cn times its low part
/// (dn' = -k^2 sn cn).
double dn_at(double_double x, double kp) {
    const auto j = jacobi(x.hi, kp);
    return j.dn - (1.0 - kp) * (1.0 + kp) * j.sn * j.cn * x.lo;
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
    // F is of degree 0 in (s, c): scaled by a power of 2 to the larger of 1, their squares
    // neither underflow (s = 1e-300) nor overflow, and R_F stays in its domain.
    const int scale = std::ilogb(std::max(s, std::fabs(c)));
    s = std::scalbn(s, -scale);
    c = std::scalbn(c, -scale);
    const auto rf = carlson_rf;
    if (s == 0) return c > 0 ? 0.0 : std::numbers::pi / agm(1.0, kp);
    const double half = s * rf(c * c, c * c + kp * s * kp * s, s * s + c * c);
    if (c >= 0) return half;
    // Beyond pi/2: F(psi) = 2 K - F(pi - psi).
    return std::numbers::pi / agm(1.0, kp) - half;
}

motion motion::from_state(pendulum_state start) {
    return from_state(written_number(start.theta), written_number(start.omega));
}

namespace {

/// True for a state at rest (omega exactly 0) at an angle in (0, pi]: an amplitude.
bool at_rest_within_pi(const written_number& theta, const written_number& omega) {
    if (omega.value() != 0 || !(theta.value() > 0 && theta.value() < 4.0)) return false;
    constexpr mpfr_prec_t bits = 1280;
    return !(evaluate_written(theta, bits) > mp::pi(bits));
}

/// The start as a message names it.
std::string state_text(const written_number& theta, const written_number& omega) {
    const auto shown = [](const written_number& x) { return x.text().empty() ? format_double(x.value()) : x.text(); };
    return "theta0 = " + shown(theta) + ", omega0 = " + shown(omega);
}

/// E in decimal where a double holds it to fewer digits than 17 or not at all (subnormal or
/// 0), as numbers_of() says it for a state; empty where it is a normal double.
std::string unheld_energy(long double energy) {
    if (energy == 0 || std::fabs(energy) >= DBL_MIN) return "";
    char text[64];
    std::snprintf(text, sizeof text, "%.17Lg", energy);
    return text;
}

}  // namespace

motion motion::from_state(const written_number& theta, const written_number& omega) {
    if (!std::isfinite(theta.value()) || !std::isfinite(omega.value())) {
        throw domain_error("a start needs a finite angle and velocity, got theta = " + format_double(theta.value()) +
                           ", omega = " + format_double(omega.value()));
    }
    if (theta.value() == 0 && omega.value() == 0) {
        throw domain_error("the pendulum at rest at the bottom does not move: give a start with theta or omega "
                           "not 0 (or an energy > 0)");
    }
    if (at_rest_within_pi(theta, omega)) {
        // Released at rest: the amplitude itself, with its distance from pi (pi is refused).
        // A double is itself: the one nearest pi is pi - 1.2e-16 (the text "pi" is refused).
        constexpr double pi_lo = 1.2246467991473532e-16;
        const auto held = [&] {
            return theta.value() == pi ? pendulum::amplitude::from_pi(pi_lo) : pendulum::amplitude(theta.value());
        };
        motion m = from_amplitude(theta.text().empty() ? held() : parse_amplitude(theta.text()));
        m.first_ = theta;
        m.second_ = omega;
        return m;
    }
    const start_energy e = decide_start([&](mpfr_prec_t bits) { return state_energy_at(theta, omega, bits); },
                                        state_text(theta, omega), exactly_separatrix(theta, omega));
    motion m;
    m.start_ = {theta.value(), omega.value()};
    m.first_ = theta;
    m.second_ = omega;
    m.prepare(numbers_of(e), 0.5 * std::fabs(omega.value()));
    return m;
}

motion motion::from_energy(double energy) { return from_energy(written_number(energy)); }

motion motion::from_energy(const written_number& energy) {
    const double value = energy.value();
    if (!(value > 0 && std::isfinite(value))) {
        throw domain_error("the energy must be > 0 (in units of m g L, from the bottom; 2 is the separatrix), got " +
                           (energy.text().empty() ? format_double(value) : energy.text()));
    }
    const start_energy e = decide_start([&](mpfr_prec_t bits) { return written_energy_at(energy, bits); },
                                        "energy = " + (energy.text().empty() ? format_double(value) : energy.text()),
                                        exactly_two(energy));
    const start_numbers n = numbers_of(e);
    motion m;
    m.origin_ = origin::energy;
    m.first_ = energy;
    // From the bottom: omega = sqrt(2 E) and |omega|/2 = sqrt(E/2), each rounded once.
    m.start_ = {0.0, n.speed};
    m.prepare(n, n.half_speed);
    return m;
}

motion motion::from_amplitude(const pendulum::amplitude& theta0) {
    motion m;
    const double k = theta0.k();
    const double kp = theta0.kp();
    m.origin_ = origin::amplitude;
    m.start_ = {theta0.radians(), 0.0};
    m.start_angle_ = theta0.radians();
    m.kind_ = regime::libration;
    // E = 2 k^2 and 2 - E = 2 k'^2, each rounded once from extended precision.
    m.energy_ = static_cast<double>(2.0L * theta0.k_extended() * theta0.k_extended());
    m.gap_ = static_cast<double>(2.0L * theta0.kp_extended() * theta0.kp_extended());
    m.energy_unheld_ = unheld_energy(2.0L * theta0.k_extended() * theta0.k_extended());
    m.k_ = k;
    m.kp_ = kp;
    m.libration_.emplace(theta0);
    m.given_.emplace(theta0);
    m.quarter_ = m.libration_->quarter_period();
    m.at_quarter_ = true;
    return m;
}

void motion::prepare(const start_numbers& n, double half_speed) {
    energy_ = n.energy;
    gap_ = n.gap;
    energy_unheld_ = n.energy_unheld;
    cancelled_ = n.cancelled;
    kind_ = n.kind;
    k_ = n.k;
    kp_ = n.kp;
    // The motion backwards is the mirror image of the motion forwards from the mirrored start.
    mirror_ = start_.omega < 0 ? -1.0 : 1.0;
    const auto [turns, angle] = reduce(mirror_ * start_.theta);
    turns_ = turns;
    start_angle_ = mirror_ * angle;
    if (kind_ == regime::libration) {
        given_.emplace(amplitude::from_parts(n.theta0, n.d, k_, kp_));
        libration_.emplace(*given_);
        quarter_ = libration_->quarter_period();
        // Time from the turning point +theta0 down to the start: psi = am(tau) with
        // sn : cn = |omega|/2 : k' sin(theta/2) (from theta = 2 atan2(k cn, k'),
        // theta'/w0 = -2 k k' sn/dn). Moving forwards, the start is that time before it; from
        // the bottom it is a quarter period exactly.
        offset_ = angle == 0 ? -quarter_ : -elliptic_f(half_speed, kp_ * std::sin(0.5 * angle), kp_);
        start_fraction_ = (offset_ + (mirror_ < 0 ? 2.0 * quarter_ : 0.0)) / (4.0 * quarter_);
        at_quarter_ = angle == 0;
        return;
    }
    if (kind_ == regime::separatrix) {
        // theta = 2 atan(sinh tau): tau = asinh(tan(theta/2)).
        offset_ = std::asinh(std::tan(0.5 * angle));
        return;
    }
    quarter_ = n.quarter;
    quarter_lo_ = n.quarter_lo;
    half_turn_ = n.half_turn;
    half_turn_lo_ = n.half_turn_lo;
    k_lo_ = n.k_lo;
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

double motion::period_ratio() const {
    // T/T0 = 1/agm(1, k') and T_rev/T0 = k/(2 agm(1, k')), each with one division.
    if (kind_ == regime::libration) return libration_->period_ratio();
    if (kind_ == regime::rotation) return k_ / (2.0 * agm(1.0, kp_));
    return period();  // throws at the separatrix
}

amplitude motion::amplitude() const {
    if (kind_ != regime::libration) {
        throw domain_error("a " + std::string(row_of(kind_).name) + " (" + std::string(row_of(kind_).energy) +
                           ", here E = " + format_double(energy_) +
                           ") has no amplitude: only a libration (E < 2) swings between turning points");
    }
    // Released at rest from an amplitude: that amplitude, with whichever of theta0 and pi -
    // theta0 is exact; from a state or an energy: the moduli are all there is.
    return *given_;
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

std::pair<double, bool> motion::libration_clock_parts() const {
    (void)libration();
    return {offset_, mirror_ < 0};
}

double motion::libration_center() const {
    (void)libration();
    return mirror_ * turns_ * two_pi_hi + mirror_ * turns_ * two_pi_lo;
}

motion::folded_time motion::fraction_of_period(double s) const {
    (void)libration();
    if (!std::isfinite(s)) throw domain_error("time must be finite, got " + format_double(s));
    // Whole periods are dropped and a half period folded away, each step exact (s less the
    // integer nearest it, then +-1/2 by Sterbenz): any libration has theta(t + T/2) =
    // 2 center - theta(t) and omega(t + T/2) = -omega(t), so every multiple of T/2 lands on
    // the start or its mirror image exactly, whatever the start's place in its period.
    const double rest = s - std::nearbyint(s);
    if (rest > 0.25) return {rest - 0.5, true};
    if (rest < -0.25) return {rest + 0.5, true};
    return {rest, false};
}

double motion::theta_at_fraction(double s) const {
    const folded_time f = fraction_of_period(s);
    const double sign = f.half ? -1.0 : 1.0;
    if (f.rest == 0) return f.half ? libration_center() - start_angle_ : start_.theta;
    return libration_center() + sign * libration_->theta_at_fraction(f.rest + start_fraction_);
}

double motion::velocity_at_fraction(double s) const {
    const folded_time f = fraction_of_period(s);
    const double sign = f.half ? -1.0 : 1.0;
    if (f.rest == 0) return sign * start_.omega;
    return sign * pendulum::velocity_at_fraction(*libration_, f.rest + start_fraction_);
}

double start_phase(const motion& m, const fourier_solution& solution) {
    return std::remainder(solution.frequency_ratio * m.libration_clock(0.0), 2 * pi);
}

double motion::forward_theta(double tau) const {
    switch (kind_) {
    case regime::libration: return libration_->theta(tau);
    case regime::separatrix: return 2.0 * std::atan(std::sinh(tau));
    case regime::rotation: return rotation_theta(tau, 0.0);  // one revolution takes 2 k K
    }
    return 0.0;
}

double motion::forward_velocity(double tau) const {
    switch (kind_) {
    case regime::libration: return pendulum::velocity_at_fraction(*libration_, tau / (4.0 * quarter_));
    case regime::separatrix: return 2.0 / std::cosh(tau);
    case regime::rotation: return rotation_velocity(tau, 0.0);
    }
    return 0.0;
}

motion::rotation_place motion::place_in_revolution(double tau, double tau_lo) const {
    // u = tau / k less the nearest whole revolutions 2 K, every step a double-double: next to
    // the top theta and omega go as K - |r|, whose absolute digits are their relative ones.
    const double n = std::nearbyint(tau / (2.0 * half_turn_));
    const double whole = -2.0 * n * half_turn_;  // rounded; the fma below keeps what it lost
    const double_double turns{whole, std::fma(-2.0 * n, half_turn_, -whole) - 2.0 * n * half_turn_lo_};
    const double_double rest = add(two_sum(tau, tau_lo), turns);
    const double_double r = divide(rest, {k_, k_lo_});
    return {n, r.hi, r.lo};
}

double motion::rotation_theta(double tau, double tau_lo) const {
    // theta = 2 am(r): am(|r|) within K/2 of the bottom, am(K - u) = atan2(cn(u), k' sn(u))
    // beyond, each corrected by its derivative (dn) times the low part of its argument.
    const rotation_place p = place_in_revolution(tau, tau_lo);
    const double sign = p.r < 0 ? -1.0 : 1.0;
    const double_double r{std::fabs(p.r), sign * p.r_lo};
    double am = 0;
    if (r.hi <= 0.5 * quarter_) {
        const auto j = jacobi(r.hi, kp_);
        am = std::atan2(j.sn, j.cn) + j.dn * r.lo;
    } else {
        const double_double u = add({quarter_, quarter_lo_}, {-r.hi, -r.lo});
        const auto j = jacobi(u.hi, kp_);
        am = std::atan2(j.cn, kp_ * j.sn) - kp_ / j.dn * u.lo;
    }
    return p.n * 2.0 * pi + 2.0 * sign * am;
}

double motion::rotation_velocity(double tau, double tau_lo) const {
    // dn(u) = dn(|r|) within K/2 of the bottom and k'/dn(K - |r|) beyond: next to the top
    // omega is k'/dn(K - |r|), whose relative digits are the absolute digits of K - |r|.
    const rotation_place p = place_in_revolution(tau, tau_lo);
    const double_double r = p.r < 0 ? double_double{-p.r, -p.r_lo} : double_double{p.r, p.r_lo};
    if (r.hi <= 0.5 * quarter_) return 2.0 / k_ * dn_at(r, kp_);
    const double_double u = add({quarter_, quarter_lo_}, {-r.hi, -r.lo});
    return 2.0 / k_ * (kp_ / dn_at(u, kp_));
}

namespace {

/// sin(theta) of a rotation theta = 2 am(r | k), r in [-K, K]: 2 sn cn, beyond K/2 through
/// v = K - |r| (sn = cn(v)/dn(v), cn = k' sn(v)/dn(v)), so that next to the top, where theta is
/// pi to every digit a double has, it keeps its own.
double rotation_sine(double r, double quarter, double kp) {
    const double sign = r < 0 ? -1.0 : 1.0;
    r = std::fabs(r);
    if (r <= 0.5 * quarter) {
        const auto j = jacobi(r, kp);
        return sign * 2.0 * j.sn * j.cn;
    }
    const auto j = jacobi(quarter - r, kp);
    return sign * 2.0 * kp * j.cn * j.sn / (j.dn * j.dn);
}

}  // namespace

double motion::acceleration(double w0_t) const {
    if (!std::isfinite(w0_t)) throw domain_error("time must be finite, got " + format_double(w0_t));
    const double tau = w0_t + offset_;
    switch (kind_) {
    case regime::libration: return -std::sin(theta(w0_t));
    case regime::separatrix: return -mirror_ * 2.0 * std::tanh(tau) / std::cosh(tau);
    case regime::rotation: {
        const double revolution = 2.0 * k_ * quarter_;
        const double r = (tau - std::nearbyint(tau / revolution) * revolution) / k_;
        return -mirror_ * rotation_sine(r, quarter_, kp_);
    }
    }
    return 0.0;
}

double motion::theta(double w0_t) const {
    if (!std::isfinite(w0_t)) throw domain_error("time must be finite, got " + format_double(w0_t));
    // At the start the angle is what was given, not its round trip through the time offset.
    if (w0_t == 0) return start_.theta;
    if (kind_ == regime::rotation) {
        const double_double tau = two_sum(w0_t, offset_);
        return mirror_ * (turns_ * two_pi_hi + rotation_theta(tau.hi, tau.lo) + turns_ * two_pi_lo);
    }
    return mirror_ * (turns_ * two_pi_hi + forward_theta(w0_t + offset_) + turns_ * two_pi_lo);
}

double motion::velocity(double w0_t) const { return velocity(w0_t, 0.0); }

double motion::velocity(double w0_t, double low) const {
    if (!std::isfinite(w0_t)) throw domain_error("time must be finite, got " + format_double(w0_t));
    if (w0_t == 0 && low == 0) return start_.omega;
    if (kind_ == regime::rotation) {
        const double_double tau = add(two_sum(w0_t, offset_), {low, 0.0});
        return mirror_ * rotation_velocity(tau.hi, tau.lo);
    }
    return mirror_ * forward_velocity(w0_t + offset_) + acceleration(w0_t) * low;
}

}  // namespace pendulum
