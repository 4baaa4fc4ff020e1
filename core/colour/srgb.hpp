// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// CIE XYZ -> linear BT.709/sRGB -> sRGB transfer curve, plus gamut handling.
#include "core/numerics/select.hpp"
#include "core/numerics/types.hpp"

#include <cmath>

namespace lc::colour {

// Matrix of docs/PHYSICS.md section 6 / seed 003 eq. 12 (D65 white).
Vec3 xyzToLinearSrgb(const Vec3& xyz);

// Relative luminance of linear sRGB (Y row of the inverse matrix, BT.709 weights).
double linearSrgbLuminance(const Vec3& rgb);

// sRGB opto-electronic transfer curve for one channel (seed 003 eq. 13); values above 1
// are extended with the same power law, negatives are mirrored.
double srgbEncode(double linear);
Vec3 srgbEncode(const Vec3& linear);
double srgbDecode(double encoded);
// The decode for every scalar (double, codegen::Expr for the shaders' lcSrgbDecode): odd in e.
template <class S>
S srgbToLinear(const S& e) {
    using std::abs;
    using std::pow;
    const S a = abs(e);
    const S linear = ifPositive(a - S(0.04045), pow((a + S(0.055)) / S(1.055), S(2.4)), a / S(12.92));
    return ifPositive(-e, -linear, linear);
}

// The sRGB encoding curve for c >= 0 (seed 003 eq. 13), the one place it is written.
template <class S>
S srgbCurve(const S& c) {
    using std::pow;
    return ifPositive(c - S(0.0031308), S(1.055) * pow(c, S(1.0 / 2.4)) - S(0.055), S(12.92) * c);
}

// The encode of a display image (8-bit files, the GPU post-renderer's output): linear clamped to
// [0, 1], then the sRGB curve. For every scalar (double; codegen::Expr for lcSrgbEncodeDisplay).
template <class S>
S srgbEncodeDisplay(const S& linear) {
    using std::max;
    using std::min;
    return srgbCurve(min(max(linear, S(0.0)), S(1.0)));
}

// Out-of-gamut fix: if a channel is negative, mix the colour with the grey of the same
// luminance, C' = Y + s (C - Y), choosing the largest s in [0, 1] that makes the smallest
// channel zero. Luminance and hue angle are kept; only saturation is lost. A colour with
// Y <= 0 becomes black.
Vec3 desaturateIntoGamut(const Vec3& linearRgb);

}  // namespace lc::colour
