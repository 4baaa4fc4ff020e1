// Lorentz boosts, velocity addition, Doppler factor, aberration and searchlight against
// textbook formulas (docs/PHYSICS.md section 6, seed 003 sect. 3).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "core/colour/planck.hpp"
#include "core/sr/doppler.hpp"
#include "core/sr/lorentz.hpp"

using namespace lc;
using namespace lc::sr;

namespace {
Vec3 randomBeta(std::mt19937& rng, double maxSpeed) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec3 v;
    do v = Vec3(u(rng), u(rng), u(rng)); while (v.norm() > 1.0 || v.norm() < 1e-3);
    return v * maxSpeed;
}
}  // namespace

TEST(SrLorentz, BoostPreservesTheMinkowskiMetric) {
    std::mt19937 rng(1);
    const Mat4 eta = minkowskiMetric();
    for (int i = 0; i < 50; ++i) {
        const Vec3 beta = randomBeta(rng, 0.999);
        const Mat4 L = boost(beta);
        EXPECT_LT((L.transpose() * eta * L - eta).cwiseAbs().maxCoeff(), 1e-9 * L.cwiseAbs().maxCoeff());
        EXPECT_LT((L * boost(-beta) - Mat4::Identity()).cwiseAbs().maxCoeff(), 1e-9 * L.squaredNorm());
        EXPECT_LT((inverseBoost(beta) - L.inverse()).cwiseAbs().maxCoeff(), 1e-8 * L.squaredNorm());
        EXPECT_NEAR(L.determinant(), 1.0, 1e-8);
        EXPECT_GT(L(0, 0), 0.0);  // orthochronous
    }
}

TEST(SrLorentz, BoostMovesTheRestFrameOrigin) {
    // The origin of S' (x' = 0) moves with velocity beta in S, its clock dilated by gamma.
    const Vec3 beta(0.3, -0.4, 0.5);
    const Vec4 x = boost(beta) * Vec4(2.0, 0.0, 0.0, 0.0);
    const double gamma = 1.0 / std::sqrt(1.0 - 0.5);
    EXPECT_NEAR(x[0], 2.0 * gamma, 1e-12);
    EXPECT_LT((x.tail<3>() - beta * x[0]).norm(), 1e-12);
    EXPECT_NEAR(lorentzGamma(beta), gamma, 1e-14);
    EXPECT_THROW(boost(Vec3(1.0, 0.0, 0.0)), std::invalid_argument);
}

TEST(SrLorentz, CollinearCompositionAddsRapidities) {
    const Vec3 dir = Vec3(1.0, 2.0, -2.0).normalized();
    const double b1 = 0.6, b2 = 0.7;
    const double b12 = (b1 + b2) / (1.0 + b1 * b2);  // textbook velocity addition
    EXPECT_NEAR(std::atanh(b12), std::atanh(b1) + std::atanh(b2), 1e-12);
    const Mat4 product = composeBoosts(b1 * dir, b2 * dir);
    EXPECT_LT((product - boost(b12 * dir)).cwiseAbs().maxCoeff(), 1e-12 * product.cwiseAbs().maxCoeff());
    EXPECT_LT((addVelocities(b1 * dir, b2 * dir) - b12 * dir).norm(), 1e-14);
}

TEST(SrLorentz, PerpendicularVelocityAdditionAndThomasRotation) {
    // u' along y in S', S' moving along x with v: w = (v, u' / gamma_v, 0) (time dilation of the
    // transverse motion).
    const double v = 0.8, u = 0.5;
    const double gv = 1.0 / std::sqrt(1.0 - v * v);
    const Vec3 w = addVelocities(Vec3(v, 0, 0), Vec3(0, u, 0));
    EXPECT_LT((w - Vec3(v, u / gv, 0.0)).norm(), 1e-14);
    // Non-collinear boosts compose to a boost times a rotation (Thomas-Wigner), not a boost.
    const Mat4 product = composeBoosts(Vec3(v, 0, 0), Vec3(0, u, 0));
    const Mat4 R = boost(-w) * product;
    EXPECT_NEAR(R(0, 0), 1.0, 1e-12);
    EXPECT_LT((R.block<3, 1>(1, 0).norm() + R.block<1, 3>(0, 1).norm()), 1e-12);
    const Eigen::Matrix3d rot = R.block<3, 3>(1, 1);
    EXPECT_LT((rot.transpose() * rot - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_GT(std::acos(std::min(1.0, (rot.trace() - 1.0) / 2.0)), 1e-3);  // a genuine rotation
}

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
        const Vec4 k = boost(beta) * Vec4(1.0, kRest.x(), kRest.y(), kRest.z());
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
        const Vec4 kRest = boost(Vec3(-beta, 0, 0)) * k;
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
    const Vec3 b(-beta, 0, 0);                 // mirror moves towards -x, light comes from -x
    const Vec3 vIn(1, 0, 0), vOut(-1, 0, 0);
    EXPECT_NEAR(reflectionFrequencyRatio(b, vIn, vOut), 1.3 / 0.7, 1e-14);
    // Same as the product of the two one-way Doppler factors.
    // Collinear, so in the mirror's frame the lamp approaches with -b along vIn.
    const double toMirror = dopplerFactor(-b, vIn);
    const double fromMirror = dopplerFactor(b, vOut);
    EXPECT_NEAR(reflectionFrequencyRatio(b, vIn, vOut), toMirror * fromMirror, 1e-12);
}
