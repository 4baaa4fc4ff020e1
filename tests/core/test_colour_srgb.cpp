// SPDX-License-Identifier: BSD-3-Clause
// sRGB: the transfer curve, the white point and desaturation (core/colour/srgb).
#include <gtest/gtest.h>

#include <cmath>

#include "core/colour/srgb.hpp"

using namespace lc::colour;
using lc::Vec3;

TEST(ColourSrgb, TransferCurveKneeAndRoundTrip) {
    // The two branches meet at the knee (continuity to 1e-4, the curve's published rounding).
    EXPECT_NEAR(12.92 * 0.0031308, 1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055, 1e-4);
    EXPECT_NEAR(srgbEncode(0.0031308), 0.0404500, 1e-6);
    EXPECT_NEAR(srgbEncode(1.0), 1.0, 1e-12);
    EXPECT_NEAR(srgbEncode(0.214041140), 0.5, 1e-6);  // 50 % grey, sRGB spec
    for (double x = 0.0; x <= 1.0; x += 0.01) EXPECT_NEAR(srgbDecode(srgbEncode(x)), x, 1e-12);
}

TEST(ColourSrgb, WhitePointMapsToEqualChannels) {
    // D65 white (x, y) = (0.3127, 0.3290) with Y = 1 -> linear RGB (1, 1, 1) to matrix rounding.
    const Vec3 xyz(0.3127 / 0.3290, 1.0, (1 - 0.3127 - 0.3290) / 0.3290);
    const Vec3 rgb = xyzToLinearSrgb(xyz);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(rgb[i], 1.0, 2e-3);
}

TEST(ColourSrgb, DesaturationKeepsLuminanceAndHue) {
    const Vec3 c(1.2, 0.3, -0.2);
    const Vec3 d = desaturateIntoGamut(c);
    EXPECT_NEAR(d.minCoeff(), 0.0, 1e-12);
    EXPECT_NEAR(linearSrgbLuminance(d), linearSrgbLuminance(c), 1e-12);
    // d - Y is parallel to c - Y (same hue direction, less saturation).
    const Vec3 y = Vec3::Constant(linearSrgbLuminance(c));
    EXPECT_NEAR((d - y).normalized().dot((c - y).normalized()), 1.0, 1e-12);
    EXPECT_EQ(desaturateIntoGamut(Vec3(0.1, 0.2, 0.3)), Vec3(0.1, 0.2, 0.3));
    EXPECT_EQ(desaturateIntoGamut(Vec3(-0.5, 0.0, 0.1)), Vec3::Zero());
}
