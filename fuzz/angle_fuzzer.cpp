// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer harness: any bytes into the angle parser give a value or std::invalid_argument.
#include "cli/lists.hpp"
#include "pendulum/angle.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const double v = pendulum::parse_angle(text);
        if (!std::isfinite(v)) std::abort();  // documented: finite or an error
    } catch (const std::invalid_argument&) {
    }
    try {
        pendulum::cli::split_list(text);
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
