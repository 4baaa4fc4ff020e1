// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Planck spectrum -> CIE XYZ -> sRGB, the two tone maps of seed 003 (Fig. 6) and a
// lookup table meant to be uploaded as a 1D texture.
#include <algorithm>
#include <memory>
#include <vector>

#include "core/numerics/types.hpp"

namespace lc::colour {

using Vec2 = Eigen::Vector2d;

// Tristimulus integrals X, Y, Z = int B_lambda(lambda, T) cmf(lambda) dlambda over
// 360-830 nm (composite Simpson, step in nm). Units: W sr^-1 m^-2 per unit CMF.
Vec3 planckXyz(double temperatureK, double stepNm = 0.5);

// CIE 1931 chromaticity (x, y) of a black body.
Vec2 planckChromaticity(double temperatureK);

enum class ToneMap {
    // XYZ / Y(T): colour only, brightness is lost (seed 003 Fig. 6 left). If a channel still
    // exceeds 1 the colour is divided by its largest channel so the hue survives.
    ColourOnly,
    // XYZ / Y(T_ref) keeps absolute brightness (so the D^4 searchlight change shows), then
    // C -> 0.6 log10(C + 1) on the sRGB value, clamped to [0, 1] (Fig. 6 right).
    ReferenceLog,
};

constexpr double kDefaultReferenceK = 1500.0;

// Display sRGB in [0, 1] of a black body of temperature T under a tone map. Negative
// linear channels are removed with desaturateIntoGamut (see srgb.hpp).
Vec3 blackbodySrgb(double temperatureK, ToneMap map, double referenceK = kDefaultReferenceK);

// The continuous sample index of temperature T in a table of n samples equally spaced in 1/T
// (reciprocal temperature, along which a black body's colour changes about evenly) from tMin to
// tMax, clamped to [0, n - 1]. For every scalar: BlackbodyTable::lookup calls it in double, the
// shaders' lcPlanckSampleIndex is generated from it.
template <class S>
S blackbodySampleIndex(const S& temperature, const S& tMin, const S& tMax, const S& samples) {
    using std::max;
    using std::min;
    const S s = (S(1.0) / tMin - S(1.0) / temperature) / (S(1.0) / tMin - S(1.0) / tMax);
    return min(max(s, S(0.0)), S(1.0)) * (samples - S(1.0));
}

// Tabulated blackbodySrgb for both tone maps, samples equally spaced in 1/T from tMin to tMax
// (blackbodySampleIndex). Lookup interpolates linearly, like GL_LINEAR texture filtering, and
// clamps outside the range.
class BlackbodyTable {
public:
    BlackbodyTable(double tMinK = 1000.0, double tMaxK = 26000.0, int samples = 1024,
                   double referenceK = kDefaultReferenceK);

    Vec3 lookup(double temperatureK, ToneMap map) const;
    // The same colour decoded to linear light (srgbDecode of each texel, then interpolated): what
    // a CPU renderer blends with, without a power function per channel and pixel.
    Vec3 lookupLinear(double temperatureK, ToneMap map) const;
    // The temperature of sample i.
    double sampleTemperature(int i) const;

    // Interleaved RGB floats, samples() texels.
    const std::vector<float>& texels(ToneMap map) const;
    int samples() const { return n_; }
    double tMin() const { return tMin_; }
    double tMax() const { return tMax_; }
    double referenceK() const { return tRef_; }

private:
    Vec3 interpolate(const std::vector<float>& texels, double temperatureK) const;

    double tMin_, tMax_, tRef_;
    int n_;
    std::vector<float> colourOnly_, referenceLog_;
    std::vector<float> colourOnlyLinear_, referenceLogLinear_;
};

// The table every renderer shares (the CPU's post-rendering, lights, special relativity, and the
// shaders' Planck texture): kStandardTable* below, built once on first use (thread-safe), within
// one 8-bit level of blackbodySrgb from 1000 K to 10^6 K in both tone maps
// (BlackbodyTable.StandardTableIsWithinOneLevelOfTheIntegral).
constexpr double kStandardTableMinK = 500.0, kStandardTableMaxK = 1e7;
constexpr int kStandardTableSamples = 8192;
std::shared_ptr<const BlackbodyTable> standardBlackbodyTable();

}  // namespace lc::colour
