// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The energy of a start from its numbers as written, in MPFR: for the core only, not installed.

#include "pendulum/angle.hpp"
#include "pendulum/formulas_mp.hpp"
#include "pendulum/motion.hpp"
#include "pendulum/mp_real.hpp"

#include <functional>
#include <string>

namespace pendulum {

/// The energy E and the gap 2 - E of a start, each correct to the precision they carry, and
/// the regime they decide.
struct start_energy {
    mp::real energy;  ///< E per m g L, from the bottom
    mp::real gap;     ///< 2 - E, without cancellation beyond its own terms
    regime kind;      ///< by the sign of the gap; the separatrix where it vanishes
    long cancelled;   ///< bits the gap lost to cancellation (its terms' size over its own)
};

/// The energy of the state (theta, omega) as written, at `bits` (a guide: the gap keeps
/// about `bits` bits of its own, whatever cancels). Not deciding the regime (kind is set from
/// the sign, cancelled from the terms).
start_energy state_energy_at(const written_number& theta, const written_number& omega, mpfr_prec_t bits);

/// The energy E as written, at `bits`.
start_energy written_energy_at(const written_number& energy, mpfr_prec_t bits);

/// The first precision decide_start() tries, in bits.
inline constexpr mpfr_prec_t start_first_bits = 128;
/// The last: 2^16 bits (19,728 decimal digits), 2^9 times the first.
inline constexpr mpfr_prec_t start_ceiling_bits = 65536;

/// True where the state (theta, omega) as written has E = 2 exactly, proved from their exact
/// values (exact_written): theta = b pi with cos(b pi) rational (b a multiple of 1/6 whose
/// cosine is 0, +-1/2 or +-1) and omega rational with omega^2 = 2 (1 + cos theta). Any other
/// state of the angle language is off the separatrix (Lindemann: cos of a rational other
/// than 0, plus a rational multiple of pi, is transcendental; Niven: cos(b pi) is otherwise
/// irrational; and pi^2 is transcendental), or its exact value is not known: false.
bool exactly_separatrix(const written_number& theta, const written_number& omega);

/// True where the energy as written is 2 exactly.
bool exactly_two(const written_number& energy);

/// Decides the regime of a start: the separatrix at once where `on_separatrix` (E = 2 proved
/// exactly, exactly_separatrix()); else the gap at a precision and at twice it, from
/// start_first_bits doubling up to start_ceiling_bits: decided at the first pair where both
/// agree to 64 bits (as does the energy); otherwise throws domain_error naming the ceiling:
/// the inputs cannot decide (a gap only the ceiling sees: 2 - E below 2^-65528 of its terms,
/// never taken as the separatrix), or the energy is 0 to every bit (an angle whose place in
/// the turn needs more bits than the ceiling, or at rest at a multiple of 2 pi). A
/// decided libration or rotation that doubles cannot hold is refused too: 2 k' (its distance
/// from the top) below 2.2250738585072014e-308, as an amplitude's distance from pi may not be,
/// or a libration's amplitude that rounds to 0.
start_energy decide_start(const std::function<start_energy(mpfr_prec_t)>& at, const std::string& what,
                          bool on_separatrix);

/// The doubles of a decided start, each rounded once from the exact energy and gap.
start_numbers numbers_of(const start_energy& e);

/// The period in w0 t of a motion given as a state or an energy, from its numbers as written,
/// with `bits` bits; throws domain_error at the separatrix.
mp::real written_period(const motion& m, mpfr_prec_t bits);

/// The amplitude of a libration given as a state or an energy, from its numbers as written,
/// with `bits` bits: k = sqrt(E/2), k' = sqrt((2 - E)/2), theta0 = 2 atan2(k, k'),
/// 1 - k' = k^2/(1 + k'); throws domain_error unless the motion is such a libration.
mp::mp_amplitude written_amplitude(const motion& m, mpfr_prec_t bits);

/// A libration's own clock at its start (motion::libration_clock(0): the time since it was at
/// its amplitude +theta0, in w0 t, half a period added for a start moving backwards) from
/// its numbers as written, with `bits` bits: F(psi | k) by Carlson's R_F in MPFR; throws
/// domain_error unless the motion is a libration given as a state or an energy.
mp::real written_clock(const motion& m, mpfr_prec_t bits);

}  // namespace pendulum
