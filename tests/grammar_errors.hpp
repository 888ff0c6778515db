// SPDX-License-Identifier: GPL-3.0-or-later
// What the core's expression languages say of a text: its refusal's message, or "accepted".
#pragma once

#include "pendulum/angle.hpp"
#include "pendulum/formula.hpp"

#include <string>

namespace test_support {

/// The message an angle's text is refused with, or "accepted".
inline std::string angle_error(const std::string& text) {
    try {
        (void)pendulum::parse_angle(text);
    } catch (const pendulum::domain_error& e) {
        return e.what();
    }
    return "accepted";
}

/// The message a formula's text is refused with, or "accepted".
inline std::string formula_error(const std::string& text) {
    try {
        const pendulum::formula f(text);
    } catch (const pendulum::domain_error& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace test_support
