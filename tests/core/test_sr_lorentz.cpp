// SPDX-License-Identifier: BSD-3-Clause
// Lorentz boosts and velocity addition against textbook formulas (core/sr/lorentz;
// docs/PHYSICS.md section 6, seed 003 sect. 3).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "core/colour/planck.hpp"
#include "core/sr/doppler.hpp"
#include "core/sr/lorentz.hpp"
#include "tests/common/random_velocity.hpp"

// lc::sr::boost qualified: a unity batch that includes Boost makes the bare name ambiguous.
using namespace lc;
using namespace lc::sr;

using lc::test::randomBeta;

TEST(SrLorentz, BoostPreservesTheMinkowskiMetric) {
    std::mt19937 rng(1);
    const Mat4 eta = minkowskiMetric();
    for (int i = 0; i < 50; ++i) {
        const Vec3 beta = randomBeta(rng, 0.999);
        const Mat4 L = sr::boost(beta);
        EXPECT_LT((L.transpose() * eta * L - eta).cwiseAbs().maxCoeff(), 1e-9 * L.cwiseAbs().maxCoeff());
        EXPECT_LT((L * sr::boost(-beta) - Mat4::Identity()).cwiseAbs().maxCoeff(), 1e-9 * L.squaredNorm());
        EXPECT_LT((inverseBoost(beta) - L.inverse()).cwiseAbs().maxCoeff(), 1e-8 * L.squaredNorm());
        EXPECT_NEAR(L.determinant(), 1.0, 1e-8);
        EXPECT_GT(L(0, 0), 0.0);  // orthochronous
    }
}

TEST(SrLorentz, BoostMovesTheRestFrameOrigin) {
    // The origin of S' (x' = 0) moves with velocity beta in S, its clock dilated by gamma.
    const Vec3 beta(0.3, -0.4, 0.5);
    const Vec4 x = sr::boost(beta) * Vec4(2.0, 0.0, 0.0, 0.0);
    const double gamma = 1.0 / std::sqrt(1.0 - 0.5);
    EXPECT_NEAR(x[0], 2.0 * gamma, 1e-12);
    EXPECT_LT((x.tail<3>() - beta * x[0]).norm(), 1e-12);
    EXPECT_NEAR(lorentzGamma(beta), gamma, 1e-14);
    EXPECT_THROW(sr::boost(Vec3(1.0, 0.0, 0.0)), std::invalid_argument);
}

TEST(SrLorentz, CollinearCompositionAddsRapidities) {
    const Vec3 dir = Vec3(1.0, 2.0, -2.0).normalized();
    const double b1 = 0.6, b2 = 0.7;
    const double b12 = (b1 + b2) / (1.0 + b1 * b2);  // textbook velocity addition
    EXPECT_NEAR(std::atanh(b12), std::atanh(b1) + std::atanh(b2), 1e-12);
    const Mat4 product = composeBoosts(b1 * dir, b2 * dir);
    EXPECT_LT((product - sr::boost(b12 * dir)).cwiseAbs().maxCoeff(), 1e-12 * product.cwiseAbs().maxCoeff());
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
    const Mat4 R = sr::boost(-w) * product;
    EXPECT_NEAR(R(0, 0), 1.0, 1e-12);
    EXPECT_LT((R.block<3, 1>(1, 0).norm() + R.block<1, 3>(0, 1).norm()), 1e-12);
    const Eigen::Matrix3d rot = R.block<3, 3>(1, 1);
    EXPECT_LT((rot.transpose() * rot - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_GT(std::acos(std::min(1.0, (rot.trace() - 1.0) / 2.0)), 1e-3);  // a genuine rotation
}
