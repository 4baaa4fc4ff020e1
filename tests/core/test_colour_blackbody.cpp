// SPDX-License-Identifier: BSD-3-Clause
// Black-body colours: Planckian-locus literature values, tone maps and the LUT (core/colour/blackbody).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"

using namespace lc::colour;
using lc::Vec3;

TEST(ColourBlackbody, PlanckianLocusChromaticity) {
    // Literature chromaticities of the Planckian locus (CIE 1931 2-degree).
    const Vec2 a = planckChromaticity(2856.0);  // CIE illuminant A
    EXPECT_NEAR(a.x(), 0.4476, 0.002);
    EXPECT_NEAR(a.y(), 0.4074, 0.002);
    const Vec2 d = planckChromaticity(6500.0);
    EXPECT_NEAR(d.x(), 0.3135, 0.002);
    EXPECT_NEAR(d.y(), 0.3237, 0.002);
}

TEST(ColourBlackbody, D65LikeTemperatureIsNearlyWhite) {
    const Vec3 c = blackbodySrgb(6504.0, ToneMap::ColourOnly);
    EXPECT_GT(c.minCoeff(), 0.9);
    EXPECT_LE(c.maxCoeff(), 1.0 + 1e-12);
}

TEST(ColourBlackbody, BlueGrowsMonotonicallyWithTemperature) {
    double lastX = 1.0, lastRatio = 0.0;
    for (double T = 1000.0; T <= 26000.0; T += 250.0) {
        const Vec2 xy = planckChromaticity(T);
        EXPECT_LT(xy.x(), lastX) << T;
        lastX = xy.x();
        // Displayed colour: blue over red never decreases (equal only while blue is clipped to 0).
        const Vec3 rgb = blackbodySrgb(T, ToneMap::ColourOnly);
        const double ratio = rgb.z() / rgb.x();
        if (T > 2000.0)
            EXPECT_GT(ratio, lastRatio) << T;
        else
            EXPECT_GE(ratio, lastRatio) << T;
        lastRatio = ratio;
    }
    const Vec3 cool = blackbodySrgb(2000.0, ToneMap::ColourOnly), hot = blackbodySrgb(20000.0, ToneMap::ColourOnly);
    EXPECT_GT(cool.x(), cool.z());
    EXPECT_GT(hot.z(), hot.x());
}

TEST(ColourToneMap, ReferenceLogKeepsBrightnessAndSaturatesToWhite) {
    const Vec3 c1500 = blackbodySrgb(1500.0, ToneMap::ReferenceLog);
    EXPECT_GT(c1500.x(), c1500.y());  // dark red
    EXPECT_GT(c1500.y(), c1500.z());
    EXPECT_LT(c1500.x(), 0.5);
    const Vec3 c5000 = blackbodySrgb(5000.0, ToneMap::ReferenceLog);
    EXPECT_GT(c5000.minCoeff(), 0.95);  // "above 3600 K mapped to white"
    double last = -1.0;
    for (double T = 1000.0; T <= 4000.0; T += 100.0) {
        const Vec3 c = blackbodySrgb(T, ToneMap::ReferenceLog);
        const double lum = c.sum();
        EXPECT_GE(lum, last) << T;  // brighter when hotter: searchlight stays visible
        last = lum;
    }
}

TEST(ColourTable, NodesAreExactAndErrorShrinksWithSamples) {
    const BlackbodyTable coarse(1000.0, 26000.0, 64), fine(1000.0, 26000.0, 1024);
    for (int i = 0; i < coarse.samples(); i += 7) {
        // Nodes equally spaced in 1/T.
        const double T = 1.0 / (1.0 / 1000.0 - (1.0 / 1000.0 - 1.0 / 26000.0) * i / (coarse.samples() - 1));
        EXPECT_NEAR(coarse.sampleTemperature(i), T, 1e-9 * T);
        for (ToneMap m : {ToneMap::ColourOnly, ToneMap::ReferenceLog})
            EXPECT_LT((coarse.lookup(T, m) - blackbodySrgb(T, m)).cwiseAbs().maxCoeff(), 1e-6);
    }
    double errCoarse = 0.0, errFine = 0.0;
    for (double T = 1003.7; T < 26000.0; T += 97.3) {
        const Vec3 exact = blackbodySrgb(T, ToneMap::ColourOnly);
        errCoarse = std::max(errCoarse, (coarse.lookup(T, ToneMap::ColourOnly) - exact).cwiseAbs().maxCoeff());
        errFine = std::max(errFine, (fine.lookup(T, ToneMap::ColourOnly) - exact).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(errFine, 0.2 * errCoarse);
    EXPECT_LT(errFine, 2e-3);
    EXPECT_EQ(fine.texels(ToneMap::ColourOnly).size(), 3u * 1024u);
    // Clamped outside the range.
    EXPECT_LT((fine.lookup(100.0, ToneMap::ColourOnly) - fine.lookup(1000.0, ToneMap::ColourOnly)).norm(), 1e-12);
}

// The table every renderer shares, against the integral it replaces (Planck x CIE 1931 -> sRGB,
// blackbodySrgb): within one 8-bit level of the display value in every channel, both tone maps,
// from 1000 K to 10^6 K (log-spaced temperatures between the nodes, where linear interpolation
// errs most). Beyond the table's ends the lookup holds the end colours.
TEST(BlackbodyTable, StandardTableIsWithinOneLevelOfTheIntegral) {
    const auto table = standardBlackbodyTable();
    EXPECT_EQ(table.get(), standardBlackbodyTable().get()) << "built once, shared";
    double worst[2] = {0, 0}, worstAt[2] = {0, 0};
    std::vector<double> temperatures;
    for (int k = 0; k <= 1500; ++k) temperatures.push_back(1000.0 * std::pow(1000.0, (k + 0.37) / 1500.0));
    // Densely where the blue channel leaves 0 (the gamut's edge): a kink, where interpolation errs most.
    for (double T = 1900; T < 1920; T += 0.02) temperatures.push_back(T);
    for (const double T : temperatures) {
        if (T > 1e6) continue;
        for (int m = 0; m < 2; ++m) {
            const ToneMap map = m == 0 ? ToneMap::ColourOnly : ToneMap::ReferenceLog;
            const double err = (table->lookup(T, map) - blackbodySrgb(T, map)).cwiseAbs().maxCoeff();
            if (err > worst[m]) worst[m] = err, worstAt[m] = T;
        }
    }
    std::printf(
        "standard table: worst |lookup - integral| %.2e (colour only, at %.0f K), %.2e (reference log, at "
        "%.0f K) in display sRGB\n",
        worst[0], worstAt[0], worst[1], worstAt[1]);
    EXPECT_LE(worst[0], 1.0 / 255);
    EXPECT_LE(worst[1], 1.0 / 255);
    EXPECT_LT((table->lookup(1e9, ToneMap::ColourOnly) - table->lookup(kStandardTableMaxK, ToneMap::ColourOnly)).norm(),
              1e-12);
}
