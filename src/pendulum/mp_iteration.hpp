// SPDX-License-Identifier: GPL-3.0-or-later
// The iteration to order N with MPFR, for the amplitudes where the double iteration's
// rounding grows beyond 1e-14 (close to pi), and for the iteration's period errors; defined
// in mp_iteration.cpp. Internal to the core library.
#pragma once

#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/formulas_mp.hpp"
#include "pendulum/mp_real.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace pendulum {

/// A Fourier solution in MPFR: w/w0 and c1, c3, ... with one precision.
struct mp_solution {
    mp::real ratio;                     ///< w/w0 (NaN where the level has no period)
    std::vector<mp::real> coefficients; ///< c1, c3, ...
};

/// An exact amplitude with any number of bits asked for.
using amplitude_source = std::function<mp::mp_amplitude(mpfr_prec_t bits)>;

/// A method's solution in MPFR at the exact amplitude its `amplitude_at` gives, with `bits`
/// (at least 64): w/w0 within a few units of 2^-(bits - 16).
using solution_at_amplitude = std::function<mp_solution(const amplitude_source& amplitude_at, mpfr_prec_t bits)>;

/// A method's solution at any precision, from the exact amplitude: what a fourier_solution
/// carries so that its phase (w/w0) w0 t can be formed to the last bit at any time.
struct exact_source {
    /// The solution with `bits` (at least 64): w/w0 within a few units of 2^-(bits - 16).
    std::function<mp_solution(mpfr_prec_t bits)> at;
    /// w/w0 known without calling `at` (the iteration's extended-precision run, whose MPFR
    /// run costs seconds at order 200), right to 2^-known_bits relative; 0 bits: none.
    long double known_ratio = 0;
    int known_bits = 0;  ///< see known_ratio
    /// The same method at another exact amplitude: a libration started from a state or an
    /// energy, whose amplitude only its numbers as written hold (its double is rounded).
    solution_at_amplitude at_amplitude{};
};

/// A shared source for a fourier_solution of the amplitude a: `at` is `f` at a itself.
inline std::shared_ptr<const exact_source> make_source(const amplitude& a, solution_at_amplitude f,
                                                       long double known_ratio = 0, int known_bits = 0) {
    auto at = [a, f](mpfr_prec_t bits) {
        return f([&a](mpfr_prec_t b) { return mp::exact_amplitude(a, b); }, bits);
    };
    return std::make_shared<const exact_source>(exact_source{std::move(at), known_ratio, known_bits, std::move(f)});
}

}  // namespace pendulum

namespace pendulum::detail {

/// Below this distance from pi iterated_sequence() works with MPFR: at 0.99 pi (d = 0.031)
/// the double iteration's levels are still right to 7e-15, at 0.999 pi only to 6e-14.
inline constexpr double iteration_mp_below = 0.02;

/// Levels 0 to `order` (0 <= order <= max_order, checked by the caller) of the iteration
/// computed with 128 bits and more, rounded once to doubles;
/// a level without a period has a NaN frequency, as in iterated_sequence(). Throws
/// domain_error where the projection does not converge with 2^15 points. `bits_used`, if
/// given, receives the precision whose levels agreed with the run at half of it.
std::vector<fourier_solution> iterated_sequence_mp(const amplitude& theta0, int order,
                                                   mpfr_prec_t* bits_used = nullptr);

/// lambda = (w/w0)^2 of levels 0 .. order with `bits` at the exact amplitude x; an unset
/// entry where the projection did not converge (that level and all later ones). Stops after
/// the first level for which `stop` (if given) is true; stores each level's coefficients
/// c_k/theta0 in `coefficients` if given.
std::vector<std::optional<mp::real>> mp_lambdas(const mp::mp_amplitude& x, int order, mpfr_prec_t bits,
                                                const std::function<bool(const mp::real& lambda)>& stop = {},
                                                std::vector<std::vector<mp::real>>* coefficients = nullptr);

}  // namespace pendulum::detail
