// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/time_reduction.hpp"

#include "pendulum/mp_iteration.hpp"
#include "pendulum/mp_real.hpp"
#include "pendulum/start_energy.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>
#include <numbers>

namespace pendulum {

using mp::real;

struct time_reducer::state {
    real scale;   // w0 t per unit of time
    real period;  // the period in w0 t
    real ratio;   // w/w0 of a Fourier solution, 0 without
    real two_pi;
    long double scale_extended;  // the same, for times within one period
    long double period_extended;
    long double ratio_extended;
    mutable real product;
    mutable real quotient;
    mutable real rest;
    mutable real turns;  // the whole periods the last reduction took off
    mutable double low = 0;  // the last reduced time less its double
    bool exact_ratio = false;  // ratio is w/w0 to its precision, not a double taken as exact
};

namespace {

/// k' in MPFR from whichever of theta0 and d is the amplitude itself.
real complementary_modulus(const amplitude& a, mpfr_prec_t bits) {
    if (a.near_pi()) {
        const real d = a.exact_radians() ? mp::pi(bits) - real(a.radians(), bits) : real(a.from_pi(), bits);
        return mp::sin(d / 2.0);
    }
    return mp::cos(real(a.radians(), bits) / 2.0);
}

/// The period 4 K(k) in w0 t of the libration of amplitude a.
real libration_period(const amplitude& a, mpfr_prec_t bits) {
    return 2.0 * mp::pi(bits) / mp::agm(real(1.0, bits), complementary_modulus(a, bits));
}

/// The period of a motion in w0 t: an amplitude's, or from the numbers of a state or an
/// energy as written (start_energy.hpp).
real motion_period(const motion& m, mpfr_prec_t bits) {
    if (m.given_as() == motion::origin::amplitude) return libration_period(m.amplitude(), bits);
    return written_period(m, bits);
}

/// w0 t per unit of time, `period` being the motion's period in w0 t.
real unit_scale(const time_scale& scale, const real& period) {
    const mpfr_prec_t bits = period.precision();
    if (scale.what == time_scale::unit::small_periods) return 2.0 * mp::pi(bits);
    if (scale.what == time_scale::unit::seconds) return mp::sqrt(real(scale.g, bits) / real(scale.length, bits));
    return period;
}

long double extended(const real& x) { return mpfr_get_ld(x.get(), MPFR_RNDN); }

}  // namespace

namespace {

/// w/w0 from the solution's source, with `bits`, right enough for phases up to 2^phase_exponent
/// in size: within 2^-56 rad (an eighth of an ulp of pi). The source's known ratio where it
/// is that right, its MPFR run otherwise (with 16 bits to spare for its own rounding).
/// A libration given as a state or an energy runs its approximant at its own exact
/// amplitude (from the numbers as written, written_amplitude()), not at its double: that one
/// is off by up to half an ulp, and so is the source's known ratio.
real exact_ratio(const exact_source& source, long phase_exponent, mpfr_prec_t bits, const motion* written) {
    const long needed = std::max(0L, phase_exponent + 1) + 56;
    const mpfr_prec_t asked = static_cast<mpfr_prec_t>(std::max(64L, needed + 16));
    if (written != nullptr && source.at_amplitude) {
        const amplitude_source exact = [written](mpfr_prec_t b) { return written_amplitude(*written, b); };
        return real(source.at_amplitude(exact, asked).ratio, bits);
    }
    if (source.known_bits >= needed) {
        real r(bits);
        mpfr_set_ld(r.get(), source.known_ratio, MPFR_RNDN);
        return r;
    }
    return real(source.at(asked).ratio, bits);
}

}  // namespace

/// Sets up a reducer's state for a period given at any precision.
struct reducer_setup {
    static std::unique_ptr<time_reducer::state> make(const std::function<real(mpfr_prec_t)>& period_at,
                                                     const time_scale& scale, double largest, double frequency_ratio,
                                                     const exact_source* source = nullptr,
                                                     const motion* written = nullptr);
};

namespace {

/// The motion itself where its amplitude is held only by its numbers as written (a
/// libration from a state or an energy), null otherwise.
const motion* written_libration(const motion& m) {
    return m.given_as() != motion::origin::amplitude && m.kind() == regime::libration ? &m : nullptr;
}

}  // namespace

time_reducer::time_reducer(const amplitude& a, const time_scale& scale, double largest, double frequency_ratio)
    : state_(reducer_setup::make([&a](mpfr_prec_t bits) { return libration_period(a, bits); }, scale, largest,
                        frequency_ratio)) {}

time_reducer::time_reducer(const motion& m, const time_scale& scale, double largest, double frequency_ratio)
    : state_(reducer_setup::make([&m](mpfr_prec_t bits) { return motion_period(m, bits); }, scale, largest,
                        frequency_ratio)) {}

time_reducer::time_reducer(const amplitude& a, const time_scale& scale, double largest,
                           const fourier_solution& solution)
    : state_(reducer_setup::make([&a](mpfr_prec_t bits) { return libration_period(a, bits); }, scale, largest,
                                 solution.frequency_ratio, solution.exact.get())) {}

time_reducer::time_reducer(const motion& m, const time_scale& scale, double largest, const fourier_solution& solution)
    : state_(reducer_setup::make([&m](mpfr_prec_t bits) { return motion_period(m, bits); }, scale, largest,
                                 solution.frequency_ratio, solution.exact.get(), written_libration(m))) {}

std::unique_ptr<time_reducer::state> reducer_setup::make(const std::function<real(mpfr_prec_t)>& period_at,
                                                         const time_scale& scale, double largest,
                                                         double frequency_ratio, const exact_source* source,
                                                         const motion* written) {
    if (!(std::isfinite(largest) && largest >= 0)) {
        throw domain_error("the largest time must be finite, got " + format_double(largest));
    }
    if (!(frequency_ratio >= 0 && std::isfinite(frequency_ratio))) {
        throw domain_error("a frequency ratio must be finite and > 0, got " + format_double(frequency_ratio));
    }
    // Enough bits for the integer part of the largest time in periods (of the motion, and of
    // the Fourier solution's phase) and 128 more, from the sizes at a low precision first.
    const real rough_period = period_at(64);
    const real rough_scale = unit_scale(scale, rough_period);
    const int time_exponent = std::ilogb(std::max(largest, 1.0));
    long cycles = time_exponent + mp::exponent(rough_scale) - mp::exponent(rough_period) + 1;
    if (frequency_ratio > 0) cycles = std::max(cycles, time_exponent + mp::exponent(rough_scale) + std::ilogb(frequency_ratio));
    const mpfr_prec_t bits = 128 + std::max(0L, cycles);
    real period = period_at(bits);
    real per_unit = unit_scale(scale, period);
    // The solution's own w/w0 where it has one, the double taken as exact otherwise.
    const bool exact = source != nullptr && frequency_ratio > 0;
    real ratio = exact ? exact_ratio(*source, time_exponent + mp::exponent(rough_scale) + std::ilogb(frequency_ratio), bits,
                                     written)
                       : real(frequency_ratio, bits);
    const long double ratio_extended = exact ? extended(ratio) : static_cast<long double>(frequency_ratio);
    auto s = std::make_unique<time_reducer::state>(time_reducer::state{
        per_unit, period, std::move(ratio), 2.0 * mp::pi(bits), extended(per_unit), extended(period),
        ratio_extended, real(bits + 64), real(bits), real(bits), real(0.0, bits), 0.0, exact});
    return s;
}

time_reducer::~time_reducer() = default;

double time_reducer::operator()(double s) const {
    if (!std::isfinite(s)) throw domain_error("time must be finite, got " + format_double(s));
    // Within one period the extended product rounded once is right to an ulp of w0 t.
    const long double w = s * state_->scale_extended;
    if (std::fabs(w) < state_->period_extended) {
        mpfr_set_zero(state_->turns.get(), 1);
        const double t = static_cast<double>(w);
        state_->low = static_cast<double>(w - t);
        return t;
    }
    mpfr_mul_d(state_->product.get(), state_->scale.get(), s, MPFR_RNDN);
    // n = round(w0 t / P) (off by one at worst next to a half period, where the rest is then
    // just outside [-P/2, P/2]: still the exact difference), rest = w0 t - n P, and the rest
    // as a double-double: its double and what that leaves.
    mpfr_div(state_->quotient.get(), state_->product.get(), state_->period.get(), MPFR_RNDN);
    mpfr_rint(state_->turns.get(), state_->quotient.get(), MPFR_RNDN);
    mpfr_fms(state_->rest.get(), state_->turns.get(), state_->period.get(), state_->product.get(), MPFR_RNDN);
    mpfr_neg(state_->rest.get(), state_->rest.get(), MPFR_RNDN);
    const double t = state_->rest.to_double();
    mpfr_sub_d(state_->quotient.get(), state_->rest.get(), t, MPFR_RNDN);
    state_->low = mpfr_get_d(state_->quotient.get(), MPFR_RNDN);
    return t;
}

double time_reducer::low() const { return state_->low; }

motion_point point_at(const motion& m, const time_reducer& reduce, double s) {
    const double t = reduce(s);
    const double low = reduce.low();
    // theta(t + low) = theta(t) + theta'(t) low + O(low^2), low below half an ulp of t; omega
    // at the double-double t + low (motion::velocity): at (1e-300, 2) 1e12 T0 on, omega
    // 6e-189 is k'/dn(K - r), and K - r in doubles was 1e-13 of itself off (1553 ulps).
    const double omega = m.velocity(t);
    const double theta = m.theta(t);
    motion_point p{theta + omega * low, m.velocity(t, low)};
    if (m.kind() == regime::rotation) p.theta = reduce.plus_turns(p.theta, m.start().omega < 0 ? -1 : 1);
    return p;
}

double time_reducer::phase(double s) const {
    if (!std::isfinite(s)) throw domain_error("time must be finite, got " + format_double(s));
    if (!(state_->ratio_extended > 0)) throw domain_error("a phase needs the Fourier solution's frequency ratio");
    // Within one period of the phase: with a double ratio taken as exact, w0 t rounded once,
    // times w/w0 rounded once (an ulp or two of x, the same as the formula at w0 t in doubles);
    // with the solution's own ratio (to 2^-56 or better, held in extended precision) the
    // product in extended precision rounded once. Further out the phase is formed in MPFR.
    if (!state_->exact_ratio) {
        const double w = static_cast<double>(s * state_->scale_extended);
        const double x = static_cast<double>(state_->ratio_extended) * w;
        if (std::fabs(x) < 2 * std::numbers::pi) return x;
    } else {
        const long double x = s * state_->scale_extended * state_->ratio_extended;
        if (std::fabs(x) < 2 * std::numbers::pi_v<long double>) return static_cast<double>(x);
    }
    // Locals, not the state's scratch numbers: phase() is safe to call from several threads.
    real product(state_->product.precision());
    real rest(state_->rest.precision());
    mpfr_mul_d(product.get(), state_->scale.get(), s, MPFR_RNDN);
    mpfr_mul(product.get(), product.get(), state_->ratio.get(), MPFR_RNDN);
    mpfr_remainder(rest.get(), product.get(), state_->two_pi.get(), MPFR_RNDN);
    return rest.to_double();
}

double time_reducer::start_phase(const motion& m) const {
    if (!(state_->ratio_extended > 0)) throw domain_error("a phase needs the Fourier solution's frequency ratio");
    real clock(state_->product.precision());
    if (written_libration(m) != nullptr) {
        // Its clock from its numbers as written: the double offset is off by an ulp or two.
        clock = written_clock(m, clock.precision());
    } else {
        const auto [offset, half_period] = m.libration_clock_parts();
        mpfr_set_d(clock.get(), offset, MPFR_RNDN);
        if (half_period) mpfr_add(clock.get(), clock.get(), (state_->period / 2.0).get(), MPFR_RNDN);
    }
    mpfr_mul(clock.get(), clock.get(), state_->ratio.get(), MPFR_RNDN);
    real rest(state_->rest.precision());
    mpfr_remainder(rest.get(), clock.get(), state_->two_pi.get(), MPFR_RNDN);
    return rest.to_double();
}

double time_reducer::plus_turns(double angle, int turns_per_period) const {
    if (mpfr_zero_p(state_->turns.get())) return angle;
    mpfr_mul(state_->product.get(), state_->turns.get(), state_->two_pi.get(), MPFR_RNDN);
    mpfr_mul_si(state_->product.get(), state_->product.get(), turns_per_period, MPFR_RNDN);
    mpfr_add_d(state_->product.get(), state_->product.get(), angle, MPFR_RNDN);
    return mpfr_get_d(state_->product.get(), MPFR_RNDN);
}

}  // namespace pendulum
