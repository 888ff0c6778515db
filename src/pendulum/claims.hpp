// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

namespace pendulum {

/// One number measured for a quantitative statement of the paper (R. Borghi, arXiv:1303.5023).
struct claim_measure {
    std::string claim;      ///< short id of the statement, e.g. "lowest-period-0.1%"
    std::string where;      ///< where the paper makes it
    std::string statement;  ///< what it says
    std::string quantity;   ///< what was measured
    double value = 0;       ///< the measured number
    std::string unit;       ///< "%", "rad", "deg", "" (orders and ratios)
    std::string verdict;    ///< "holds", "fails", "holds only for (c)", ...
};

/// Measures every quantitative statement of the paper; each statement gives one or more rows.
std::vector<claim_measure> paper_claims();

/// The largest |theta_approx(t) - theta_exact(t)| over one exact period, for a Fourier
/// solution given by its method name ("lowest", "first", "second", "order:N").
double max_deviation_over_period(const std::string& method, double theta0);

/// The amplitude in (lo, hi) where f changes sign (Brent's method, GSL), to 1e-12 rad.
double find_amplitude(double (*f)(double theta0, void* params), void* params, double lo, double hi);

}  // namespace pendulum
