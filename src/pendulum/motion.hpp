// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/angle.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace pendulum {

/// The three kinds of motion of the simple pendulum, by energy E (per m g L, from the bottom).
enum class regime {
    libration,   ///< E < 2: swinging between two turning points
    separatrix,  ///< E = 2: approaching the top, reached only as t -> infinity
    rotation,    ///< E > 2: going over the top, round and round
};

/// A regime's name with its behaviour: the one row every list and message reads.
struct regime_row {
    regime kind;               ///< the regime
    std::string_view name;     ///< "libration", "separatrix", "rotation"
    std::string_view energy;   ///< its energies: "E < 2", ...
    std::string_view period;   ///< what its period is: "period T", "no period", ...
};

/// The three regimes, in order of energy.
const regime_row (&regime_rows())[3];

/// The row of a regime.
const regime_row& row_of(regime kind);

/// A start of the motion: an angle and an angular velocity in units of w0.
struct pendulum_state {
    double theta = 0;  ///< the angle in radians, any real value (not reduced)
    double omega = 0;  ///< theta'/w0, any sign
};

/// The numbers of a start's motion, each rounded once from its exact energy E and gap 2 - E.
struct start_numbers {
    regime kind = regime::libration;  ///< decided from the exact gap
    double energy = 0;                ///< E
    double gap = 0;                   ///< 2 - E
    double k = 0;                     ///< the modulus
    double kp = 0;                    ///< the complementary modulus
    double theta0 = 0;                ///< a libration's amplitude 2 atan2(k, k')
    double d = 0;                     ///< pi less it, 2 atan2(k', k)
    double half_speed = 0;            ///< sqrt(E/2): |omega|/2 at the bottom
    double speed = 0;                 ///< sqrt(2 E): |omega| at the bottom
    long cancelled = 0;               ///< bits the gap lost to cancellation of its terms
    double quarter = 0;               ///< a rotation's K(k), rounded once (0 for the others)
    double quarter_lo = 0;            ///< K(k) less that double
    double half_turn = 0;             ///< a rotation's half revolution k K(k) in w0 t, rounded once
    double half_turn_lo = 0;          ///< k K(k) less that double
    double k_lo = 0;                  ///< a rotation's k less its double k
    std::string energy_unheld;        ///< E in decimal where a double holds it to fewer digits, or not at all
};

/// The exact motion theta'' + sin(theta) = 0 from any start, in all three regimes.
///
/// Time is w0 t. theta(t) is unwrapped: a rotation's angle keeps rising (or falling), and
/// a libration swings about the multiple of 2 pi nearest its start. The moduli are kept with
/// their complements, computed from the energy gap 2 - E (exact for a state through MPFR), so
/// the motion stays accurate within 1e-12 of the separatrix on either side: libration
/// k = sqrt(E/2), k' = sqrt((2 - E)/2); rotation k = sqrt(2/E), k' = sqrt((E - 2)/E).
class motion {
public:
    /// The motion from a state (theta, omega); throws domain_error for a state that is not
    /// finite or for the pendulum at rest at the bottom (energy 0).
    static motion from_state(pendulum_state start);
    /// The motion from a state as written: its energy and gap from the numbers as written
    /// (MPFR), the regime decided from them (E = 2 the separatrix, as for 2pi/3 with 1; a start
    /// whose numbers cannot decide it is a domain_error). A state at rest (omega exactly 0) at
    /// an angle in (0, pi] is its amplitude, from_amplitude(parse_amplitude(theta)): pi - d
    /// keeps d, and pi itself is refused.
    static motion from_state(const written_number& theta, const written_number& omega);
    /// The motion launched from the bottom (theta = 0) with energy E > 0, moving forward:
    /// omega = sqrt(2 E). Throws domain_error naming the energy unless 0 < E < infinity.
    static motion from_energy(double energy);
    /// The same for an energy as written ("2-1e-20" is a libration, "2" the separatrix).
    static motion from_energy(const written_number& energy);
    /// The libration released at rest from amplitude theta0 (the paper's start).
    static motion from_amplitude(const pendulum::amplitude& theta0);

    /// How a motion was given: released at rest from an amplitude, from a state, or an energy.
    enum class origin { amplitude, state, energy };
    /// How this motion was given (from_amplitude, from_state or from_energy).
    origin given_as() const { return origin_; }
    /// The regime of the motion.
    regime kind() const { return kind_; }
    /// The energy E per m g L (from the bottom), rounded once.
    double energy() const { return energy_; }
    /// E in decimal where a double cannot hold it to every digit (below 2.2e-308, where it is
    /// subnormal or 0, or above the largest double); empty where energy() holds it.
    const std::string& energy_unheld() const { return energy_unheld_; }
    /// The first number as written: a state's angle, or the energy.
    const written_number& written_first() const { return first_; }
    /// A state's velocity as written (0 for the other origins).
    const written_number& written_second() const { return second_; }
    /// The bits the energy gap lost to cancellation of its terms (a state next to the separatrix).
    long cancelled_bits() const { return cancelled_; }
    /// The energy gap 2 - E, rounded once from its exact value (negative for a rotation).
    double energy_gap() const { return gap_; }
    /// The start (for from_energy: theta = 0, omega = sqrt(2 E) rounded).
    pendulum_state start() const { return start_; }
    /// The modulus k of the motion (libration sqrt(E/2), rotation sqrt(2/E), separatrix 1).
    double modulus() const { return k_; }
    /// The complementary modulus k' (0 at the separatrix).
    double complementary_modulus() const { return kp_; }
    /// True for libration and rotation: the separatrix has no period.
    bool has_period() const { return kind_ != regime::separatrix; }
    /// w0 T: the libration's period 4 K(k), or the rotation's revolution 2 k K(k); throws
    /// domain_error at the separatrix, which has none.
    double period() const;
    /// The period over the small-amplitude period 2 pi / w0 (T/T0 or T_rev/T0); throws as
    /// period() does.
    double period_ratio() const;
    /// The libration's amplitude (its turning point, in (0, pi)); throws domain_error for the
    /// other regimes, naming the regime.
    pendulum::amplitude amplitude() const;
    /// The libration's exact solution (released at its amplitude); throws as amplitude() does.
    const exact_solution& libration() const;

    /// A libration's own clock at time w0 t: the time since it was at its amplitude +theta0,
    /// where the paper's solutions start (theta = center + libration().theta(clock)); throws as
    /// amplitude() does.
    double libration_clock(double w0_t) const;
    /// libration_clock(0) as its two parts, each exact: the forward motion's time at the start
    /// and whether half a period (2 K) is added (a backwards start); throws as amplitude() does.
    std::pair<double, bool> libration_clock_parts() const;
    /// The multiple of 2 pi a libration swings about; throws as amplitude() does.
    double libration_center() const;
    /// A libration's theta at the time s periods T after its start: the start's place in its
    /// period is a fraction of it (-1/4 from the bottom moving forwards), so the turning points
    /// and crossings at the quarter periods land exactly, as for an amplitude; throws as
    /// amplitude() does.
    double theta_at_fraction(double s) const;
    /// theta'/w0 the same way.
    double velocity_at_fraction(double s) const;
    /// True where a libration's start is exactly at a quarter period (a turning point, or the
    /// bottom), so that theta_at_fraction() keeps every digit; elsewhere the start's place is a
    /// rounded fraction, and a time reduced in w0 t is the better clock.
    bool starts_at_quarter() const { return at_quarter_; }
    /// True where theta_at_fraction(s) and velocity_at_fraction(s) keep every digit: a start at
    /// a quarter period, or any start at a multiple of half a period (its start or mirror image).
    bool exact_at_fraction(double s) const { return at_quarter_ || 2.0 * s == std::nearbyint(2.0 * s); }

    /// theta at time w0 t, unwrapped (continuous in t).
    double theta(double w0_t) const;
    /// theta'/w0 at time w0 t.
    double velocity(double w0_t) const;
    /// theta'/w0 at the time w0 t + low, a double-double (|low| below half an ulp of w0 t):
    /// a rotation forms its place in the revolution and K - r next to the top as double-doubles,
    /// so that omega keeps its relative digits where it is e-189 (the time's every ulp moves it
    /// by 1e-16 of K there); the others correct velocity(w0_t) by acceleration() times low.
    double velocity(double w0_t, double low) const;
    /// theta''/w0^2 = -sin(theta) at time w0 t, from the Jacobi functions for a rotation and the
    /// separatrix, so that it keeps its relative digits next to the top.
    double acceleration(double w0_t) const;

private:
    motion() = default;
    /// Sets the regime, moduli and time offset from the start and its numbers.
    void prepare(const start_numbers& n, double half_speed);
    /// A time in periods since the start, less its whole periods and folded by a half period
    /// into [-1/4, 1/4] (`half` where it was folded), each step exact.
    struct folded_time {
        double rest;  ///< the time left in periods, in [-1/4, 1/4]
        bool half;    ///< true where a half period was taken away
    };
    /// The libration's time since the start, folded (throws for a time that is not finite).
    folded_time fraction_of_period(double s) const;
    /// theta and theta'/w0 of the forward motion (omega >= 0 after mirroring) at w0 t.
    double forward_theta(double tau) const;
    double forward_velocity(double tau) const;
    /// A rotation's place in its revolution at the double-double time tau + tau_lo: the whole
    /// revolutions n taken off and u = tau/k - 2 n K in [-K, K] as a double-double.
    struct rotation_place {
        double n;     ///< whole revolutions
        double r;     ///< u, rounded
        double r_lo;  ///< u less r
    };
    /// The place of the time tau + tau_lo in a rotation's revolution.
    rotation_place place_in_revolution(double tau, double tau_lo) const;
    /// A rotation's theta of the forward motion at the double-double time tau + tau_lo.
    double rotation_theta(double tau, double tau_lo) const;
    /// A rotation's theta'/w0 of the forward motion at the double-double time tau + tau_lo.
    double rotation_velocity(double tau, double tau_lo) const;

    regime kind_ = regime::libration;
    origin origin_ = origin::state;
    pendulum_state start_{};
    double energy_ = 0;
    double gap_ = 0;
    double k_ = 0;
    double kp_ = 0;
    double quarter_ = 0;  ///< K(k)
    double quarter_lo_ = 0;    ///< a rotation's K(k) less quarter_
    double half_turn_ = 0;     ///< a rotation's k K(k), rounded once
    double half_turn_lo_ = 0;  ///< k K(k) less half_turn_
    double k_lo_ = 0;          ///< a rotation's k less k_
    double mirror_ = 1;   ///< -1 where the start moves backwards: theta = -forward(-start)
    double turns_ = 0;    ///< the multiple of 2 pi nearest the mirrored start angle
    double start_angle_ = 0;  ///< the start angle less libration_center(), to rounding
    double offset_ = 0;   ///< the forward motion's time at the start
    std::optional<exact_solution> libration_;
    std::optional<pendulum::amplitude> given_;  ///< the amplitude itself, for from_amplitude()
    written_number first_ = 0.0;                ///< a state's angle or the energy, as written
    written_number second_ = 0.0;               ///< a state's velocity as written
    long cancelled_ = 0;
    double start_fraction_ = 0;                 ///< a libration's clock at the start in periods
    bool at_quarter_ = false;                   ///< start_fraction_ is a multiple of 1/4 exactly
    std::string energy_unheld_;
};

/// The phase (w/w0) w0 t, reduced modulo 2 pi, that a Fourier solution has at time 0 when it
/// runs on a libration's own clock (libration_clock(0)); throws as motion::amplitude() does.
/// theta(t) = libration_center() + solution.theta_at_phase(phase of t + start_phase).
double start_phase(const motion& m, const fourier_solution& solution);

/// The incomplete elliptic integral of the first kind F(psi | k) for the angle psi in [0, pi]
/// given as atan2(s, c) (s >= 0, s and c not both 0), with the complementary modulus k':
/// F = s R_F(c^2, c^2 + k'^2 s^2, s^2 + c^2), no cancellation next to k = 1.
double elliptic_f(double s, double c, double kp);

}  // namespace pendulum
