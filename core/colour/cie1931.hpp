// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// CIE 1931 2-degree colour matching functions, analytic approximation.
#include "core/numerics/types.hpp"

namespace lc::colour {

// xbar, ybar, zbar at wavelength lambda (nm). Multi-lobe piecewise-Gaussian fit of
// C. Wyman, P.-P. Sloan, P. Shirley, "Simple Analytic Approximations to the CIE XYZ
// Color Matching Functions", JCGT 2(2), 2013 (listing 1). Error is well below the
// spread between CIE observers; no table needs to be shipped.
Vec3 cie1931Cmf(double lambdaNm);

// Visible range over which tristimulus integrals are taken.
constexpr double kCmfMinNm = 360.0;
constexpr double kCmfMaxNm = 830.0;

}  // namespace lc::colour
