// SPDX-License-Identifier: BSD-3-Clause
// Every image of a point: the worked example of docs/PHYSICS.md section 3 (literature-style reference values), landing
// of each image on its point through the forward closed form and through numeric integration,
// and image counts against a brute-force scan of rays that uses only the forward closed form.
#include "core/godel/images.hpp"
#include "core/spacetime/frame.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/metrics/godel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace lc;
using namespace lc::godel;

namespace {

// Where the image's ray is after lambda, in the solver's chart.
Vec4 landing(const Image& im, double a, double tObs = 0) { return im.ray(a, tObs).cartesian(im.lambda); }

void expectLands(const ImageSet& s, const Vec3& p, double a, double tol = 1e-10) {
    for (const Image& im : s.images) {
        const Vec4 x = landing(im, a);
        EXPECT_LT((x.segment<3>(1) - p).norm(), tol)
            << "winding " << im.winding << " " << branchName(im.branch) << " lands at " << x.transpose();
        EXPECT_NEAR(x(0), im.emissionTime, 1e-9 * std::max(1.0, std::abs(x(0))));
        EXPECT_NEAR(im.direction.norm(), 1.0, 1e-14);
        EXPECT_NEAR(im.direction(2), im.k3, 1e-14);
        EXPECT_NEAR(std::cos(im.psi), im.k3, 1e-14);
    }
}

// Brute force: for beta on a fine grid, find by bisection where the forward closed-form ray
// crosses r = r_p (crossing j = 0,1,2,... along the ray), and count sign changes of
// z(crossing j) - |z_p| along beta. The count equals the number of images with winding <= N.
int bruteForceCount(double a, double rp, double zp, int N) {
    const double q = rp / (2 * a);
    const double k3max = std::sqrt((1 - q * q) / (1 + q * q));
    const int M = 3000;
    std::vector<std::vector<double>> zc(2 * N + 2);
    for (int i = 1; i < M; ++i) {
        // Cubic clustering at k3max, where the grazing (fold) roots sit very close together.
        const double k3 = k3max * (1 - std::pow(1 - double(i) / M, 3));
        const OriginGeodesic g = OriginGeodesic::nullFromK3(a, k3, 0.0, -1);
        const double quarter = kPi / 2 / g.omega();
        for (int j = 0; j < 2 * N + 2; ++j) {
            // Crossing j: on the way out (j even) or back (j odd) of loop j/2.
            double lo = (2 * (j / 2) + (j % 2)) * quarter;
            double hi = lo + quarter;
            auto f = [&](double l) { return std::hypot(g.cartesian(l)(1), g.cartesian(l)(2)) - rp; };
            double flo = f(lo), fhi = f(hi);
            if ((flo > 0) == (fhi > 0)) {
                zc[j].push_back(NAN);
                continue;
            }
            for (int it = 0; it < 80; ++it) {
                const double mid = 0.5 * (lo + hi), fm = f(mid);
                if ((fm > 0) == (flo > 0)) {
                    lo = mid;
                    flo = fm;
                } else {
                    hi = mid;
                }
            }
            zc[j].push_back(k3 * 0.5 * (lo + hi));
        }
    }
    int count = 0;
    for (const auto& v : zc)
        for (std::size_t i = 0; i + 1 < v.size(); ++i)
            if (std::isfinite(v[i]) && std::isfinite(v[i + 1]) &&
                ((v[i] - std::abs(zp)) > 0) != ((v[i + 1] - std::abs(zp)) > 0))
                ++count;
    return count;
}

}  // namespace

TEST(GodelImages, WorkedExampleOfPhysicsMd) {
    const ImageSolver solver(1.0);
    ImageOptions opt;
    opt.maxWinding = 0;
    const ImageSet s = solver.solveCylindrical(1.0, 0.7, 0.3, opt);
    ASSERT_EQ(s.status, ImageStatus::Ok);
    ASSERT_EQ(s.images.size(), 2u);
    const Image& o = s.images[0];
    const Image& i = s.images[1];
    EXPECT_EQ(o.branch, Branch::Outbound);
    EXPECT_EQ(i.branch, Branch::Inbound);
    EXPECT_NEAR(o.psi, 1.294019, 1e-6);
    EXPECT_NEAR(o.phi0, 1.417467, 1e-6);
    EXPECT_NEAR(o.lambda, 1.097866, 1e-6);
    EXPECT_NEAR(o.emissionTime, -0.931438, 1e-6);
    EXPECT_NEAR(i.psi, 1.513333, 1e-6);
    EXPECT_NEAR(i.phi0, -3.127663, 1e-6);
    EXPECT_NEAR(i.lambda, 5.223563, 1e-6);
    EXPECT_NEAR(i.emissionTime, -1.721704, 1e-6);
    EXPECT_EQ(o.frequencyRatio, 1.0);
    expectLands(s, Vec3(std::cos(0.7), std::sin(0.7), 0.3), 1.0);
}

namespace {
// The numeric tracer (dopri5 at 1e-13) from s0 over `affine`: where the ray is then.
Vec4 numericEnd(const GodelCartesian& st, const PhasePoint& s0, double affine) {
    TraceOptions to;
    to.absTol = to.relTol = 1e-13;
    to.maxAffine = affine;
    to.maxSteps = 10000000;
    const TraceResult r = traceGeodesic(st, s0, to);
    EXPECT_EQ(r.reason, StopReason::MaxAffine);
    return r.end.x;
}
}  // namespace

TEST(GodelImages, ImagesLandThroughNumericIntegration) {
    // Independent of the closed form: start the numeric tracer with the image's direction.
    const double a = 1.0;
    const GodelCartesian st(a);
    const ImageSolver solver(a);
    const Vec3 p(0.4, -0.9, 0.8);
    ImageOptions opt;
    opt.maxWinding = 2;
    const ImageSet s = solver.solve(p, opt);
    ASSERT_GE(s.images.size(), 4u);
    for (const Image& im : s.images) {
        PhasePoint s0;  // at the origin g = diag(1,-1,-1,-1): p = (k0, -direction)
        s0.p = Vec4(-1, -im.direction(0), -im.direction(1), -im.direction(2));
        const Vec4 end = numericEnd(st, s0, im.lambda);
        EXPECT_LT((end.segment<3>(1) - p).norm(), 1e-9) << im.winding << branchName(im.branch);
        EXPECT_NEAR(end(0), im.emissionTime, 1e-9);
    }
}

TEST(GodelImages, CountsMatchBruteForceScan) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(0, 1);
    const double a = 1.0;
    const ImageSolver solver(a);
    const int N = 2;
    for (int k = 0; k < 10; ++k) {
        const double rp = 2 * a * (0.05 + 0.9 * u(rng));
        const double zp = (u(rng) - 0.5) * 16;
        ImageOptions opt;
        opt.maxWinding = N;
        const ImageSet s = solver.solveCylindrical(rp, 6 * u(rng), zp, opt);
        EXPECT_EQ(int(s.images.size()), bruteForceCount(a, rp, zp, N)) << "r=" << rp << " z=" << zp;
    }
}

TEST(GodelImages, BetweenGrazingHeightAndFoldTwoWayBackRoots) {
    // Z* < |z| <= Zpk: the inbound equation of docs/PHYSICS.md section 3 has two roots and the outbound none. The
    // solver reports them as the two branches (sides of the fold); brute force agrees on 2.
    const double a = 1.0, rp = 1.0;
    const double q = rp / (2 * a), k3max = std::sqrt((1 - q * q) / (1 + q * q));
    const double Zstar = 2 * a * k3max / std::sqrt(1 + k3max * k3max) * (kPi / 2);
    const double z = Zstar * (1 + 1e-3);
    ImageOptions opt;
    opt.maxWinding = 0;
    const ImageSet s = ImageSolver(a).solveCylindrical(rp, 0.2, z, opt);
    ASSERT_EQ(s.images.size(), 2u);
    EXPECT_TRUE(s.images[0].pastTurningPoint);
    EXPECT_TRUE(s.images[1].pastTurningPoint);
    EXPECT_EQ(bruteForceCount(a, rp, z, 0), 2);
    expectLands(s, Vec3(rp * std::cos(0.2), rp * std::sin(0.2), z), a);
}

TEST(GodelImages, PointsLandForRandomPoints) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0, 1);
    for (double a : {1.0, 0.3, 5.0}) {
        const ImageSolver solver(a);
        for (int k = 0; k < 200; ++k) {
            const double rp = 2 * a * u(rng) * 0.999, ph = 7 * u(rng) - 3.5, zp = (u(rng) - 0.5) * 20 * a;
            ImageOptions opt;
            opt.maxWinding = 5;
            opt.k0 = k % 2 ? 1 : -1;
            opt.tObserver = 0.0;
            const Vec3 p(rp * std::cos(ph), rp * std::sin(ph), zp);
            const ImageSet s = solver.solve(p, opt);
            ASSERT_EQ(s.status, ImageStatus::Ok);
            expectLands(s, p, a, 1e-10 * std::max(1.0, a));
            for (std::size_t i = 1; i < s.images.size(); ++i) EXPECT_LE(s.images[i - 1].lambda, s.images[i].lambda);
            // On one branch, higher windings are deeper and older (past) / later (future).
            for (const Image& x : s.images)
                for (const Image& y : s.images)
                    if (x.branch == y.branch && y.winding == x.winding + 1) {
                        EXPECT_LT(x.lambda, y.lambda);
                        EXPECT_GT(opt.k0 * (y.emissionTime - x.emissionTime), 0);
                    }
            // Both branches of a winding come together.
            for (const Image& im : s.images) {
                int mates = 0;
                for (const Image& o : s.images) mates += o.winding == im.winding;
                EXPECT_EQ(mates, 2);
            }
        }
    }
}

TEST(GodelImages, PlaneZeroHasExactlyTwoDirections) {
    const double a = 1.0;
    const ImageSolver solver(a);
    ImageOptions opt;
    opt.maxWinding = 6;
    const Vec3 p(0.3, 1.2, 0.0);
    const ImageSet s = solver.solve(p, opt);
    ASSERT_EQ(s.images.size(), 14u);
    expectLands(s, p, a);
    for (const Image& im : s.images) {
        EXPECT_EQ(im.k3, 0.0);
        const Image& first = im.branch == Branch::Outbound ? s.images[0] : s.images[1];
        EXPECT_LT((im.direction - first.direction).norm(), 1e-12);  // windings repeat the direction
        EXPECT_LE(im.emissionTime, first.emissionTime);
    }
    EXPECT_NE((s.images[0].direction - s.images[1].direction).norm(), 0.0);
    // h = arcsin q: lambda = 2a (h + n pi) and 2a (pi - h + n pi).
    const double h = std::asin(p.head<2>().norm() / (2 * a));
    EXPECT_NEAR(s.images[0].lambda, 2 * a * h, 1e-13);
    EXPECT_NEAR(s.images[1].lambda, 2 * a * (kPi - h), 1e-13);
    EXPECT_NEAR(s.images[13].lambda, 2 * a * (kPi - h + 6 * kPi), 1e-12);
}

TEST(GodelImages, NearThePlaneIsContinuous) {
    const double a = 1.0;
    const ImageSolver solver(a);
    ImageOptions opt;
    opt.maxWinding = 3;
    const ImageSet s0 = solver.solve(Vec3(0.7, 0.2, 0.0), opt);
    for (double z : {1e-14, -1e-14, 1e-300, -1e-9}) {
        const Vec3 p(0.7, 0.2, z);
        const ImageSet s = solver.solve(p, opt);
        ASSERT_EQ(s.images.size(), s0.images.size());
        expectLands(s, p, a);
        for (std::size_t i = 0; i < s.images.size(); ++i) {
            EXPECT_LT((s.images[i].direction - s0.images[i].direction).norm(), 1e-8);
            EXPECT_NEAR(s.images[i].lambda, s0.images[i].lambda, 1e-8);
            EXPECT_EQ(s.images[i].k3 >= 0, z >= 0);
        }
    }
}

TEST(GodelImages, LargeHeightSkipsLowWindings) {
    const double a = 1.0;
    const ImageSolver solver(a);
    ImageOptions opt;
    opt.maxWinding = 10;
    const Vec3 p(0.5, 0.5, 30.0);
    const ImageSet s = solver.solve(p, opt);
    ASSERT_FALSE(s.images.empty());
    expectLands(s, p, a);
    // |z| <= sqrt2 a (n+1) pi is needed (the ray climbs at most that much per winding).
    const int nmin = s.images.front().winding;
    EXPECT_GT(nmin, 0);
    EXPECT_GT(30.0, std::sqrt(2.0) * a * nmin * kPi * 0.9);
    EXPECT_EQ(int(s.images.size()), 2 * (10 - nmin + 1));
    EXPECT_EQ(int(s.images.size()), bruteForceCount(a, p.head<2>().norm(), 30.0, 10));
    opt.maxWinding = 2;
    EXPECT_TRUE(solver.solve(p, opt).images.empty());
    EXPECT_EQ(solver.solve(p, opt).status, ImageStatus::Ok);
}

TEST(GodelImages, FiftyWindingsGiveTwoImagesEachThatLandOnThePoint) {
    const double a = 1.0;
    const ImageSolver solver(a);
    ImageOptions opt;
    opt.maxWinding = 50;
    const Vec3 p(-0.8, 0.9, 2.5);
    const ImageSet s = solver.solve(p, opt);
    const int nmin = s.images.front().winding;
    EXPECT_LE(nmin, 1);
    EXPECT_EQ(int(s.images.size()), 2 * (51 - nmin));
    expectLands(s, p, a, 1e-9);
    EXPECT_EQ(s.images.back().winding, 50);
}

TEST(GodelImages, PointsJustInsideTheHorizonHaveFiniteImagesThatLand) {
    const double a = 1.0;
    const ImageSolver solver(a);
    ImageOptions opt;
    opt.maxWinding = 4;
    for (double eps : {1e-6, 1e-9, 1e-12}) {
        for (double z : {0.0, 0.01, 1.0}) {
            const double rp = 2 * a * (1 - eps);
            const Vec3 p(rp * std::cos(1.0), rp * std::sin(1.0), z);
            const ImageSet s = solver.solve(p, opt);
            ASSERT_EQ(s.status, ImageStatus::Ok);
            for (const Image& im : s.images) EXPECT_TRUE(std::isfinite(im.lambda) && im.direction.allFinite());
            expectLands(s, p, a, 1e-9);
            // Only nearly horizontal rays reach so far out.
            for (const Image& im : s.images) EXPECT_LT(std::abs(im.k3), 2e-3 + 10 * std::sqrt(eps));
        }
    }
}

TEST(GodelImages, BeyondTheHorizonIsReportedNotThrown) {
    const double a = 1.0;
    const ImageSolver solver(a);
    for (double r : {2.0, 2.0 + 1e-15, 3.0, 1e6}) {
        ImageSet s;
        EXPECT_NO_THROW(s = solver.solveCylindrical(r, 0.3, 0.5));
        EXPECT_EQ(s.status, ImageStatus::BeyondHorizon);
        EXPECT_TRUE(s.images.empty());
        EXPECT_FALSE(s.message.empty());
    }
    EXPECT_EQ(solver.solve(Vec3(NAN, 0, 0)).status, ImageStatus::InvalidInput);
}

TEST(GodelImages, AxisPointsHaveOneAxialRayAndRingsThatReturnToIt) {
    const double a = 1.0;
    const ImageSolver solver(a);
    ImageOptions opt;
    opt.maxWinding = 3;
    for (double z : {0.5, -2.0, 7.0}) {
        const Vec3 p(0, 0, z);
        const ImageSet s = solver.solve(p, opt);
        ASSERT_EQ(s.status, ImageStatus::Ok);
        int axialCount = 0;
        for (const Image& im : s.images) {
            if (!im.ring) {
                ++axialCount;
                EXPECT_NEAR(im.lambda, std::abs(z), 1e-14);
                EXPECT_NEAR(im.k3, z > 0 ? 1 : -1, 0);
                EXPECT_NEAR(im.emissionTime, -std::abs(z), 1e-14);  // flat along the axis
                EXPECT_EQ(im.winding, int(std::floor(std::abs(z) / (kSqrt2 * a * kPi))));
            } else {
                // The ring's rays return to the axis at height z after m half-periods.
                for (double ph : {0.0, 1.0, 4.0}) {
                    Image r = im;
                    r.phi0 = ph;
                    const Vec4 x = landing(r, a);
                    EXPECT_LT((x.segment<3>(1) - p).norm(), 1e-10);
                }
            }
        }
        EXPECT_EQ(axialCount, 1);
        // Nearby points: each image converges to the axis images (rings come in pairs).
        const Vec3 pn(1e-9, 0, z);
        const ImageSet sn = solver.solve(pn, opt);
        expectLands(sn, pn, a, 1e-10);
        for (const Image& im : sn.images) {
            double best = 1e9;
            for (const Image& ax : s.images) {
                const double d = ax.ring ? std::abs(im.psi - ax.psi) : (im.direction - ax.direction).norm();
                if (std::abs(im.lambda - ax.lambda) < 1e-6) best = std::min(best, d);
            }
            EXPECT_LT(best, 1e-6) << "near-axis image winding " << im.winding << " lambda " << im.lambda;
        }
    }
    // The observer's own position: only earlier copies, as horizontal rings at lambda = 2 pi a m.
    const ImageSet self = solver.solve(Vec3::Zero(), opt);
    ASSERT_EQ(self.images.size(), 4u);
    for (std::size_t m = 0; m < 4; ++m) {
        EXPECT_TRUE(self.images[m].ring);
        EXPECT_NEAR(self.images[m].lambda, 2 * kPi * a * (m + 1), 1e-12);
        EXPECT_NEAR(self.images[m].emissionTime, -2 * kPi * a * (kSqrt2 - 1) * (m + 1), 1e-12);
    }
}

TEST(GodelImages, PointsNearTheAxisAreSeenAlongPolarRays) {
    const double a = 1.0;
    const ImageSolver solver(a);
    ImageOptions opt;
    opt.maxWinding = 3;
    for (double rp : {1e-12, 1e-6}) {
        const Vec3 p(rp, 0.0, 1.0);
        const ImageSet s = solver.solve(p, opt);
        expectLands(s, p, a, 1e-10);
        bool polar = false;
        for (const Image& im : s.images) polar |= im.k3 > 1 - 1e-6;
        EXPECT_TRUE(polar);  // k3 -> 1: seen nearly straight up the axis
    }
}

TEST(GodelImages, MovedObserversRaysStartAtItAndEndOnThePoint) {
    const double a = 1.0;
    const Vec4 obs(3.0, 0.9, -0.4, 0.7);
    const ObserverView view(a, obs);
    const Vec3 wp(0.2, 0.5, -0.3);
    const ImageSet s = view.images(wp, 2);
    ASSERT_FALSE(s.images.empty());
    const GodelCartesian st(a);
    for (const Image& im : s.images) {
        // Ray in the observer chart, mapped back to the world; it starts at the observer event
        // and ends on the world point at the reported emission event.
        const OriginGeodesic g = im.ray(a);
        const Vec4 start = view.toWorld().apply(g.cartesian(0));
        const Vec4 end = view.toWorld().apply(g.cartesian(im.lambda));
        EXPECT_LT((start - obs).norm(), 1e-12);
        EXPECT_LT((end.segment<3>(1) - wp).norm(), 1e-10);
        EXPECT_NEAR(end(0), im.emissionTime, 1e-10);
        // And it is null in the world chart.
        const Vec4 k = view.toWorld().pushForward(g.cartesian(1.0), g.tangentCartesian(1.0));
        EXPECT_NEAR(k.dot(st.metric(view.toWorld().apply(g.cartesian(1.0))) * k), 0.0, 1e-12);
    }
    // An observer too far from the point: reported.
    const ObserverView far(a, Vec4(0, 2.5, 0, 0));
    EXPECT_EQ(far.images(Vec3(-0.5, 0, 0), 2).status, ImageStatus::BeyondHorizon);
}

// The direction a moved observer sees each image along, in its documented frame (the static
// observer's Gram-Schmidt frame of d/dx, d/dy, d/dz, docs/PHYSICS.md section 8: the camera's,
// what `lightcone images`, Python and the images table report): the numeric tracer, launched from
// the observer in the world chart along that frame direction (LocalFrame::pastNullMomentum, the
// camera's launch), reaches the point at the image's affine distance and emission time. Several
// observers off the axis and off the plane, points off the plane. ObserverView's chart is aligned
// with that frame (frameAxes the identity). Before, it was Isometry::movingToOrigin's, turned by up
// to 145.5 degrees for these observers, and `images` printed directions in it.
TEST(GodelImages, MovedObserverSeesEachImageAlongItsFrameDirection) {
    const double a = 1.0;
    const GodelCartesian st(a);
    const std::vector<std::pair<Vec4, Vec3>> cases{{Vec4(0, -0.3, 0.2, 0.0), Vec3(1.0, 0.0, 0.0)},
                                                   {Vec4(3.0, 0.9, -0.4, 0.7), Vec3(0.2, 0.5, -0.3)},
                                                   {Vec4(-1.0, 0.5, 0.6, -0.2), Vec3(-0.4, 1.1, 0.6)},
                                                   {Vec4(0, 1.2, 0.0, 0.0), Vec3(0.3, -0.2, 0.1)}};
    int checked = 0;
    for (const auto& [observer, point] : cases) {
        const ObserverView view(a, observer);
        const ImageSet set = view.images(point, 1);
        ASSERT_FALSE(set.images.empty());
        const LocalFrame frame = LocalFrame::staticObserver(st, observer);
        for (int i = 0; i < 3; ++i) EXPECT_LT((view.frameAxes()[i] - Vec3::Unit(i)).norm(), 1e-12);
        for (const Image& im : set.images) {
            const Vec3 d = view.inObserverFrame(im.direction);
            EXPECT_NEAR(d.norm(), 1.0, 1e-12);
            PhasePoint s0;
            s0.x = observer;
            s0.p = frame.pastNullMomentum(st, d);
            const Vec4 end = numericEnd(st, s0, im.lambda);
            EXPECT_LT((end.segment<3>(1) - point).norm(), 1e-8) << im.winding << branchName(im.branch);
            EXPECT_NEAR(end(0), im.emissionTime, 1e-8);
            ++checked;
        }
    }
    EXPECT_GE(checked, 8);
}

TEST(GodelImages, StaticWorldLineReproducesStaticImages) {
    const double a = 1.0;
    const Vec3 p(0.6, -0.3, 0.4);
    WorldLine w;
    w.position = [&](double tau) { return Vec4(tau, p(0), p(1), p(2)); };
    MovingImageOptions mo;
    mo.image.maxWinding = 1;
    mo.tauMin = -20;
    mo.tauMax = 1;
    const auto mv = imagesOfWorldLine(a, w, mo);
    ImageOptions opt;
    opt.maxWinding = 1;
    const ImageSet s = ImageSolver(a).solve(p, opt);
    ASSERT_EQ(mv.size(), s.images.size());
    for (std::size_t i = 0; i < mv.size(); ++i) {
        EXPECT_NEAR(mv[i].tau, s.images[i].emissionTime, 1e-10);
        EXPECT_NEAR(mv[i].image.frequencyRatio, 1.0, 1e-9);
        EXPECT_LT((mv[i].image.direction - s.images[i].direction).norm(), 1e-10);
    }
}

TEST(GodelImages, RecedingAlongTheAxisGivesSpecialRelativisticDoppler) {
    // On the axis the (t, z) plane is flat: an emitter receding at speed beta along +z is
    // redshifted by sqrt((1-beta)/(1+beta)) (independent oracle). Its world line, x = (gamma tau,
    // 0, 0, 1 + gamma beta tau), is a timelike geodesic (k3 = gamma beta, r_max = 0).
    const double a = 1.0, beta = 0.3, gamma = 1 / std::sqrt(1 - beta * beta);
    const FreeFall ff(OriginGeodesic::timelike(a, gamma, gamma * beta, 0.0, 0.0, 1.0), Isometry(a));
    MovingImageOptions mo;
    mo.image.maxWinding = 0;
    mo.tauMin = -5;
    mo.tauMax = 0.5;
    const auto mv = imagesOfWorldLine(a, ff.worldLine(), mo);
    int axial = 0;
    for (const auto& m : mv) {
        if (m.image.ring) continue;
        ++axial;
        EXPECT_NEAR(m.image.frequencyRatio, std::sqrt((1 - beta) / (1 + beta)), 1e-9);
        EXPECT_NEAR(m.image.event(3), 1 / (1 + beta), 1e-9);
        EXPECT_NEAR(m.image.emissionTime, -1 / (1 + beta), 1e-9);
    }
    EXPECT_EQ(axial, 1);
    // Without a velocity callable (finite differences of the position) the same.
    WorldLine w = ff.worldLine();
    w.velocity = nullptr;
    for (const auto& m : imagesOfWorldLine(a, w, mo))
        if (!m.image.ring) {
            EXPECT_NEAR(m.image.frequencyRatio, std::sqrt((1 - beta) / (1 + beta)), 1e-7);
        }
}

TEST(GodelImages, FreeFallingEmitterOnItsWorldLineAndRay) {
    const double a = 1.0;
    const GodelCartesian st(a);
    const FreeFall ff(OriginGeodesic::timelike(a, 1.2, 0.1, 0.4), Isometry::movingOriginTo(a, Vec4(-3, 0.5, 0.3, 0.2)));
    MovingImageOptions mo;
    mo.image.maxWinding = 1;
    mo.tauMin = -6;
    mo.tauMax = 3;
    const auto mv = imagesOfWorldLine(a, ff.worldLine(), mo);
    ASSERT_FALSE(mv.empty());
    for (const auto& m : mv) {
        const Vec4 x = ff.position(m.tau);
        const Vec4 y = m.image.ray(a).cartesian(m.image.lambda);
        EXPECT_LT((x - y).norm(), 1e-9);
        // Frequency ratio from independent pieces: numeric ray momentum and finite-difference velocity.
        PhasePoint s0;
        s0.p = Vec4(-1, -m.image.direction(0), -m.image.direction(1), -m.image.direction(2));
        TraceOptions to;
        to.absTol = to.relTol = 1e-13;
        to.maxAffine = m.image.lambda;
        const TraceResult r = traceGeodesic(st, s0, to);
        Vec4 u = (ff.position(m.tau + 1e-6) - ff.position(m.tau - 1e-6)) / 2e-6;
        u /= std::sqrt(u.dot(st.metric(x) * u));
        EXPECT_NEAR(m.image.frequencyRatio, -1.0 / r.end.p.dot(u), 1e-7);
        EXPECT_NE(m.image.frequencyRatio, 1.0);
    }
}
