// SPDX-License-Identifier: GPL-3.0-or-later
#include "pendulum/amplitude.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

namespace pendulum {

std::string format_double(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, end);
}

void check_amplitude(double theta0, std::string_view name) {
    // The double nearest pi lies just below pi; it still means "pi" to the user, who
    // asked for the unstable equilibrium, so it is rejected like pi itself.
    if (!(theta0 > 0.0 && theta0 < std::numbers::pi)) {
        throw domain_error(std::string(name) + " must be strictly between 0 and pi, got " +
                           format_double(theta0));
    }
}

}  // namespace pendulum
