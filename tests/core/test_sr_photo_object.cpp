// SPDX-License-Identifier: BSD-3-Clause
// Photo-objects (seed 003 eq. 5-8) against hand-derived closed forms in the observer frame,
// and the Penrose-Terrell circular outline of a moving sphere.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>

#include "core/sr/mesh.hpp"
#include "core/sr/photo_object.hpp"

using namespace lc;
using namespace lc::sr;

namespace {

// Independent oracle, worked in S only: a point at rest in S' (moving with speed beta along
// axis k, origin at a when t = 0) is at X(t) = a + x'_perp + (x'_k / gamma) e_k + beta t e_k
// (length contraction). Light reaching (t_o, x_o) left at t_e < t_o with
// t_o - t_e = |X(t_e) - x_o|, i.e. (1 - b^2) t^2 - 2 (t_o + b P_k) t + (t_o^2 - |P|^2) = 0
// with P = X(0) - x_o; the past light cone is the smaller root.
Vec4 handEmission(const Vec3& xRest, int k, double beta, const Vec3& a, const Vec4& obs) {
    const double gamma = 1.0 / std::sqrt(1.0 - beta * beta);
    Vec3 X0 = a + xRest;
    X0[k] = a[k] + xRest[k] / gamma;
    const Vec3 P = X0 - obs.tail<3>();
    const double to = obs[0];
    const double A = 1.0 - beta * beta, B = to + beta * P[k], C = to * to - P.squaredNorm();
    const double t = (B - std::sqrt(B * B - A * C)) / A;
    Vec3 X = X0;
    X[k] += beta * t;
    return Vec4(t, X.x(), X.y(), X.z());
}

// Angular spread (max - min) of the angular radius of the outline of a set of directions
// about the axis of the circle fitted to that outline.
double outlineSpread(const std::vector<Vec3>& points, const Vec3& eye) {
    std::vector<Vec3> dirs;
    Vec3 c0 = Vec3::Zero();
    for (const Vec3& p : points) {
        dirs.push_back((p - eye).normalized());
        c0 += dirs.back();
    }
    c0.normalize();
    const Vec3 e1 = c0.unitOrthogonal(), e2 = c0.cross(e1);
    const int bins = 360;
    std::vector<double> best(bins, -1.0);
    std::vector<Vec3> outline(bins);
    for (const Vec3& d : dirs) {
        const double rho = std::acos(std::clamp(d.dot(c0), -1.0, 1.0));
        const double psi = std::atan2(d.dot(e2), d.dot(e1));
        const int b = std::min(bins - 1, static_cast<int>((psi + kPi) / (2 * kPi) * bins));
        if (rho > best[b]) best[b] = rho, outline[b] = d;
    }
    // Points of a circle on the unit sphere lie in a plane n.d = h: least-squares plane.
    Vec3 mean = Vec3::Zero();
    for (const Vec3& d : outline) mean += d;
    mean /= bins;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Vec3& d : outline) cov += (d - mean) * (d - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    Vec3 n = es.eigenvectors().col(0);
    if (n.dot(c0) < 0) n = -n;
    double lo = 10.0, hi = -10.0;
    for (const Vec3& d : outline) {
        const double r = std::acos(std::clamp(n.dot(d), -1.0, 1.0));
        lo = std::min(lo, r), hi = std::max(hi, r);
    }
    return hi - lo;
}

std::vector<Vec3> sampleSphere(double radius, int nTheta, int nPhi) {
    std::vector<Vec3> pts;
    pts.reserve(static_cast<size_t>(nTheta) * nPhi);
    for (int i = 0; i < nTheta; ++i) {
        const double th = kPi * (i + 0.5) / nTheta;
        for (int j = 0; j < nPhi; ++j) {
            const double ph = 2 * kPi * j / nPhi;
            pts.emplace_back(radius * std::sin(th) * std::cos(ph), radius * std::sin(th) * std::sin(ph),
                             radius * std::cos(th));
        }
    }
    return pts;
}

}  // namespace

TEST(SrPhotoObject, PointAtRestWithTheObserverIsSeenWhereItIs) {
    const MovingFrame still(Vec3::Zero(), Vec3(1.0, -2.0, 3.0));
    const Vec4 obs(7.0, 0.5, 0.5, -1.0);
    const Vec3 x(0.3, 4.0, -2.0);
    const Vec4 e = emissionEvent(still, x, obs);
    EXPECT_LT((e.tail<3>() - (x + still.origin())).norm(), 1e-13);
    EXPECT_NEAR(e[0], obs[0] - (x + still.origin() - obs.tail<3>()).norm(), 1e-13);
}

TEST(SrPhotoObject, EmissionIsOnThePastLightConeAndTheWorldline) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 50; ++i) {
        Vec3 beta(u(rng), u(rng), u(rng));
        beta *= 0.97 * std::abs(u(rng)) / std::max(1.0, beta.norm());
        const MovingFrame f(beta, Vec3(u(rng), u(rng), u(rng)) * 5);
        const Vec4 obs(u(rng) * 10, u(rng) * 5, u(rng) * 5, u(rng) * 5);
        const Vec3 x(u(rng), u(rng), u(rng));
        const Vec4 e = emissionEvent(f, x, obs);
        const Vec4 sep = obs - e;
        EXPECT_GT(sep[0], 0.0);
        EXPECT_NEAR(sep[0], sep.tail<3>().norm(), 1e-10 * (1 + sep[0]));
        // On the worldline: e = origin event of the point + proper time along gamma (1, beta).
        const Vec4 start = f.eventToObserver(Vec4(0.0, x.x(), x.y(), x.z()));
        const Vec4 along = e - start;
        EXPECT_LT((along.tail<3>() - beta * along[0]).norm(), 1e-10 * (1 + std::abs(along[0])));
    }
}

TEST(SrPhotoObject, CubeAtNinetyFivePercentMatchesHandFormula) {
    const TriMesh cube = makeCube(1.0, 8);
    // Motion along x past an observer at the origin at t = 0 (the brief's construction)...
    {
        const double beta = 0.95;
        const Vec3 a(-1.0, 3.0, 0.5);
        const MovingFrame f(Vec3(beta, 0, 0), a);
        const Vec4 obs(0.0, 0.0, 0.0, 0.0);
        for (const Vec3& x : cube.positions) {
            const Vec4 hand = handEmission(x, 0, beta, a, obs);
            EXPECT_NEAR(hand[0], -(hand.tail<3>() - obs.tail<3>()).norm(), 1e-12);  // t_e = -|x(t_e) - x_obs|
            EXPECT_LT((emissionEvent(f, x, obs) - hand).norm(), 1e-11);
        }
    }
    // ...and the seed's Fig. 4 set-up: beta = (0, 0.95, 0), x_obs = (2, 5, 0.2), c t_obs in
    // {4.4, 5.12, 5.66}, cube of edge 1 centred at the origin of S'.
    for (double tObs : {4.4, 5.12, 5.66}) {
        const MovingFrame f(Vec3(0, 0.95, 0), Vec3::Zero());
        const Vec4 obs(tObs, 2.0, 5.0, 0.2);
        const std::vector<Vec3> app = apparentPositions(f, cube.positions, obs);
        for (size_t i = 0; i < cube.positions.size(); ++i)
            EXPECT_LT((app[i] - handEmission(cube.positions[i], 1, 0.95, Vec3::Zero(), obs).tail<3>()).norm(), 1e-11);
    }
}

TEST(SrPhotoObject, PenroseTerrellSphereOutlineIsACircle) {
    const std::vector<Vec3> sphere = sampleSphere(1.0, 1200, 2400);
    const MovingFrame f(Vec3(0.9, 0, 0), Vec3::Zero());
    for (const Vec4& obs : {Vec4(0.0, 0.0, -4.0, 0.0), Vec4(3.0, 1.0, -3.0, 0.5), Vec4(-2.0, 2.0, 3.5, -1.0)}) {
        const std::vector<Vec3> app = apparentPositions(f, sphere, obs);
        // Control: the "measured" length-contracted ellipsoid (simultaneous in S at t_obs) is
        // visibly not circular, so the check above can fail.
        std::vector<Vec3> measured;
        for (const Vec3& x : sphere) measured.emplace_back(x.x() / f.gamma() + 0.9 * obs[0], x.y(), x.z());
        const double spread = outlineSpread(app, obs.tail<3>()), control = outlineSpread(measured, obs.tail<3>());
        EXPECT_LT(spread, 1e-3) << obs.transpose();
        EXPECT_GT(control, 1e-2) << obs.transpose();
        std::printf("  outline spread: apparent %.2e rad, length-contracted control %.2e rad\n", spread, control);
    }
}
