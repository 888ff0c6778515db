// SPDX-License-Identifier: GPL-3.0-or-later
// The unit costs of figures::render_cost (src/figures/render_cost.cpp), measured on the
// real functions: seconds of one call, averaged over the amplitudes a panel evaluates them
// at. Usage: calibrate_costs [SECONDS_PER_ROW]; see bench/calibrate_costs.md for the run
// the constants come from.
#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/period_error.hpp"

#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace {

double budget = 0.5;  // CPU seconds per row
constexpr long least_calls = 4;

/// CPU seconds of this process so far (a busy machine slows the wall clock, not this).
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// CPU seconds per call of f(theta) over `amplitudes`, repeated for `budget` seconds and at
/// least least_calls calls (the amplitudes' order spreads the first few over the axis).
double per_call(const std::vector<pendulum::amplitude>& amplitudes,
                const std::function<void(const pendulum::amplitude&)>& f) {
    const double start = cpu_seconds();
    long calls = 0;
    double elapsed = 0;
    for (std::size_t i = 0; elapsed < budget || calls < least_calls; i = (i + 1) % amplitudes.size()) {
        f(amplitudes[i]);
        ++calls;
        elapsed = cpu_seconds() - start;
        if (calls >= least_calls && elapsed > 10 * budget) break;
    }
    return elapsed / static_cast<double>(calls);
}

/// The amplitude axis of a period or coefficient panel: 400 points in (0, pi), in an order
/// that spreads them over the axis (a row cut short by its time still averages the axis).
std::vector<pendulum::amplitude> axis() {
    std::vector<pendulum::amplitude> a;
    for (int i = 0; i < 400; ++i) a.emplace_back(std::numbers::pi * (1 + (i * 157 + 158) % 400) / 401.0);
    return a;
}

/// One amplitude close to pi, as a convergence, spectrum or motion panel may take one.
std::vector<pendulum::amplitude> near_pi(double d) { return {pendulum::amplitude::from_pi(d)}; }

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1) budget = std::atof(argv[1]);
    const auto grid = axis();
    std::printf("# seconds per call; axis = mean over 400 amplitudes in (0, pi)\n");
    std::printf("%-26s %12s %12s %12s\n", "method", "period", "error", "solution");
    for (const auto& row : pendulum::method_table()) {
        std::vector<int> ns{row.min_n < 0 ? -1 : row.max_n};
        if (row.role == pendulum::method_role::iterated) ns = {0, 1, 2, 5, 10, 20, 40, 80, 120, 200};
        for (const int n : ns) {
            const pendulum::method_choice m{&row, n};
            const double period = per_call(grid, [&](const auto& a) { (void)pendulum::method_period(m, a); });
            const double error = per_call(grid, [&](const auto& a) { (void)pendulum::method_period_error(m, a); });
            double solution = 0;
            if (m.has_motion() && !m.is_exact()) {
                solution = per_call(grid, [&](const auto& a) { (void)pendulum::method_solution(m, a); });
            }
            std::printf("%-26s %12.3e %12.3e %12.3e\n", m.text().c_str(), period, error, solution);
            std::fflush(stdout);
        }
    }
    std::printf("\n# order:N solution at one amplitude close to pi (d = pi - theta0)\n");
    std::printf("%-10s %12s %12s %12s\n", "N", "d=0.5", "d=0.01", "d=1e-300");
    for (const int n : {10, 40, 100, 200}) {
        const pendulum::method_choice m = pendulum::parse_method("order:" + std::to_string(n));
        std::printf("%-10d", n);
        for (const double d : {0.5, 0.01, 1e-300}) {
            std::printf(" %12.3e", per_call(near_pi(d), [&](const auto& a) { (void)pendulum::method_solution(m, a); }));
        }
        std::printf("\n");
        std::fflush(stdout);
    }
    std::printf("\n# convergence: iterated_period_errors(theta0, N, 1e-300) at d = pi - theta0\n");
    std::printf("%-10s %12s %12s %12s\n", "N", "d=0.5", "d=0.01", "d=1e-300");
    for (const int n : {10, 40, 100, 200}) {
        std::printf("%-10d", n);
        for (const double d : {0.5, 0.01, 1e-300}) {
            std::printf(" %12.3e",
                        per_call(near_pi(d), [&](const auto& a) { (void)pendulum::iterated_period_errors(a, n, 1e-300); }));
        }
        std::printf("\n");
        std::fflush(stdout);
    }
    std::printf("\n# exact: fourier_coefficients(theta0, 100) and exact_solution at d\n");
    for (const double d : {0.5, 1e-6, 1e-300}) {
        std::printf("d=%-8g %12.3e %12.3e\n", d,
                    per_call(near_pi(d), [](const auto& a) { (void)pendulum::fourier_coefficients(a, 100); }),
                    per_call(near_pi(d), [](const auto& a) { (void)pendulum::exact_solution(a).theta(1.0); }));
    }
    return 0;
}
