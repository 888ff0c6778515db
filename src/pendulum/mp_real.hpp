// SPDX-License-Identifier: GPL-3.0-or-later
// A multiple-precision real (MPFR) for the few numbers that need more than a double: angle
// expressions near pi, differences below rounding. Internal to the core library: the
// installed headers do not include it.
#pragma once

#include <mpfr.h>

#include <algorithm>

namespace pendulum::mp {

namespace detail {

/// MPFR keeps caches (pi, log 2) per thread and asks each thread to free them before it
/// ends: a worker thread that used a real frees them at its exit.
struct thread_caches {
    thread_caches() = default;
    thread_caches(const thread_caches&) = delete;
    thread_caches& operator=(const thread_caches&) = delete;
    ~thread_caches() { mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE); }
};

/// Registers the calling thread's cleanup, once per thread.
inline void free_caches_at_thread_exit() {
    thread_local thread_caches caches;
    (void)caches;
}

}  // namespace detail

/// An MPFR number with its own precision; every operation rounds to nearest.
class real {
public:
    /// Zero with `bits` of precision.
    explicit real(mpfr_prec_t bits) {
        detail::free_caches_at_thread_exit();
        mpfr_init2(v_, bits);
        mpfr_set_zero(v_, 1);
    }
    /// `x` exactly, with `bits` of precision (at least 53).
    real(double x, mpfr_prec_t bits) {
        detail::free_caches_at_thread_exit();
        mpfr_init2(v_, bits);
        mpfr_set_d(v_, x, MPFR_RNDN);
    }
    /// `x` rounded to `bits` of precision.
    real(const real& x, mpfr_prec_t bits) {
        detail::free_caches_at_thread_exit();
        mpfr_init2(v_, bits);
        mpfr_set(v_, x.v_, MPFR_RNDN);
    }
    real(const real& o) {
        detail::free_caches_at_thread_exit();
        mpfr_init2(v_, mpfr_get_prec(o.v_));
        mpfr_set(v_, o.v_, MPFR_RNDN);
    }
    real(real&& o) noexcept {
        mpfr_init2(v_, MPFR_PREC_MIN);
        mpfr_swap(v_, o.v_);
    }
    real& operator=(const real& o) {
        if (this != &o) {
            mpfr_set_prec(v_, mpfr_get_prec(o.v_));
            mpfr_set(v_, o.v_, MPFR_RNDN);
        }
        return *this;
    }
    real& operator=(real&& o) noexcept {
        mpfr_swap(v_, o.v_);
        return *this;
    }
    ~real() { mpfr_clear(v_); }

    mpfr_ptr get() { return v_; }
    mpfr_srcptr get() const { return v_; }
    mpfr_prec_t precision() const { return mpfr_get_prec(v_); }
    /// Rounded to the nearest double.
    double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }
    bool is_zero() const { return mpfr_zero_p(v_) != 0; }
    int sign() const { return mpfr_sgn(v_); }

private:
    mpfr_t v_;
};

/// The result of a two-argument operation: the larger precision of the two.
inline real result_of(const real& a, const real& b) {
    return real(std::max(a.precision(), b.precision()));
}

inline real operator+(const real& a, const real& b) {
    real r = result_of(a, b);
    mpfr_add(r.get(), a.get(), b.get(), MPFR_RNDN);
    return r;
}
inline real operator-(const real& a, const real& b) {
    real r = result_of(a, b);
    mpfr_sub(r.get(), a.get(), b.get(), MPFR_RNDN);
    return r;
}
inline real operator*(const real& a, const real& b) {
    real r = result_of(a, b);
    mpfr_mul(r.get(), a.get(), b.get(), MPFR_RNDN);
    return r;
}
inline real operator/(const real& a, const real& b) {
    real r = result_of(a, b);
    mpfr_div(r.get(), a.get(), b.get(), MPFR_RNDN);
    return r;
}
inline real operator-(const real& a) {
    real r(a.precision());
    mpfr_neg(r.get(), a.get(), MPFR_RNDN);
    return r;
}
inline real operator+(const real& a, double b) { return a + real(b, a.precision()); }
inline real operator-(const real& a, double b) { return a - real(b, a.precision()); }
inline real operator*(const real& a, double b) { return a * real(b, a.precision()); }
inline real operator/(const real& a, double b) { return a / real(b, a.precision()); }
inline real operator+(double a, const real& b) { return real(a, b.precision()) + b; }
inline real operator-(double a, const real& b) { return real(a, b.precision()) - b; }
inline real operator*(double a, const real& b) { return real(a, b.precision()) * b; }
inline real operator/(double a, const real& b) { return real(a, b.precision()) / b; }
inline bool operator<(const real& a, const real& b) { return mpfr_less_p(a.get(), b.get()) != 0; }
inline bool operator>(const real& a, const real& b) { return mpfr_greater_p(a.get(), b.get()) != 0; }
inline bool operator<(const real& a, double b) { return mpfr_cmp_d(a.get(), b) < 0; }
inline bool operator<(double a, const real& b) { return mpfr_cmp_d(b.get(), a) > 0; }
inline bool operator>(const real& a, double b) { return mpfr_cmp_d(a.get(), b) > 0; }
inline bool operator<=(const real& a, double b) { return mpfr_cmp_d(a.get(), b) <= 0; }
inline bool operator>=(const real& a, double b) { return mpfr_cmp_d(a.get(), b) >= 0; }

/// Applies a one-argument MPFR function.
template <class F>
real apply(F f, const real& x) {
    real r(x.precision());
    f(r.get(), x.get(), MPFR_RNDN);
    return r;
}

inline real sin(const real& x) { return apply(mpfr_sin, x); }
inline real cos(const real& x) { return apply(mpfr_cos, x); }
inline real sqrt(const real& x) { return apply(mpfr_sqrt, x); }
inline real log(const real& x) { return apply(mpfr_log, x); }
inline real abs(const real& x) { return apply(mpfr_abs, x); }
inline real fabs(const real& x) { return apply(mpfr_abs, x); }

/// pi with `bits` of precision.
inline real pi(mpfr_prec_t bits) {
    real r(bits);
    mpfr_const_pi(r.get(), MPFR_RNDN);
    return r;
}

/// The Bessel function J_n(x).
inline real bessel_j(long n, const real& x) {
    real r(x.precision());
    mpfr_jn(r.get(), n, x.get(), MPFR_RNDN);
    return r;
}

/// The arithmetic-geometric mean of a and b.
inline real agm(const real& a, const real& b) {
    real r = result_of(a, b);
    mpfr_agm(r.get(), a.get(), b.get(), MPFR_RNDN);
    return r;
}

/// log2 |x| rounded down (x nonzero): the binary exponent minus one.
inline long exponent(const real& x) { return static_cast<long>(mpfr_get_exp(x.get())) - 1; }

}  // namespace pendulum::mp
