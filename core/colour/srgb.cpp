// SPDX-License-Identifier: BSD-3-Clause
#include "core/colour/srgb.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace lc::colour {

Vec3 xyzToLinearSrgb(const Vec3& xyz) {
    Eigen::Matrix3d m;
    m << 3.2405, -1.5372, -0.4985,  //
        -0.9693, 1.8760, 0.0416,    //
        0.0556, -0.2040, 1.0573;
    return m * xyz;
}

double linearSrgbLuminance(const Vec3& rgb) { return 0.2126 * rgb.x() + 0.7152 * rgb.y() + 0.0722 * rgb.z(); }

double srgbEncode(double c) { return c < 0.0 ? -srgbCurve(-c) : srgbCurve(c); }

Vec3 srgbEncode(const Vec3& c) { return Vec3(srgbEncode(c.x()), srgbEncode(c.y()), srgbEncode(c.z())); }

double srgbDecode(double e) { return srgbToLinear(e); }

Vec3 desaturateIntoGamut(const Vec3& c) {
    const double minC = c.minCoeff();
    if (minC >= 0.0) return c;
    const double y = linearSrgbLuminance(c);
    if (y <= 0.0) return Vec3::Zero();
    // Y - minC > 0 here, so s lies in (0, 1).
    const double s = y / (y - minC);
    Vec3 out = Vec3::Constant(y) + s * (c - Vec3::Constant(y));
    return out.cwiseMax(0.0);  // only rounding noise is clipped
}

}  // namespace lc::colour
