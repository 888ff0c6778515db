// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/motion.hpp"

#include <memory>

namespace pendulum {

/// The unit of a time: periods T of the exact motion, small-amplitude periods T0, or seconds
/// of a pendulum of a length and gravity.
struct time_scale {
    /// Which unit.
    enum class unit { periods, small_periods, seconds } what = unit::periods;
    double length = 1;  ///< metres, for seconds
    double g = 1;       ///< m/s^2, for seconds
};

/// Turns times into w0 t reduced modulo one period of a motion, exactly: the product with
/// the unit and the reduction are done in MPFR with every bit of the time and enough bits
/// for its integer part in periods, so that any finite time, up to the largest double, loses
/// nothing (in doubles w0 t alone is off by 1e-16 of itself). The period is the exact
/// motion's (4 K(k) of a libration, 2 k K(k) of a rotation's revolution), computed from the
/// exact amplitude or from the exact energy of a state; a Fourier solution's phase
/// (w/w0) w0 t is reduced modulo 2 pi with its frequency ratio taken as exact.
class time_reducer {
public:
    /// For times up to `largest` in size in `scale` of the libration of amplitude theta0;
    /// frequency_ratio > 0 also prepares phase() for a Fourier solution of that w/w0.
    time_reducer(const amplitude& theta0, const time_scale& scale, double largest, double frequency_ratio = 0);
    /// The same for a motion with a period (a libration or a rotation); throws domain_error
    /// at the separatrix.
    time_reducer(const motion& m, const time_scale& scale, double largest, double frequency_ratio = 0);
    /// For times up to `largest` of the libration of amplitude theta0 and the Fourier solution
    /// `solution`: where it carries its exact_source, phase() forms (w/w0) w0 t with w/w0 to
    /// the precision the time needs (not the double frequency_ratio), so that the phase is
    /// the exact motion's to the last bit at any time.
    time_reducer(const amplitude& theta0, const time_scale& scale, double largest, const fourier_solution& solution);
    /// The same for a motion with a period.
    time_reducer(const motion& m, const time_scale& scale, double largest, const fourier_solution& solution);
    ~time_reducer();
    time_reducer(const time_reducer&) = delete;
    time_reducer& operator=(const time_reducer&) = delete;

    /// w0 t for the time s rounded once, w0 t itself within one period (|w0 t| < P, P the
    /// period in w0 t), reduced to [-P/2, P/2] beyond; the whole periods taken off are kept
    /// for plus_turns(), the part below the result's rounding for low().
    double operator()(double s) const;
    /// The reduced time the last operator() rounded, less that double: the low half of a
    /// double-double (below half an ulp of it), so that a motion's angle at the reduced time
    /// can be right to an ulp however far out the time is (point_at()).
    double low() const;
    /// The phase (w/w0) w0 t of the Fourier solution at the time s, reduced to (-2 pi, 2 pi)
    /// (to [-pi, pi] and rounded once with the solution's exact source); throws domain_error
    /// unless a frequency ratio was given. Safe to call from several threads at once.
    double phase(double s) const;
    /// The phase of the Fourier solution at time 0 of the libration m this reducer was made
    /// for: (w/w0) times m's clock at its start (libration_clock(0)), with the reducer's w/w0
    /// and half its exact period, in MPFR, reduced to [-pi, pi] and rounded once (start_phase()
    /// takes both as doubles). Throws domain_error unless a frequency ratio was given.
    double start_phase(const motion& m) const;
    /// angle + 2 pi n turns_per_period rounded once, n the whole periods (signed) the last
    /// operator() took off: a rotation's unwrapped angle to the last bit at any time.
    double plus_turns(double angle, int turns_per_period) const;

private:
    struct state;
    friend struct reducer_setup;
    std::unique_ptr<state> state_;
};

/// theta and theta'/w0 of a motion at one time.
struct motion_point {
    double theta = 0;  ///< the angle, unwrapped (a rotation's whole revolutions added back exactly)
    double omega = 0;  ///< theta'/w0
};

/// A motion with a period at the time s (in the reducer's unit): the time reduced exactly as
/// a double-double, the angle at its double corrected by theta' times its low half, a
/// rotation's revolutions added back (forward or backward with the start's velocity), omega
/// at the double: what the trajectory command and the figures print.
motion_point point_at(const motion& m, const time_reducer& reduce, double s);

}  // namespace pendulum
