// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/time_reduction.hpp"

#include "pendulum/mp_real.hpp"

#include <algorithm>
#include <cmath>

namespace pendulum {

using mp::real;

struct time_reducer::state {
    real scale;   // w0 t per unit of time
    real period;  // the period in w0 t
    long double scale_extended;   // the same, for times within one period
    long double period_extended;
    mutable real product;
    mutable real rest;
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

}  // namespace

time_reducer::time_reducer(const amplitude& a, const time_scale& scale, double largest, double frequency_ratio) {
    if (!(std::isfinite(largest) && largest >= 0)) throw domain_error("the largest time must be finite, got " + format_double(largest));
    // Enough bits for the integer part of the largest time in periods and 120 more; w0 per
    // second may be as large as 5e163.
    double per_unit = 2 * 3.2;  // an upper bound of w0 t per unit, with a period of at least 2 pi
    if (scale.what == time_scale::unit::periods) per_unit = 1;
    if (scale.what == time_scale::unit::seconds) per_unit = std::sqrt(scale.g) / std::sqrt(scale.length);
    const double cycles = std::max(1.0, largest * per_unit);
    const mpfr_prec_t bits = 128 + std::max(0, std::ilogb(cycles));
    const real two_pi = 2.0 * mp::pi(bits);
    real four_k = two_pi / mp::agm(real(1.0, bits), complementary_modulus(a, bits));
    real period = frequency_ratio > 0 ? two_pi / real(frequency_ratio, bits) : four_k;
    real unit_scale = four_k;
    if (scale.what == time_scale::unit::small_periods) unit_scale = two_pi;
    if (scale.what == time_scale::unit::seconds) unit_scale = mp::sqrt(real(scale.g, bits) / real(scale.length, bits));
    const auto extended = [](const real& x) { return mpfr_get_ld(x.get(), MPFR_RNDN); };
    state_ = std::make_unique<state>(
        state{unit_scale, period, extended(unit_scale), extended(period), real(bits), real(bits)});
}

time_reducer::~time_reducer() = default;

double time_reducer::operator()(double s) const {
    if (!std::isfinite(s)) throw domain_error("time must be finite, got " + format_double(s));
    // Within one period the extended product rounded once is right to an ulp of w0 t.
    const long double w = s * state_->scale_extended;
    if (std::fabs(w) < state_->period_extended) return static_cast<double>(w);
    mpfr_mul_d(state_->product.get(), state_->scale.get(), s, MPFR_RNDN);
    mpfr_fmod(state_->rest.get(), state_->product.get(), state_->period.get(), MPFR_RNDN);
    return state_->rest.to_double();
}

}  // namespace pendulum
