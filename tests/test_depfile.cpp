// SPDX-License-Identifier: GPL-3.0-or-later
// Specs, styles and names from strangers: see the tests below.
#include "process.hpp"

#include <gtest/gtest.h>
