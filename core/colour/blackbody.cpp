// SPDX-License-Identifier: BSD-3-Clause
#include "core/colour/blackbody.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

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

namespace {
// planckXyz's Simpson sum with the colour-matching functions and weights computed once: a table
// of thousands of temperatures then costs one exponential per wavelength and temperature.
class PlanckIntegrator {
public:
    explicit PlanckIntegrator(double stepNm = 0.5) {
        int n = static_cast<int>(std::ceil((kCmfMaxNm - kCmfMinNm) / stepNm));
        if (n % 2) ++n;
        const double h = (kCmfMaxNm - kCmfMinNm) / n;
        for (int i = 0; i <= n; ++i) {
            const double w = kCmfMinNm + i * h;
            const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            wavelengths_.push_back(w);
            weighted_.push_back(weight * cie1931Cmf(w) * (h * 1e-9 / 3.0));
        }
    }
    Vec3 xyz(double T) const {
        Vec3 sum = Vec3::Zero();
        for (std::size_t i = 0; i < wavelengths_.size(); ++i)
            sum += planckRadianceNm(wavelengths_[i], T) * weighted_[i];
        return sum;
    }

private:
    std::vector<double> wavelengths_;
    std::vector<Vec3> weighted_;
};
}  // namespace

BlackbodyTable::BlackbodyTable(double tMinK, double tMaxK, int samples, double referenceK)
    : tMin_(tMinK), tMax_(tMaxK), tRef_(referenceK), n_(samples) {
    if (samples < 2 || !(tMaxK > tMinK) || tMinK <= 0.0) throw std::invalid_argument("BlackbodyTable: bad range");
    colourOnly_.resize(3 * n_);
    referenceLog_.resize(3 * n_);
    const double yRef = planckXyz(tRef_).y();
    const PlanckIntegrator integrator;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n_; ++i) {
        const double T = sampleTemperature(i);
        const Vec3 xyz = integrator.xyz(T);
        const Vec3 a = colourOnly(xyz), b = referenceLog(xyz, yRef);
        for (int c = 0; c < 3; ++c) {
            colourOnly_[3 * i + c] = static_cast<float>(a[c]);
            referenceLog_[3 * i + c] = static_cast<float>(b[c]);
        }
    }
    colourOnlyLinear_.resize(colourOnly_.size());
    referenceLogLinear_.resize(referenceLog_.size());
    for (std::size_t k = 0; k < colourOnly_.size(); ++k) {
        colourOnlyLinear_[k] = static_cast<float>(srgbDecode(colourOnly_[k]));
        referenceLogLinear_[k] = static_cast<float>(srgbDecode(referenceLog_[k]));
    }
}

Vec3 BlackbodyTable::interpolate(const std::vector<float>& texels, double T) const {
    const double u = blackbodySampleIndex(T, tMin_, tMax_, double(n_));
    const int i = std::min(static_cast<int>(u), n_ - 2);
    const double f = u - i;
    Vec3 out;
    for (int c = 0; c < 3; ++c) out[c] = (1.0 - f) * texels[3 * i + c] + f * texels[3 * (i + 1) + c];
    return out;
}

Vec3 BlackbodyTable::lookup(double T, ToneMap map) const { return interpolate(texels(map), T); }

Vec3 BlackbodyTable::lookupLinear(double T, ToneMap map) const {
    return interpolate(map == ToneMap::ColourOnly ? colourOnlyLinear_ : referenceLogLinear_, T);
}

double BlackbodyTable::sampleTemperature(int i) const {
    const double s = static_cast<double>(i) / (n_ - 1);
    return 1.0 / (1.0 / tMin_ - s * (1.0 / tMin_ - 1.0 / tMax_));
}

std::shared_ptr<const BlackbodyTable> standardBlackbodyTable() {
    static const auto table =
        std::make_shared<const BlackbodyTable>(kStandardTableMinK, kStandardTableMaxK, kStandardTableSamples);
    return table;
}

const std::vector<float>& BlackbodyTable::texels(ToneMap map) const {
    return map == ToneMap::ColourOnly ? colourOnly_ : referenceLog_;
}

}  // namespace lc::colour
