// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/start_energy.hpp"

#include "pendulum/written_mp.hpp"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>

namespace pendulum {

using mp::real;

namespace {

/// Bits a difference lost: its larger term's exponent over its own (all of them where it is 0).
long cancelled_bits(const real& a, const real& b, const real& difference) {
    if (difference.is_zero()) return static_cast<long>(difference.precision());
    const long larger = std::max(a.is_zero() ? LONG_MIN / 2 : mp::exponent(a), b.is_zero() ? LONG_MIN / 2 : mp::exponent(b));
    return std::max(0L, larger - mp::exponent(difference));
}

regime regime_of(const real& gap) {
    if (gap.is_zero()) return regime::separatrix;
    return gap > 0.0 ? regime::libration : regime::rotation;
}

/// True where the gap vanishes to the precision it was computed with (8 bits to spare).
bool vanishes(const start_energy& e) {
    return e.gap.is_zero() || e.cancelled >= static_cast<long>(e.gap.precision()) - 8;
}

/// True where two values of the gap agree in sign and to 64 bits of the finer (as doubles
/// they would agree at 0 where both underflow).
bool agree(const real& coarse, const real& fine) {
    if (mpfr_sgn(coarse.get()) != mpfr_sgn(fine.get())) return false;
    const real difference = real(coarse, fine.precision()) - fine;
    return difference.is_zero() || mp::exponent(fine) - mp::exponent(difference) >= 64;
}

/// A number in decimal, 17 digits: for messages about values a double does not hold.
std::string decimal(const real& x) {
    char* text = nullptr;
    if (mpfr_asprintf(&text, "%.17Rg", x.get()) < 0 || !text) return "?";
    std::string out = text;
    mpfr_free_str(text);
    return out;
}

}  // namespace

start_energy state_energy_at(const written_number& theta, const written_number& omega, mpfr_prec_t bits) {
    const real th = evaluate_written(theta, bits);
    const real w = evaluate_written(omega, bits);
    const real s = mp::sin(th / 2.0);
    const real c = mp::cos(th / 2.0);
    const real kinetic = w * w / 2.0;
    // 2 - E = (2 - w)(2 + w)/2 - 2 sin^2(theta/2) = 2 cos^2(theta/2) - w^2/2: the form whose
    // terms are exact to relative rounding (the smaller of the sine and the cosine squared),
    // so only the cancellation between the two terms themselves costs bits.
    const bool sine_small = mp::fabs(s) < mp::fabs(c) || mpfr_cmpabs(s.get(), c.get()) == 0;
    const real first = sine_small ? (2.0 - w) * (2.0 + w) / 2.0 : 2.0 * c * c;
    const real second = sine_small ? 2.0 * s * s : kinetic;
    real gap = first - second;
    return {kinetic + 2.0 * s * s, gap, regime_of(gap), cancelled_bits(first, second, gap)};
}

start_energy written_energy_at(const written_number& energy, mpfr_prec_t bits) {
    const real e = evaluate_written(energy, bits);
    const real two(2.0, bits);
    real gap = two - e;
    return {e, gap, regime_of(gap), cancelled_bits(two, e, gap)};
}

start_energy decide_start(const std::function<start_energy(mpfr_prec_t)>& at, const std::string& what) {
    constexpr mpfr_prec_t last = 1280;
    for (const mpfr_prec_t bits : {mpfr_prec_t{192}, last}) {
        start_energy coarse = at(bits);
        start_energy fine = at(2 * bits);
        const bool zero = vanishes(coarse) && vanishes(fine);
        const bool gap_decided = !vanishes(coarse) && !vanishes(fine) && agree(coarse.gap, fine.gap);
        // The energy too must agree: an angle far out (1e307pi) loses its place in the turn to
        // the precision, and a state at rest at a multiple of 2 pi has E = 0 to every bit.
        if (gap_decided && agree(coarse.energy, fine.energy)) return fine;
        if (bits == last && gap_decided) {
            throw domain_error(what + ": its energy is " + decimal(fine.energy) + " at 2560 bits and " +
                               decimal(coarse.energy) + " at 1280: E = 0 (at rest at the bottom) to the precision "
                               "of its terms, or an angle too far out for its place in the turn to be known; give "
                               "a start whose energy is not 0 (an angle within a few turns of 0, or omega0 not 0)");
        }
        if (bits == last && zero) {
            // E = 2 to 2552 bits of its terms: the numbers as written are on the separatrix.
            fine.energy = real(2.0, 2 * bits);
            fine.gap = real(0.0, 2 * bits);
            fine.kind = regime::separatrix;
            return fine;
        }
        if (bits == last) {
            throw domain_error(what + ": its energy is 2 within " + std::to_string(fine.cancelled) +
                               " bits of its terms (2 - E = " + decimal(fine.gap) +
                               " at 2560 bits, another number at 1280): the regime (libration, separatrix or rotation) "
                               "cannot be decided from the numbers as written; give a start further from the separatrix E = 2");
        }
    }
    throw domain_error("unreachable");  // the loop returns or throws at the last precision
}

start_numbers numbers_of(const start_energy& e) {
    start_numbers n;
    n.kind = e.kind;
    n.cancelled = e.kind == regime::separatrix ? 0 : e.cancelled;
    n.energy = e.energy.to_double();
    n.gap = e.gap.to_double();
    const double size = std::fabs(n.energy);
    if (!e.energy.is_zero() && !(size >= DBL_MIN && size <= DBL_MAX)) n.energy_unheld = decimal(e.energy);
    const real half = e.energy / 2.0;
    if (e.kind == regime::libration) {
        const real k = mp::sqrt(half);
        const real kp = mp::sqrt(e.gap / 2.0);
        real angle(k.precision());
        mpfr_atan2(angle.get(), k.get(), kp.get(), MPFR_RNDN);
        n.theta0 = (2.0 * angle).to_double();
        mpfr_atan2(angle.get(), kp.get(), k.get(), MPFR_RNDN);
        n.d = (2.0 * angle).to_double();
        n.k = k.to_double();
        n.kp = kp.to_double();
    } else if (e.kind == regime::rotation) {
        n.k = mp::sqrt(2.0 / e.energy).to_double();
        n.kp = mp::sqrt(-e.gap / e.energy).to_double();
    } else {
        n.k = 1.0;
        n.kp = 0.0;
    }
    n.half_speed = mp::sqrt(half).to_double();
    n.speed = mp::sqrt(2.0 * e.energy).to_double();
    return n;
}

real written_period(const motion& m, mpfr_prec_t bits) {
    if (!m.has_period()) (void)m.period();  // throws, naming the separatrix
    const mpfr_prec_t p = bits + 64 + m.cancelled_bits();
    const start_energy e = m.given_as() == motion::origin::energy
                               ? written_energy_at(m.written_first(), p)
                               : state_energy_at(m.written_first(), m.written_second(), p);
    const real one(1.0, p);
    const real exact = m.kind() == regime::libration
                           ? 2.0 * mp::pi(p) / mp::agm(one, mp::sqrt(e.gap / 2.0))
                           : mp::pi(p) * mp::sqrt(2.0 / e.energy) / mp::agm(one, mp::sqrt(-e.gap / e.energy));
    return real(exact, bits);
}

}  // namespace pendulum
