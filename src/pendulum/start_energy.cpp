// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/start_energy.hpp"

#include "pendulum/written_mp.hpp"

#include <algorithm>
#include <array>
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

namespace {

/// The message for a start no precision up to the ceiling decides: its energy 0 to every bit
/// (or an angle whose place in the turn needs more bits than the ceiling), or its gap 2 - E.
[[noreturn]] void refuse_undecided(const start_energy& coarse, const start_energy& fine, bool gap_decided,
                                   mpfr_prec_t bits, const std::string& what) {
    const std::string fine_bits = std::to_string(bits);
    const std::string coarse_bits = std::to_string(bits / 2);
    if (gap_decided) {
        throw domain_error(what + ": its energy is " + decimal(fine.energy) + " at " + fine_bits + " bits and " +
                           decimal(coarse.energy) + " at " + coarse_bits +
                           ": E = 0 (at rest at the bottom) to the precision of its terms, or an angle whose place in the turn needs more than " +
                           std::to_string(start_ceiling_bits) + " bits; give a start whose energy is not 0 (an angle "
                           "within a few turns of 0, or omega0 not 0)");
    }
    throw domain_error(what + ": its energy is 2 within " + std::to_string(fine.cancelled) +
                       " bits of its terms (2 - E = " + decimal(fine.gap) + " at " + fine_bits +
                       " bits, another number at " + coarse_bits +
                       "): the regime (libration, separatrix or rotation) cannot be decided from the numbers as "
                       "written within " + std::to_string(start_ceiling_bits) +
                       " bits; give a start further from the separatrix E = 2");
}

/// A decided libration or rotation whose motion doubles hold: a distance from the separatrix
/// 2 k' (the libration's pi - theta0, to O(k'^3)) of at least the smallest normal double, as an
/// amplitude's distance from pi must be, and a libration's amplitude 2 atan2(k, k') not 0 as a
/// double; otherwise throws domain_error naming the start and the number a double cannot hold.
start_energy held(start_energy e, const std::string& what) {
    const mpfr_prec_t bits = e.gap.precision();
    const real two_kp = e.kind == regime::libration ? 2.0 * mp::sqrt(e.gap / 2.0) : 2.0 * mp::sqrt(-e.gap / e.energy);
    if (two_kp < DBL_MIN) {
        throw domain_error(what + ": 2 - E = " + decimal(e.gap) + ", so close to the separatrix that 2 k' = " +
                           decimal(two_kp) + " (the " + std::string(e.kind == regime::libration ? "amplitude's " : "") +
                           "distance from the top) is below the smallest normal double, 2.2250738585072014e-308, as "
                           "an amplitude's distance from pi may not be: a double cannot hold the motion; give a start "
                           "further from the separatrix E = 2");
    }
    if (e.kind == regime::libration) {
        real amplitude(bits);
        const real k = mp::sqrt(e.energy / 2.0);
        mpfr_atan2(amplitude.get(), k.get(), mp::sqrt(e.gap / 2.0).get(), MPFR_RNDN);
        if ((2.0 * amplitude).to_double() == 0) {
            throw domain_error(what + ": its amplitude is " + decimal(2.0 * amplitude) +
                               ", below the smallest double, 4.9406564584124654e-324: a double cannot hold it "
                               "(E = " + decimal(e.energy) + "); give a start with a larger energy");
        }
    }
    return e;
}

}  // namespace

namespace {

/// cos(b pi) where it is rational (b a multiple of 1/6 at 0, +-1/3, +-1/2, +-2/3, 1 modulo 2),
/// into `out`; false otherwise.
bool rational_cosine(const rational& b, rational& out) {
    rational six_b;
    mpq_set_ui(six_b.get(), 6, 1);
    mpq_mul(six_b.get(), six_b.get(), b.get());
    if (mpz_cmp_ui(mpq_denref(six_b.get()), 1) != 0) return false;
    // k pi/6 with k modulo 12, and the rational cosines among them.
    const unsigned long k = mpz_fdiv_ui(mpq_numref(six_b.get()), 12);
    constexpr std::array<int, 12> twice_cosine{2, 0, 1, 0, -1, 0, -2, 0, -1, 0, 1, 0};
    constexpr std::array<bool, 12> rational_there{true, false, true, true, true, false,
                                                  true, false, true, true, true, false};
    if (!rational_there[k]) return false;
    mpq_set_si(out.get(), twice_cosine[k], 2);
    mpq_canonicalize(out.get());
    return true;
}

}  // namespace

bool exactly_separatrix(const written_number& theta, const written_number& omega) {
    const auto th = exact_written(theta);
    const auto w = exact_written(omega);
    if (!th || !w || mpq_sgn(th->a.get()) != 0 || mpq_sgn(w->b.get()) != 0) return false;
    rational c;
    if (!rational_cosine(th->b, c)) return false;
    // omega^2 = 2 (1 + cos theta).
    rational lhs;
    rational rhs;
    mpq_mul(lhs.get(), w->a.get(), w->a.get());
    mpq_set_ui(rhs.get(), 1, 1);
    mpq_add(rhs.get(), rhs.get(), c.get());
    mpq_add(rhs.get(), rhs.get(), rhs.get());
    return mpq_equal(lhs.get(), rhs.get()) != 0;
}

bool exactly_two(const written_number& energy) {
    const auto e = exact_written(energy);
    return e && mpq_sgn(e->b.get()) == 0 && mpq_cmp_ui(e->a.get(), 2, 1) == 0;
}

start_energy decide_start(const std::function<start_energy(mpfr_prec_t)>& at, const std::string& what,
                          bool on_separatrix) {
    if (on_separatrix) {
        start_energy e = at(start_first_bits);
        e.energy = real(2.0, start_first_bits);
        e.gap = real(0.0, start_first_bits);
        e.kind = regime::separatrix;
        e.cancelled = 0;
        return e;
    }
    start_energy coarse = at(start_first_bits);
    for (mpfr_prec_t bits = 2 * start_first_bits; bits <= start_ceiling_bits; bits *= 2) {
        start_energy fine = at(bits);
        const bool gap_decided = !vanishes(coarse) && !vanishes(fine) && agree(coarse.gap, fine.gap);
        // The energy too must agree: an angle far out (1e307pi) loses its place in the turn to
        // the precision, and a state at rest at a multiple of 2 pi has E = 0 to every bit.
        if (gap_decided && agree(coarse.energy, fine.energy)) return held(std::move(fine), what);
        // At the ceiling undecided: a gap below 2^-65528 of its terms is not the separatrix
        // unless proved so (on_separatrix), which returned above.
        if (bits == start_ceiling_bits) refuse_undecided(coarse, fine, gap_decided, bits, what);
        coarse = std::move(fine);
    }
    throw domain_error("unreachable");  // the loop returns or throws at the ceiling
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
        const real k = mp::sqrt(2.0 / e.energy);
        const real kp = mp::sqrt(-e.gap / e.energy);
        const real quarter = mp::pi(k.precision()) / (2.0 * mp::agm(real(1.0, k.precision()), kp));
        const real half_turn = k * quarter;
        n.k = k.to_double();
        n.kp = kp.to_double();
        n.k_lo = (k - n.k).to_double();
        n.quarter = quarter.to_double();
        n.quarter_lo = (quarter - n.quarter).to_double();
        n.half_turn = half_turn.to_double();
        n.half_turn_lo = (half_turn - n.half_turn).to_double();
    } else {
        n.k = 1.0;
        n.kp = 0.0;
    }
    n.half_speed = mp::sqrt(half).to_double();
    n.speed = mp::sqrt(2.0 * e.energy).to_double();
    return n;
}

namespace {

/// The energy and gap of a motion given as a state or an energy, with `p` bits.
start_energy written_start(const motion& m, mpfr_prec_t p) {
    return m.given_as() == motion::origin::energy ? written_energy_at(m.written_first(), p)
                                                  : state_energy_at(m.written_first(), m.written_second(), p);
}

}  // namespace

mp::mp_amplitude written_amplitude(const motion& m, mpfr_prec_t bits) {
    if (m.given_as() == motion::origin::amplitude || m.kind() != regime::libration) {
        throw domain_error("written_amplitude needs a libration given as a state or an energy");
    }
    const mpfr_prec_t p = bits + 64 + m.cancelled_bits();
    const start_energy e = written_start(m, p);
    const real k = mp::sqrt(e.energy / 2.0);
    const real kp = mp::sqrt(e.gap / 2.0);
    real theta(p);
    mpfr_atan2(theta.get(), k.get(), kp.get(), MPFR_RNDN);
    const real one_minus_kp = (e.energy / 2.0) / (1.0 + kp);
    return {real(2.0 * theta, bits), real(k, bits), real(kp, bits), real(one_minus_kp, bits)};
}

namespace {

/// Carlson's R_F(x, y, z) in MPFR (x, y, z >= 0, at most one 0), to about 2^-p relative: the
/// duplication until the three agree to 2^-(p/6 + 4) of their mean, then its fifth-order series.
real carlson_rf_mp(real x, real y, real z, mpfr_prec_t p) {
    for (int step = 0; step < 4 * static_cast<int>(p); ++step) {
        const real a = (x + y + z) / 3.0;
        const real spread = mp::fabs(a - x) + mp::fabs(a - y) + mp::fabs(a - z);
        real bound(p);
        mpfr_mul_2si(bound.get(), a.get(), -static_cast<long>(p / 6 + 4), MPFR_RNDN);
        if (mpfr_cmp(spread.get(), bound.get()) <= 0) break;
        const real sx = mp::sqrt(x);
        const real sy = mp::sqrt(y);
        const real sz = mp::sqrt(z);
        const real lambda = sx * sy + sy * sz + sz * sx;
        x = (x + lambda) / 4.0;
        y = (y + lambda) / 4.0;
        z = (z + lambda) / 4.0;
    }
    const real a = (x + y + z) / 3.0;
    const real dx = (a - x) / a;
    const real dy = (a - y) / a;
    const real dz = -(dx + dy);
    const real e2 = dx * dy - dz * dz;
    const real e3 = dx * dy * dz;
    const real series = 1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0;
    return series / mp::sqrt(a);
}

}  // namespace

real written_clock(const motion& m, mpfr_prec_t bits) {
    const mpfr_prec_t p = bits + 64 + m.cancelled_bits();
    const mp::mp_amplitude a = written_amplitude(m, p);  // throws unless such a libration
    const real one(1.0, p);
    const real quarter = mp::pi(p) / (2.0 * mp::agm(one, a.kp));
    // A launch from the bottom moves forwards: a quarter period after its amplitude.
    if (m.given_as() == motion::origin::energy) return real(-quarter, bits);
    const real theta = evaluate_written(m.written_first(), p);
    const real omega = evaluate_written(m.written_second(), p);
    const bool backwards = omega.to_double() < 0;  // as motion::prepare mirrors it
    real angle(p);
    mpfr_remainder(angle.get(), (backwards ? -theta : theta).get(), (2.0 * mp::pi(p)).get(), MPFR_RNDN);
    // psi = am(tau) with sn : cn = |omega|/2 : k' sin(angle/2) (motion::prepare), F of degree 0.
    const real s = mp::fabs(omega) / 2.0;
    const real c = a.kp * mp::sin(angle / 2.0);
    const real f = angle.is_zero() ? real(quarter)
                   : s.is_zero()    ? real(0.0, p)
                                    : s * carlson_rf_mp(c * c, c * c + a.kp * a.kp * s * s, s * s + c * c, p);
    // Beyond pi/2 (c < 0): F(psi) = 2 K - F(pi - psi).
    const real forward = !angle.is_zero() && c < 0.0 ? 2.0 * quarter - f : f;
    const real clock = backwards ? 2.0 * quarter - forward : -forward;
    return real(clock, bits);
}

real written_period(const motion& m, mpfr_prec_t bits) {
    if (!m.has_period()) (void)m.period();  // throws, naming the separatrix
    const mpfr_prec_t p = bits + 64 + m.cancelled_bits();
    const start_energy e = written_start(m, p);
    const real one(1.0, p);
    const real exact = m.kind() == regime::libration
                           ? 2.0 * mp::pi(p) / mp::agm(one, mp::sqrt(e.gap / 2.0))
                           : mp::pi(p) * mp::sqrt(2.0 / e.energy) / mp::agm(one, mp::sqrt(-e.gap / e.energy));
    return real(exact, bits);
}

}  // namespace pendulum
