// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pendulum/amplitude.hpp"

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

/// Turns times into w0 t reduced modulo one period of a motion of amplitude theta0, exactly:
/// the product with the unit and the reduction are done in MPFR with every bit of the time,
/// so that a time of a million periods loses nothing (in doubles w0 t alone is off by
/// 1e-16 of itself). The period is the exact motion's 4 K(k), or 2 pi / (w/w0) of a Fourier
/// solution of that frequency ratio (taken as exact).
class time_reducer {
public:
    /// For times up to `largest` in size in `scale`; frequency_ratio 0 means the exact motion.
    time_reducer(const amplitude& theta0, const time_scale& scale, double largest, double frequency_ratio = 0);
    ~time_reducer();
    time_reducer(const time_reducer&) = delete;
    time_reducer& operator=(const time_reducer&) = delete;

    /// w0 t for the time s, reduced to (-P, P) with the sign of s (P the period in w0 t).
    double operator()(double s) const;

private:
    struct state;
    std::unique_ptr<state> state_;
};

}  // namespace pendulum
