// SPDX-License-Identifier: GPL-3.0-or-later
// A closed-form period formula of formulas.hpp as the method table's entries: its T/T0 in
// doubles and its error T_m/T - 1 (doubles where they suffice, MPFR otherwise, or correctly
// rounded), both from the one template. Internal to the core library.
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/formulas.hpp"
#include "pendulum/formulas_mp.hpp"
#include "pendulum/period_error.hpp"

#include <cstddef>

namespace pendulum {

/// A period in MPFR at the exact amplitude (with its precision), with the method's N.
using mp_period = mp::real (*)(const formulas::amplitude_view<mp::real>& x, int n);

/// A period in extended precision, for the methods that have one.
using extended_period = long double (*)(const amplitude& a);

/// The error of a closed-form period: doubles where they suffice (|error| >= 1e-2), then
/// extended precision where the method has it and it suffices (>= 1e-5), MPFR otherwise; or
/// MPFR throughout for precision::correctly_rounded (period_error.cpp).
period_error closed_form_error(const amplitude& a, int n, precision p, double (*period)(const amplitude&, int),
                               mp_period f, extended_period extended = nullptr);

namespace detail {

/// The MPFR tier of closed_form_error: the error with 128, 256, 512 and 1152 bits in turn,
/// from the `first` of them, the first that resolves it (below_limit where none does).
period_error mp_closed_form_error_from(const amplitude& a, int n, mp_period f, std::size_t first);
/// The first of those precisions that may resolve an error at `a`: the ones before it surely
/// cannot (the error is at most theta0^2 there), 0 where nothing is foreseen.
std::size_t foreseen_closed_form_start(const amplitude& a);
/// The MPFR tier from the foreseen precision; the same as from 128 bits, since a value whose
/// skipped precisions might have resolved it is computed again from 128 bits.
period_error mp_closed_form_error(const amplitude& a, int n, mp_period f);

}  // namespace detail

/// T/T0 of formula F in doubles, as a method table entry.
template <class F>
double closed_form_period(const amplitude& theta0, int n) {
    return F{}(formulas::view_of(theta0), n);
}

/// T/T0 of formula F in MPFR.
template <class F>
mp::real closed_form_period_mp(const formulas::amplitude_view<mp::real>& x, int n) {
    return F{}(x, n);
}

/// T_m/T - 1 of formula F, as a method table entry.
template <class F>
period_error closed_form_period_error(const amplitude& theta0, int n, precision p) {
    return closed_form_error(theta0, n, p, closed_form_period<F>, closed_form_period_mp<F>);
}

}  // namespace pendulum
