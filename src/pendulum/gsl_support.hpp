// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <gsl/gsl_integration.h>

#include <memory>
#include <string>

namespace pendulum {

/// Deleter for a GSL integration workspace.
struct integration_workspace_deleter {
    /// Frees the workspace.
    void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};

/// Owning handle of a GSL integration workspace.
using integration_workspace =
    std::unique_ptr<gsl_integration_workspace, integration_workspace_deleter>;

/// Allocates a workspace for `size` subintervals; throws std::bad_alloc on failure.
integration_workspace make_integration_workspace(std::size_t size);

/// Switches GSL's abort-on-error handler off (once); GSL status codes are checked instead.
void use_gsl_status_codes();

/// Throws std::runtime_error naming `what` if status is not GSL_SUCCESS.
void check_gsl(int status, const std::string& what);

/// The Bessel function J_n(x) of integer order (negative n allowed); throws on GSL failure.
double bessel_j(int n, double x);

/// J_n(x)/x for n >= 1, accurate for every double x != 0, subnormals included (the power
/// series below |x| = 1e-8, where J_n(x)/x = (x/2)^(n-1) / (2 n!) (1 - x^2/(4(n+1)))).
double bessel_j_over_x(int n, double x);

/// Amplitudes below this are "small": the power series in theta0 are exact to double there.
inline constexpr double small_amplitude = 1e-8;

}  // namespace pendulum
