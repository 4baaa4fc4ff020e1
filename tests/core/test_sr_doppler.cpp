// SPDX-License-Identifier: BSD-3-Clause
// Doppler factor, aberration and searchlight against textbook formulas (core/sr/doppler;
// docs/PHYSICS.md section 6, seed 003 sect. 3).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "core/colour/planck.hpp"
#include "core/sr/doppler.hpp"
#include "core/sr/lorentz.hpp"
#include "tests/common/random_velocity.hpp"

using namespace lc;
using namespace lc::sr;
using lc::test::randomBeta;

TEST(SrDoppler, SixThousandKelvinAtTwentyPercent) {
    // docs/PHYSICS.md section 6: 6000 sqrt(1.2 / 0.8) = 7348.47 K approaching, 4898.98 K receding.
    const Vec3 n(0.0, 0.0, 1.0);  // source -> observer
    const double Dapp = dopplerFactor(0.2 * n, n), Drec = dopplerFactor(-0.2 * n, n);
    EXPECT_NEAR(observedTemperature(6000.0, Dapp), 7348.47, 0.01);
    EXPECT_NEAR(observedTemperature(6000.0, Drec), 4898.98, 0.01);
    EXPECT_NEAR(Dapp, std::sqrt(1.5), 1e-14);
    // Transverse Doppler (n perpendicular to beta in S): pure time dilation, D = 1 / gamma.
    EXPECT_NEAR(dopplerFactor(Vec3(0.6, 0, 0), Vec3(0, 1, 0)), 0.8, 1e-14);
}

TEST(SrDoppler, AgreesWithTheTransformedWaveVector) {
    // A photon of unit frequency emitted in S' along k': its frequency in S is the time
    // component of Lambda(beta) (1, k') (seed eq. 3-4); D = omega / omega'.
    std::mt19937 rng(7);
    for (int i = 0; i < 40; ++i) {
        const Vec3 beta = randomBeta(rng, 0.95), kRest = randomBeta(rng, 1.0).normalized();
        const Vec4 k = sr::boost(beta) * Vec4(1.0, kRest.x(), kRest.y(), kRest.z());
        const Vec3 n = k.tail<3>() / k[0];
        EXPECT_NEAR(n.norm(), 1.0, 1e-12);
        EXPECT_NEAR(dopplerFactor(beta, n), k[0], 1e-9 * k[0]);
        EXPECT_LT((aberrateToObserver(beta, kRest) - n).norm(), 1e-12);
        EXPECT_LT((aberrateToRest(beta, n) - kRest).norm(), 1e-9);
    }
}

TEST(SrAberration, MatchesTheTextbookAngleFormula) {
    // cos(theta') = (cos(theta) - beta) / (1 - beta cos(theta)), theta measured from beta, for
    // the direction of a null vector of S expressed in S' (S' moving with beta along x).
    const double beta = 0.9;
    for (double theta = 0.05; theta < kPi; theta += 0.1) {
        const Vec4 k(1.0, std::cos(theta), std::sin(theta), 0.0);
        const Vec4 kRest = sr::boost(Vec3(-beta, 0, 0)) * k;
        EXPECT_NEAR(minkowskiDot(kRest, kRest), 0.0, 1e-12);
        const double cosRest = kRest[1] / kRest[0];
        EXPECT_NEAR(cosRest, (std::cos(theta) - beta) / (1.0 - beta * std::cos(theta)), 1e-12);
        EXPECT_NEAR(aberrateToRest(Vec3(beta, 0, 0), k.tail<3>()).x(), cosRest, 1e-12);
    }
}

TEST(SrSearchlight, PlanckStaysPlanckAtDopplerTemperature) {
    // L_lambda(lambda) = D^5 L'_lambda'(lambda' = D lambda) is exactly B(lambda, D T).
    for (double D : {0.4, 1.0 / std::sqrt(1.5), std::sqrt(1.5), 3.0}) {
        for (double lambdaNm : {300.0, 450.0, 550.0, 700.0, 2000.0}) {
            const double l = lambdaNm * 1e-9;
            const double shifted = searchlightSpectral(D) * colour::planckRadiance(D * l, 6000.0);
            EXPECT_NEAR(shifted / colour::planckRadiance(l, observedTemperature(6000.0, D)), 1.0, 1e-12);
        }
        // Bolometric: the integral over lambda scales as D^4 (Stefan-Boltzmann).
        auto integral = [](double T) {
            double s = 0.0;
            const double l0 = 1e-8, l1 = 1e-3;
            const int n = 100000;
            const double h = std::log(l1 / l0) / n;
            for (int i = 0; i <= n; ++i) {
                const double l = l0 * std::exp(i * h);
                s += (i == 0 || i == n ? 0.5 : 1.0) * colour::planckRadiance(l, T) * l;
            }
            return s * h;
        };
        EXPECT_NEAR(integral(D * 6000.0) / integral(6000.0), searchlightBolometric(D), 1e-4 * searchlightBolometric(D));
    }
}

TEST(SrDoppler, ReflectionOffAMovingMirror) {
    // Head-on retro-reflection off a mirror approaching at beta: ratio (1 + beta) / (1 - beta).
    const double beta = 0.3;
    const Vec3 b(-beta, 0, 0);  // mirror moves towards -x, light comes from -x
    const Vec3 vIn(1, 0, 0), vOut(-1, 0, 0);
    EXPECT_NEAR(reflectionFrequencyRatio(b, vIn, vOut), 1.3 / 0.7, 1e-14);
    // Same as the product of the two one-way Doppler factors.
    // Collinear, so in the mirror's frame the lamp approaches with -b along vIn.
    const double toMirror = dopplerFactor(-b, vIn);
    const double fromMirror = dopplerFactor(b, vOut);
    EXPECT_NEAR(reflectionFrequencyRatio(b, vIn, vOut), toMirror * fromMirror, 1e-12);
}
