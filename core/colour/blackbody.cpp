#include "core/colour/blackbody.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/colour/cie1931.hpp"
#include "core/colour/planck.hpp"
#include "core/colour/srgb.hpp"

namespace lc::colour {

Vec3 planckXyz(double T, double stepNm) {
    // Simpson needs an even interval count.
    int n = static_cast<int>(std::ceil((kCmfMaxNm - kCmfMinNm) / stepNm));
    if (n % 2) ++n;
    const double h = (kCmfMaxNm - kCmfMinNm) / n;
    Vec3 sum = Vec3::Zero();
    for (int i = 0; i <= n; ++i) {
        const double w = kCmfMinNm + i * h;
        const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * planckRadianceNm(w, T) * cie1931Cmf(w);
    }
    return sum * (h * 1e-9 / 3.0);
}

Vec2 planckChromaticity(double T) {
    const Vec3 xyz = planckXyz(T);
    const double s = xyz.sum();
    return Vec2(xyz.x() / s, xyz.y() / s);
}

namespace {
Vec3 colourOnly(const Vec3& xyz) {
    if (xyz.y() <= 0.0) return Vec3::Zero();
    Vec3 rgb = desaturateIntoGamut(xyzToLinearSrgb(xyz / xyz.y()));
    rgb /= std::max(1.0, rgb.maxCoeff());
    return srgbEncode(rgb);
}

Vec3 referenceLog(const Vec3& xyz, double yRef) {
    const Vec3 rgb = srgbEncode(desaturateIntoGamut(xyzToLinearSrgb(xyz / yRef)));
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = std::clamp(0.6 * std::log10(rgb[i] + 1.0), 0.0, 1.0);
    return out;
}
}  // namespace

Vec3 blackbodySrgb(double T, ToneMap map, double referenceK) {
    const Vec3 xyz = planckXyz(T);
    if (map == ToneMap::ColourOnly) return colourOnly(xyz);
    return referenceLog(xyz, planckXyz(referenceK).y());
}

BlackbodyTable::BlackbodyTable(double tMinK, double tMaxK, int samples, double referenceK)
    : tMin_(tMinK), tMax_(tMaxK), tRef_(referenceK), n_(samples) {
    if (samples < 2 || !(tMaxK > tMinK) || tMinK <= 0.0) throw std::invalid_argument("BlackbodyTable: bad range");
    colourOnly_.resize(3 * n_);
    referenceLog_.resize(3 * n_);
    const double yRef = planckXyz(tRef_).y();
    for (int i = 0; i < n_; ++i) {
        const double T = tMin_ + (tMax_ - tMin_) * i / (n_ - 1);
        const Vec3 xyz = planckXyz(T);
        const Vec3 a = colourOnly(xyz), b = referenceLog(xyz, yRef);
        for (int c = 0; c < 3; ++c) {
            colourOnly_[3 * i + c] = static_cast<float>(a[c]);
            referenceLog_[3 * i + c] = static_cast<float>(b[c]);
        }
    }
}

Vec3 BlackbodyTable::lookup(double T, ToneMap map) const {
    const std::vector<float>& t = texels(map);
    const double u = blackbodySampleIndex(T, tMin_, tMax_, double(n_));
    const int i = std::min(static_cast<int>(u), n_ - 2);
    const double f = u - i;
    Vec3 out;
    for (int c = 0; c < 3; ++c) out[c] = (1.0 - f) * t[3 * i + c] + f * t[3 * (i + 1) + c];
    return out;
}

const std::vector<float>& BlackbodyTable::texels(ToneMap map) const {
    return map == ToneMap::ColourOnly ? colourOnly_ : referenceLog_;
}

}  // namespace lc::colour
