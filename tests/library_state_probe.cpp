// SPDX-License-Identifier: GPL-3.0-or-later
// A host program that links only the core library (pendulum_core) and calls every part of
// it that uses GSL: library_state_test.sh checks with nm that neither the library nor this
// program refers to GSL's error handler or to other process-wide settings, and runs it.
#include "pendulum/amplitude.hpp"
#include "pendulum/approximants.hpp"
#include "pendulum/claims.hpp"
#include "pendulum/exact.hpp"
#include "pendulum/methods.hpp"
#include "pendulum/motion.hpp"

#include <cmath>
#include <cstdio>
#include <exception>

namespace {

double minus_half(double x, void*) { return x - 0.5; }

}  // namespace

int main() {
    using namespace pendulum;
    double sum = 0;
    for (const double theta0 : {1e-3, 0.5, 2.0, 3.1}) {
        const exact_solution exact(theta0);
        sum += exact.coefficient_by_quadrature(1) + iterated(theta0, 3).period_ratio() + first_order(theta0).period_ratio();
        sum += motion::from_state({theta0, 0.5}).theta(1.0);
        for (const auto& row : method_table()) {
            const method_choice m{&row, row.min_n < 0 ? -1 : row.min_n, nullptr};
            const auto e = method_period_error(m, theta0, precision::correctly_rounded);
            if (e.what == period_error::kind::value) sum += e.value;
        }
    }
    sum += find_amplitude(minus_half, nullptr, 0.0, 1.0) + max_deviation_over_period("lowest", 2.0);
    std::printf("%.17g\n", sum);
    return std::isfinite(sum) ? 0 : 1;
}
