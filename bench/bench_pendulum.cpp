// SPDX-License-Identifier: GPL-3.0-or-later
// Time per amplitude of the exact solution and of each approximant.
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"

#include <benchmark/benchmark.h>

#include <numbers>

namespace {

// Amplitudes spread over (0, pi), the near-separatrix end included.
constexpr double amplitudes[] = {0.1, 0.5, 1.0, std::numbers::pi / 2, 2.5, 0.9 * std::numbers::pi,
                                 0.99 * std::numbers::pi, std::numbers::pi - 1e-6};
constexpr int count = sizeof amplitudes / sizeof amplitudes[0];

template <typename F>
void per_amplitude(benchmark::State& state, F f) {
    int i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(f(amplitudes[i]));
        i = (i + 1) % count;
    }
}

void exact_period(benchmark::State& s) { per_amplitude(s, [](double t) { return pendulum::period_ratio(t); }); }
void exact_coefficients(benchmark::State& s) {
    per_amplitude(s, [](double t) { return pendulum::fourier_coefficients(t, 3); });
}
void exact_theta_100(benchmark::State& s) {
    per_amplitude(s, [](double t) {
        const pendulum::exact_solution e(t);
        double sum = 0;
        for (int i = 0; i < 100; ++i) sum += e.theta_at_fraction(i / 100.0);
        return sum;
    });
}
void quadrature_c1(benchmark::State& s) {
    per_amplitude(s, [](double t) { return pendulum::exact_solution(t).coefficient_by_quadrature(0); });
}
void harmonic(benchmark::State& s) { per_amplitude(s, [](double t) { return pendulum::harmonic(t); }); }
void lowest(benchmark::State& s) { per_amplitude(s, [](double t) { return pendulum::lowest_order(t); }); }
void first(benchmark::State& s) { per_amplitude(s, [](double t) { return pendulum::first_order(t); }); }
void second(benchmark::State& s) { per_amplitude(s, [](double t) { return pendulum::second_order(t); }); }
void polynomial(benchmark::State& s) { per_amplitude(s, [](double t) { return pendulum::polynomial(t); }); }
void iterated(benchmark::State& s) {
    const int order = static_cast<int>(s.range(0));
    per_amplitude(s, [order](double t) { return pendulum::iterated(t, order); });
}

/// Order 200 at one amplitude (argument: theta0 in hundredths of pi), the two cases.
void iterated_200(benchmark::State& s) {
    const double theta0 = static_cast<double>(s.range(0)) / 100 * std::numbers::pi;
    for (auto _ : s) benchmark::DoNotOptimize(pendulum::iterated(theta0, 200));
}
/// Every level's period with its extended-precision rounding estimate (the convergence figure).
void iterated_periods_40(benchmark::State& s) {
    per_amplitude(s, [](double t) { return pendulum::iterated_periods(t, 40); });
}

}  // namespace

BENCHMARK(exact_period);
BENCHMARK(exact_coefficients);
BENCHMARK(exact_theta_100);
BENCHMARK(quadrature_c1);
BENCHMARK(harmonic);
BENCHMARK(lowest);
BENCHMARK(first);
BENCHMARK(second);
BENCHMARK(polynomial);
BENCHMARK(iterated)->Arg(2)->Arg(8)->Arg(24);
BENCHMARK(iterated_200)->Arg(50)->Arg(99)->Unit(benchmark::kMillisecond);
BENCHMARK(iterated_periods_40)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
