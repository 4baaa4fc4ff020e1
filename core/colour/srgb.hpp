#pragma once
// CIE XYZ -> linear BT.709/sRGB -> sRGB transfer curve, plus gamut handling.
#include "core/numerics/types.hpp"

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

// Out-of-gamut fix: if a channel is negative, mix the colour with the grey of the same
// luminance, C' = Y + s (C - Y), choosing the largest s in [0, 1] that makes the smallest
// channel zero. Luminance and hue angle are kept; only saturation is lost. A colour with
// Y <= 0 becomes black.
Vec3 desaturateIntoGamut(const Vec3& linearRgb);

}  // namespace lc::colour
