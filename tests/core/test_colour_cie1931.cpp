// SPDX-License-Identifier: BSD-3-Clause
// The CIE 1931 colour-matching fit against the CIE table (core/colour/cie1931).
#include <gtest/gtest.h>

#include <cmath>

#include "core/colour/cie1931.hpp"

using namespace lc::colour;

TEST(ColourCie, FitMatchesCie1931TableValues) {
    // CIE 1931 2-degree observer, tabulated (CIE 15:2004): lambda, xbar, ybar, zbar.
    const double table[][4] = {{450, 0.33620, 0.03800, 1.77211}, {500, 0.00490, 0.32300, 0.27200},
                               {555, 0.51205, 1.00000, 0.00575}, {600, 1.06220, 0.63100, 0.00080},
                               {650, 0.28350, 0.10700, 0.00000}, {700, 0.01136, 0.00410, 0.00000}};
    for (const auto& r : table) {
        const lc::Vec3 c = cie1931Cmf(r[0]);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], r[i + 1], 0.035 * std::max(1.0, r[i + 1])) << r[0] << " nm";
    }
}
