// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace plot {

namespace {

const char* const minus = "\u2212";

/// Integer tick indices i with i*step in [lo, hi] (or enclosing it when expanding).
std::pair<long long, long long> index_range(double lo, double hi, double step, bool expand) {
    // A small slack keeps ticks that land on the limits up to rounding.
    const double slack = 1e-9;
    const double a = lo / step;
    const double b = hi / step;
    if (expand) return {static_cast<long long>(std::floor(a + slack)), static_cast<long long>(std::ceil(b - slack))};
    return {static_cast<long long>(std::ceil(a - slack)), static_cast<long long>(std::floor(b + slack))};
}

void widen_if_degenerate(double& lo, double& hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) throw std::invalid_argument("axis range must be finite");
    if (lo > hi) std::swap(lo, hi);
    if (hi - lo <= 1e-12 * std::max(std::fabs(lo), std::fabs(hi))) {
        const double d = lo == 0.0 ? 1.0 : 0.05 * std::fabs(lo);
        lo -= d;
        hi += d;
    }
}

std::string with_minus(const std::string& s) {
    if (!s.empty() && s[0] == '-') return minus + s.substr(1);
    return s;
}

}  // namespace

double nice_step(double lo, double hi, int max_ticks, bool expand) {
    widen_if_degenerate(lo, hi);  // an empty range gets a step around its value, never 0
    max_ticks = std::max(max_ticks, 2);
    const double raw = (hi - lo) / (max_ticks - 1);
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0, 20.0}) {
        const double step = m * decade;
        // 2.5 only where its labels need no more decimals than a step of 5 (25, 250, ...):
        // 0.25 would print 0.00 ... 1.00 where fewer ticks of the same range print 0.0 ... 1.0.
        if (m == 2.5 && step < 10.0 * (1 - 1e-9)) continue;
        const auto [a, b] = index_range(lo, hi, step, expand);
        if (b - a + 1 <= max_ticks && b - a >= 1) return step;
    }
    return 20.0 * decade;
}

std::vector<std::string> format_linear_labels(const std::vector<double>& ticks, double step) {
    double largest = 0.0;
    for (double t : ticks) largest = std::max(largest, std::fabs(t));
    std::vector<std::string> labels;
    const bool scientific = largest >= 1e5 || (largest > 0 && largest < 1e-2);
    int exponent = 0;
    double scaled_step = step;
    if (scientific) {
        exponent = static_cast<int>(std::floor(std::log10(largest)));
        scaled_step = step / std::pow(10.0, exponent);
    }
    // Fewest decimals that show every multiple of the step exactly.
    int decimals = 0;
    while (decimals < 12) {
        const double scaled = scaled_step * std::pow(10.0, decimals);
        if (std::fabs(scaled - std::round(scaled)) < 1e-6 * scaled) break;
        ++decimals;
    }
    for (double t : ticks) {
        char buf[64];
        if (t == 0.0 && scientific) {
            labels.emplace_back("0");
        } else if (!scientific) {
            std::snprintf(buf, sizeof buf, "%.*f", decimals, t == 0.0 ? 0.0 : t);  // never "-0.0"
            labels.push_back(with_minus(buf));
        } else {
            std::snprintf(buf, sizeof buf, "%.*f", decimals, t / std::pow(10.0, exponent));
            char ebuf[16];
            std::snprintf(ebuf, sizeof ebuf, "%d", exponent);
            labels.push_back(with_minus(buf) + "\u00d710<sup>" + with_minus(ebuf) + "</sup>");
        }
    }
    return labels;
}

tick_set linear_ticks(double lo, double hi, int max_ticks, bool expand) {
    widen_if_degenerate(lo, hi);
    const double step = nice_step(lo, hi, max_ticks, expand);
    const auto [a, b] = index_range(lo, hi, step, expand);
    tick_set t;
    t.lo = expand ? std::min(lo, a * step) : lo;
    t.hi = expand ? std::max(hi, b * step) : hi;
    for (long long i = a; i <= b; ++i) t.major.push_back(i == 0 ? 0.0 : static_cast<double>(i) * step);
    t.labels = format_linear_labels(t.major, step);
    // AutoMinorLocator: 5 subdivisions for steps 1 and 5, 4 for 2 and 2.5.
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    const int sub = (std::fabs(mantissa - 2.0) < 1e-9 || std::fabs(mantissa - 2.5) < 1e-9) ? 4 : 5;
    const double minor_step = step / sub;
    const auto [ma, mb] = index_range(t.lo, t.hi, minor_step, false);
    for (long long i = ma; i <= mb; ++i) {
        if (i % sub != 0) t.minor.push_back(static_cast<double>(i) * minor_step);
    }
    return t;
}

namespace {

constexpr double pi_value = 3.14159265358979323846;

/// The step of a pi axis as num/den of pi ({0, 1} if none fits): the finest of 1/8 ... 8
/// with at most max_ticks ticks, eighths only where quarters would leave fewer than three;
/// ticks counted as the axis has them (rounded out to a tick where it expands, else within
/// its limits), so that a thinned axis within fixed limits keeps multiples of pi.
std::pair<int, int> pi_step(double lo, double hi, int max_ticks, bool expand) {
    const int steps[][2] = {{1, 8}, {1, 4}, {1, 2}, {1, 1}, {2, 1}, {4, 1}, {8, 1}};
    for (const auto& s : steps) {
        const auto [a, b] = index_range(lo, hi, pi_value * s[0] / s[1], expand);
        const bool too_fine = s[1] == 8 && [&] {
            const auto [qa, qb] = index_range(lo, hi, pi_value / 4, expand);
            return qb - qa + 1 >= 3;
        }();
        if (!too_fine && b - a + 1 <= std::max(max_ticks, 2)) return {s[0], s[1]};
    }
    return {0, 1};
}

/// The label of p/q pi (reduced): 0, π, −3π/4, ...
std::string pi_label(long long p, long long q) {
    if (p == 0) return "0";
    std::string label;
    const long long ap = p < 0 ? -p : p;
    if (p < 0) label += minus;
    if (ap != 1) label += std::to_string(ap);
    label += "<i>\u03c0</i>";
    if (q != 1) label += "/" + std::to_string(q);
    return label;
}

/// Minor ticks halfway between the major ones, `step` apart, within the set's range.
void add_halves(tick_set& t, double step) {
    const double minor_step = step / 2;
    const auto [ma, mb] = index_range(t.lo, t.hi, minor_step, false);
    for (long long i = ma; i <= mb; ++i) {
        if (i % 2 != 0) t.minor.push_back(static_cast<double>(i) * minor_step);
    }
}

}  // namespace

tick_set pi_ticks(double lo, double hi, int max_ticks, bool expand) {
    widen_if_degenerate(lo, hi);
    const auto [num, den] = pi_step(lo, hi, max_ticks, expand);
    // Too long a range for multiples of pi to read well, or too short for two of them
    // (amplitudes within a hair of pi): plain numbers.
    if (num == 0) return linear_ticks(lo, hi, max_ticks, expand);
    const double step = pi_value * num / den;
    const auto [a, b] = index_range(lo, hi, step, expand);
    if (const auto [ia, ib] = index_range(lo, hi, step, false); ib - ia + 1 < 2) {
        return linear_ticks(lo, hi, max_ticks, expand);
    }
    tick_set t;
    t.lo = expand ? std::min(lo, a * step) : lo;
    t.hi = expand ? std::max(hi, b * step) : hi;
    for (long long i = a; i <= b; ++i) {
        // i*num/den pi, reduced.
        long long p = i * num;
        long long q = den;
        const long long g = std::gcd(p < 0 ? -p : p, q);
        if (g > 0) {
            p /= g;
            q /= g;
        }
        t.major.push_back(static_cast<double>(p) * pi_value / static_cast<double>(q));
        t.labels.push_back(pi_label(p, q));
    }
    add_halves(t, step);
    return t;
}

tick_set degree_ticks(double lo, double hi, int max_ticks, bool expand) {
    widen_if_degenerate(lo, hi);
    // Steps that divide the circle: ticks land on 30, 45, 90, ... degrees.
    const int steps[] = {1, 2, 5, 10, 15, 30, 45, 90, 180, 360};
    int step = 360;
    for (int s : steps) {
        const auto [a, b] = index_range(lo, hi, s, expand);
        if (b - a + 1 <= std::max(max_ticks, 2)) {
            step = s;
            break;
        }
    }
    const auto [a, b] = index_range(lo, hi, step, expand);
    tick_set t;
    t.lo = expand ? std::min(lo, static_cast<double>(a * step)) : lo;
    t.hi = expand ? std::max(hi, static_cast<double>(b * step)) : hi;
    for (long long i = a; i <= b; ++i) {
        const long long v = i * step;
        t.major.push_back(static_cast<double>(v));
        t.labels.push_back((v < 0 ? minus : "") + std::to_string(v < 0 ? -v : v) + "\u00b0");
    }
    // Minor ticks halve the step where that stays a whole number of degrees.
    if (step % 2 == 0 || step == 5 || step == 15 || step == 45) {
        const double minor_step = step / 2.0;
        const auto [ma, mb] = index_range(t.lo, t.hi, minor_step, false);
        for (long long i = ma; i <= mb; ++i) {
            if (i % 2 != 0) t.minor.push_back(static_cast<double>(i) * minor_step);
        }
    }
    return t;
}

namespace {

/// The decades of a log axis: the first and last labelled exponent, and every how many
/// decades a label stands (doubling until at most max_ticks fit).
struct decades {
    long long first = 0;
    long long last = 0;
    long long every = 1;
};

decades labelled_decades(double lo, double hi, int max_ticks, bool expand) {
    double a = std::log10(lo);
    double b = std::log10(hi);
    if (b - a < 1e-9) {
        a -= 1;
        b += 1;
    }
    decades d;
    d.first = expand ? static_cast<long long>(std::floor(a + 1e-9)) : static_cast<long long>(std::ceil(a - 1e-9));
    d.last = expand ? static_cast<long long>(std::ceil(b - 1e-9)) : static_cast<long long>(std::floor(b + 1e-9));
    while ((d.last - d.first) / d.every + 1 > std::max(max_ticks, 2)) d.every *= 2;
    // Fixed limits: a step up to twice as long that divides the span labels both ends
    // (1e-10 ... 1 every 5 decades, not 1e-10 and 1e-2 every 8 with 10^0 bare).
    for (long long k = d.every; !expand && d.last > d.first && k <= 2 * d.every; ++k) {
        if ((d.last - d.first) % k == 0) {
            d.every = k;
            break;
        }
    }
    if (expand) {
        // Keep the limits on labelled decades.
        d.first = static_cast<long long>(std::floor(static_cast<double>(d.first) / d.every)) * d.every;
        d.last = static_cast<long long>(std::ceil(static_cast<double>(d.last) / d.every)) * d.every;
    }
    return d;
}

/// 10^e as a major tick (labelled) or a minor one, as the decades say.
void add_power(tick_set& t, const decades& d, long long e) {
    if (e < d.first || e > d.last) return;
    const double v = std::pow(10.0, static_cast<double>(e));
    if ((e - d.first) % d.every == 0) {
        t.major.push_back(v);
        const std::string exponent = e < 0 ? minus + std::to_string(-e) : std::to_string(e);
        t.labels.push_back("10<sup>" + exponent + "</sup>");
    } else {
        t.minor.push_back(v);
    }
}

/// m times 10^e for m = 2 ... 9 within the set's range: minor ticks, except 2 and 5 times
/// it within one decade, which are labelled too.
void add_multiples(tick_set& t, long long e, bool within_decade) {
    const double v = std::pow(10.0, static_cast<double>(e));
    const double slack = 1e-9 * (t.hi - t.lo);
    for (int m = 2; m <= 9; ++m) {
        const double u = m * v;
        if (u < t.lo - slack || u > t.hi + slack) continue;
        if (within_decade && (m == 2 || m == 5)) {
            t.major.push_back(u);
            t.labels.emplace_back();
        } else {
            t.minor.push_back(u);
        }
    }
}

/// The major ticks sorted and labelled as plain numbers sharing precision: 0.5 1 2 5.
void label_as_numbers(tick_set& t) {
    std::sort(t.major.begin(), t.major.end());
    t.labels.clear();
    for (double v : t.major) {
        char buf[32];
        const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(v) + 1e-9)));
        std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
        t.labels.emplace_back(buf);
    }
}

}  // namespace

tick_set log_ticks(double lo, double hi, int max_ticks, bool expand) {
    if (!(lo > 0) || !(hi > 0) || !std::isfinite(lo) || !std::isfinite(hi)) {
        throw std::invalid_argument("a logarithmic axis needs a positive, finite range");
    }
    if (lo > hi) std::swap(lo, hi);
    const decades d = labelled_decades(lo, hi, max_ticks, expand);
    tick_set t;
    t.lo = expand ? std::pow(10.0, static_cast<double>(d.first)) : lo;
    t.hi = expand ? std::pow(10.0, static_cast<double>(d.last)) : hi;
    const bool within_decade = d.last - d.first < 1;  // fewer than two powers of ten in range
    const long long first = static_cast<long long>(std::floor(std::log10(t.lo) + 1e-9));
    const long long last = static_cast<long long>(std::ceil(std::log10(t.hi) - 1e-9));
    for (long long e = first; e <= last; ++e) {
        add_power(t, d, e);
        if (d.every == 1 && last - first <= 8) add_multiples(t, e, within_decade);
    }
    if (within_decade) label_as_numbers(t);
    std::sort(t.minor.begin(), t.minor.end());
    return t;
}

}  // namespace plot
