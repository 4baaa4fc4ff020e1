// SPDX-License-Identifier: BSD-3-Clause
// Local ray tracing of moving triangles (seed 003 sect. 4): exact hits against an oracle that
// solves the light-cone / moving-plane intersection in the observer frame S, the photo-object
// route, polygon distortion, and conservativeness of the screen footprint.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>

#include "core/sr/doppler.hpp"
#include "core/sr/local_ray_tracing.hpp"
#include "core/sr/photo_object.hpp"
#include "tests/common/sr_camera.hpp"

using namespace lc;
using namespace lc::sr;

namespace {

// A rest triangle of random size and shape, moving at up to 0.99 c, and an observer event near it:
// the footprint tests' random cases.
struct RandomTriangle {
    RestTriangle tri;
    MovingFrame frame;
    Vec4 observer;
};
// A pinhole camera at the observer's place looking along forward.
ObserverCamera cameraAt(const Vec4& observer, const Vec3& forward, double fovYDeg, int width, int height) {
    ObserverCamera cam;
    cam.position = observer.tail<3>();
    cam.forward = forward;
    cam.up = forward.unitOrthogonal();
    cam.fovYDeg = fovYDeg;
    cam.width = width;
    cam.height = height;
    cam.fovXDeg = lc::test::squarePixelFovX(width, height, fovYDeg);
    return cam;
}

RandomTriangle randomTriangle(std::mt19937& rng, std::uniform_real_distribution<double>& u) {
    RandomTriangle r;
    const double size = 0.3 + 2.0 * std::abs(u(rng));
    for (int k = 0; k < 3; ++k) r.tri.p[k] = Vec3(u(rng), u(rng), u(rng)) * size, r.tri.n[k] = Vec3::UnitZ();
    Vec3 beta(u(rng), u(rng), u(rng));
    beta = beta.normalized() * 0.99 * std::abs(u(rng));
    r.frame = MovingFrame(beta, Vec3(u(rng), u(rng), u(rng)) * 2.0);
    r.observer = Vec4(u(rng) * 4.0, u(rng) * 4.0 + 5.0, u(rng) * 4.0, u(rng) * 4.0);
    return r;
}

// Oracle in S only. A rest point p of S' (velocity beta, origin a at t = 0) is at
// X(t) = a + p - (1 - 1/gamma)(p.bhat) bhat + beta t: the triangle translates rigidly with
// a fixed normal N. The viewing ray's light-cone line is x(s) = x_obs + s d at time
// t_obs - s, so N.(x(s) - X_0(t_obs - s)) = 0 is linear in s.
struct OracleHit {
    bool hit = false;
    double s = 0.0;  // apparent distance
    Vec3 bary = Vec3::Zero();
    double margin = -1.0;  // smallest barycentric (distance from an edge); -1 if no plane hit
};

OracleHit oracle(const RestTriangle& tri, const Vec3& beta, const Vec3& a, const Vec4& obs, const Vec3& d) {
    const double g = 1.0 / std::sqrt(1.0 - beta.squaredNorm());
    const Vec3 bh = beta.norm() > 0 ? Vec3(beta.normalized()) : Vec3::Zero();
    Vec3 X[3];
    for (int i = 0; i < 3; ++i) X[i] = a + tri.p[i] - (1.0 - 1.0 / g) * tri.p[i].dot(bh) * bh;
    const Vec3 N = (X[1] - X[0]).cross(X[2] - X[0]);
    const Vec3 xo = obs.tail<3>();
    OracleHit h;
    const double den = N.dot(d + beta);
    if (std::abs(den) < 1e-14) return h;
    h.s = N.dot(X[0] + beta * obs[0] - xo) / den;
    if (!(h.s > 0.0)) return h;  // plane crossed in the future: no emission
    // Where the hit point sits in the triangle's t = 0 position.
    const Vec3 q = xo + h.s * d - beta * (obs[0] - h.s);
    Eigen::Matrix<double, 3, 2> E;
    E << X[1] - X[0], X[2] - X[0];
    const Eigen::Vector2d uv = E.colPivHouseholderQr().solve(q - X[0]);
    h.bary = Vec3(1.0 - uv.sum(), uv.x(), uv.y());
    h.margin = h.bary.minCoeff();
    h.hit = h.margin >= 0.0;
    return h;
}

}  // namespace

TEST(SrLocalRayTracing, HitReproducesThePhotoObjectOfARestPoint) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.05, 1.0);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        RestTriangle tri;
        for (int k = 0; k < 3; ++k) tri.p[k] = Vec3(u(rng), u(rng), u(rng)) * 2.0, tri.n[k] = Vec3::UnitZ();
        Vec3 beta(u(rng), u(rng), u(rng));
        beta = beta.normalized() * 0.98 * std::abs(u(rng));
        const MovingFrame f(beta, Vec3(u(rng), u(rng), u(rng)) * 3.0);
        const Vec4 obs(u(rng) * 5.0, u(rng) * 6.0, u(rng) * 6.0, u(rng) * 6.0);
        Vec3 bary(w(rng), w(rng), w(rng));
        bary /= bary.sum();
        const Vec3 p = bary[0] * tri.p[0] + bary[1] * tri.p[1] + bary[2] * tri.p[2];
        const Vec4 e = emissionEvent(f, p, obs);
        const Vec3 toApparent = e.tail<3>() - obs.tail<3>();
        const auto hit = intersectLocal(tri, f, obs, toApparent.normalized());
        ASSERT_TRUE(hit.has_value()) << i;
        EXPECT_LT((hit->barycentric - bary).norm(), 1e-8);
        EXPECT_NEAR(hit->depth, toApparent.norm(), 1e-9 * (1 + toApparent.norm()));
        EXPECT_LT((hit->emission - e).norm(), 1e-8 * (1 + e.norm()));
        EXPECT_LT((hit->restPoint - p).norm(), 1e-9);
        EXPECT_NEAR(hit->doppler, dopplerFactor(beta, -toApparent.normalized()), 1e-9 * hit->doppler);
        ++checked;
    }
    EXPECT_EQ(checked, 200);
}

TEST(SrLocalRayTracing, LargeTriangleHitSetEqualsMovingPlaneOracle) {
    // A big triangle sweeping past at beta = 0.9 close to the observer: strongly curved edges.
    RestTriangle tri;
    tri.p = {Vec3(-6.0, -1.0, -3.0), Vec3(6.0, -1.5, -3.5), Vec3(0.0, 4.0, -2.5)};
    tri.n = {Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ()};
    const Vec3 beta(0.9, 0.0, 0.1);
    const Vec3 a(0.0, 0.0, -1.0);
    const MovingFrame f(beta, a);
    const Vec4 obs(0.0, 0.0, 0.0, 0.0);
    ObserverCamera cam;
    cam.forward = Vec3(0, 0, -1);
    cam.up = Vec3(0, 1, 0);
    cam.fovYDeg = 100.0;
    cam.width = 200;
    cam.height = 150;
    cam.fovXDeg = lc::test::squarePixelFovX(cam.width, cam.height, cam.fovYDeg);
    const auto flat = apparentTriangle(tri, f, obs);

    int hits = 0, mismatches = 0, ambiguous = 0, polygonDiffers = 0;
    double maxDepthErr = 0.0, maxBaryErr = 0.0;
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            const Vec3 d = cam.directionAt(x + 0.5, y + 0.5);
            const OracleHit o = oracle(tri, beta, a, obs, d);
            const auto h = intersectLocal(tri, f, obs, d);
            const bool polygon = intersectFlat(flat, obs.tail<3>(), d).has_value();
            if (polygon != o.hit) ++polygonDiffers;
            if (std::abs(o.margin) < 1e-9) {  // on an edge to rounding: either answer is right
                ++ambiguous;
                continue;
            }
            if (o.hit != h.has_value()) {
                ++mismatches;
                continue;
            }
            if (!o.hit) continue;
            ++hits;
            maxDepthErr = std::max(maxDepthErr, std::abs(h->depth - o.s) / o.s);
            maxBaryErr = std::max(maxBaryErr, (h->barycentric - o.bary).cwiseAbs().maxCoeff());
        }
    std::printf("  large triangle: %d hit pixels, %d mismatches, %d on-edge, polygon distortion differs on %d\n", hits,
                mismatches, ambiguous, polygonDiffers);
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(hits, 2000);
    EXPECT_LT(maxDepthErr, 1e-10);
    EXPECT_LT(maxBaryErr, 1e-9);
    EXPECT_GT(polygonDiffers, 100);  // straight apparent edges miss the curved ones
}

TEST(SrLocalRayTracing, FootprintCoversEveryHitPixel) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int trials = 0, fullScreen = 0, hitPixels = 0, outside = 0, outsideCorners = 0;
    for (int i = 0; i < 600; ++i) {
        const RandomTriangle random = randomTriangle(rng, u);
        const RestTriangle& tri = random.tri;
        const MovingFrame& f = random.frame;
        const Vec4& obs = random.observer;
        const Vec3 centroid = (tri.p[0] + tri.p[1] + tri.p[2]) / 3.0;
        const Vec3 towards = apparentPosition(f, centroid, obs) - obs.tail<3>() + 0.5 * Vec3(u(rng), u(rng), u(rng));
        const ObserverCamera cam = cameraAt(obs, towards, 70.0, 128, 96);
        // No safety margin: the tangent construction alone must cover every pixel centre.
        const ApparentFootprint fp = apparentFootprint(tri, f, obs, cam, 0.0);
        ++trials;
        fullScreen += fp.fullScreen;
        // Control: the box of the apparent corners alone misses pixels of bulging edges.
        Vec2 lo = fp.corners[0], hi = fp.corners[0];
        for (const Vec2& c : fp.corners) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
        for (int y = 0; y < cam.height; ++y)
            for (int x = 0; x < cam.width; ++x)
                if (intersectLocal(tri, f, obs, cam.directionAt(x + 0.5, y + 0.5))) {
                    ++hitPixels;
                    if (!fp.rect.contains(x, y)) ++outside;
                    if (!fp.fullScreen &&
                        (x + 0.5 < lo.x() || x + 0.5 > hi.x() || y + 0.5 < lo.y() || y + 0.5 > hi.y()))
                        ++outsideCorners;
                }
    }
    std::printf("  footprints: %d trials, %d full-screen fallbacks, %d hit pixels, %d outside (corner box alone: %d)\n",
                trials, fullScreen, hitPixels, outside, outsideCorners);
    EXPECT_EQ(outside, 0);
    EXPECT_GT(outsideCorners, 0);
    EXPECT_GT(hitPixels, 10000);
    EXPECT_LT(fullScreen, trials / 4);
}

// The camera looking anywhere, as after a look-around: triangles whose apparent image is behind
// the camera or beyond a side of the view have no footprint (before, one behind the camera took
// the whole screen, and a cube turned away from cost a full-screen quad per triangle), and every
// hit pixel is still inside the footprint of its triangle.
TEST(SrLocalRayTracing, FootprintOfATriangleOutOfViewIsEmptyAndNoHitIsLost) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int trials = 0, fullScreen = 0, empty = 0, hitPixels = 0, outside = 0;
    for (int i = 0; i < 800; ++i) {
        const RandomTriangle random = randomTriangle(rng, u);
        const Vec3 anywhere(u(rng), u(rng), u(rng));
        if (anywhere.norm() < 0.1) continue;
        const ObserverCamera cam = cameraAt(random.observer, anywhere, 60.0, 64, 48);
        const ApparentFootprint fp = apparentFootprint(random.tri, random.frame, random.observer, cam, 0.0);
        ++trials;
        fullScreen += fp.fullScreen;
        empty += fp.rect.empty();
        for (int y = 0; y < cam.height; ++y)
            for (int x = 0; x < cam.width; ++x)
                if (intersectLocal(random.tri, random.frame, random.observer, cam.directionAt(x + 0.5, y + 0.5))) {
                    ++hitPixels;
                    outside += !fp.rect.contains(x, y);
                }
    }
    std::printf("  any direction: %d trials, %d empty footprints, %d full-screen, %d hit pixels, %d outside\n", trials,
                empty, fullScreen, hitPixels, outside);
    EXPECT_EQ(outside, 0);
    EXPECT_GT(hitPixels, 5000);
    EXPECT_GT(empty, trials / 2) << "most random views miss the triangle";
    EXPECT_LT(fullScreen, trials / 20);
}

// The panorama's footprint (the box in azimuth and elevation of the image's boundary, full rows
// from a pole the image contains, both sides of the seam behind the observer): for random
// triangles at up to 0.99 c, every pixel whose ray meets the triangle (the exact intersection,
// the oracle) lies in it, on a whole-sky panorama and on a partial one looking anywhere, with
// non-square pixels; and the footprints stay small.
TEST(SrLocalRayTracing, PanoramaFootprintHoldsEveryHitPixel) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int trials = 0, hitPixels = 0, outside = 0;
    double covered = 0, footprintArea = 0;
    for (int i = 0; i < 300; ++i) {
        const RandomTriangle random = randomTriangle(rng, u);
        ObserverCamera cam;
        cam.projection = Camera::Projection::Panorama;
        cam.position = random.observer.tail<3>();
        const bool whole = i % 2 == 0;
        cam.width = whole ? 96 : 80;
        cam.height = whole ? 48 : 40;
        cam.fovXDeg = whole ? 360 : 200;
        cam.fovYDeg = whole ? 180 : 120;
        cam.forward = whole ? Vec3(0, 0, -1) : Vec3(u(rng), u(rng), u(rng));
        cam.up = whole ? Vec3(0, 1, 0) : cam.forward.unitOrthogonal();
        if (cam.forward.norm() < 0.1) continue;
        const ApparentFootprint fp = apparentFootprint(random.tri, random.frame, random.observer, cam, 0.0);
        ++trials;
        EXPECT_FALSE(fp.fullScreen);
        int hits = 0;
        for (int y = 0; y < cam.height; ++y)
            for (int x = 0; x < cam.width; ++x)
                if (intersectLocal(random.tri, random.frame, random.observer, cam.direction(x, y))) {
                    ++hits;
                    outside += !fp.rect.contains(x, y);
                }
        hitPixels += hits;
        if (hits > 0 && !fp.rect.empty())
            covered += hits, footprintArea += double(fp.rect.x1 - fp.rect.x0 + 1) * (fp.rect.y1 - fp.rect.y0 + 1);
    }
    std::printf("  panorama: %d trials, %d hit pixels, %d outside, hits fill %.0f %% of their footprints\n", trials,
                hitPixels, outside, 100 * covered / footprintArea);
    EXPECT_EQ(outside, 0);
    EXPECT_GT(hitPixels, 2000);
    EXPECT_GT(covered / footprintArea, 0.15) << "footprints much larger than the images";
}

// A fast cube face behind the observer's camera (the camera turned away from it): no footprint,
// not the whole screen.
TEST(SrLocalRayTracing, TriangleBehindTheCameraHasNoFootprint) {
    RestTriangle tri;
    tri.p = {Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(0, 2, 0)};
    tri.n = {Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ()};
    const MovingFrame f = MovingFrame::throughEvent(Vec3(0.95, 0, 0), Vec4(-10, 0, 0, -8));
    ObserverCamera cam;  // at the origin
    cam.forward = Vec3(0, 0, 1);
    cam.up = Vec3(0, 1, 0);
    cam.width = 160;
    cam.height = 90;
    const ApparentFootprint away = apparentFootprint(tri, f, Vec4(0, 0, 0, 0), cam);
    EXPECT_FALSE(away.fullScreen);
    EXPECT_TRUE(away.rect.empty());
    cam.forward = Vec3(0, 0, -1);  // and towards it: a footprint of part of the screen
    const ApparentFootprint towards = apparentFootprint(tri, f, Vec4(0, 0, 0, 0), cam);
    EXPECT_FALSE(towards.rect.empty());
    EXPECT_FALSE(towards.fullScreen);
}

TEST(SrLocalRayTracing, FootprintIsTightForASmallTriangle) {
    // Far, slow, small triangle: the footprint hugs the projected triangle.
    RestTriangle tri;
    tri.p = {Vec3(-0.5, -0.5, 0), Vec3(0.5, -0.5, 0), Vec3(0, 0.5, 0)};
    tri.n = {Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitZ()};
    const MovingFrame f(Vec3(0.01, 0, 0), Vec3(0, 0, -10));
    ObserverCamera cam;
    cam.forward = Vec3(0, 0, -1);
    cam.up = Vec3(0, 1, 0);
    cam.width = 200;
    cam.height = 200;
    cam.fovXDeg = cam.fovYDeg = 20.0;
    const ApparentFootprint fp = apparentFootprint(tri, f, Vec4(0, 0, 0, 0), cam);
    EXPECT_FALSE(fp.fullScreen);
    // The triangle spans 1 / (10 tan 10 deg) * 100 px ~ 57 px.
    EXPECT_NEAR(fp.rect.x1 - fp.rect.x0, 57, 4);
    EXPECT_NEAR(fp.rect.y1 - fp.rect.y0, 57, 4);
}

TEST(SrLocalRayTracing, RestRayDepthIsTheObserverFrameDistance) {
    // sigma (S' distance) times D equals the S distance along the same null line.
    const MovingFrame f(Vec3(0.3, -0.6, 0.2), Vec3(1, 2, 3));
    const Vec4 obs(2.0, -1.0, 0.5, 4.0);
    const Vec3 d = Vec3(0.2, 1.0, -0.4).normalized();
    const RestRay r = makeRestRay(f, obs, d);
    const double sigma = 3.7;
    const Vec4 onLine = r.origin + sigma * Vec4(-1.0, r.dir.x(), r.dir.y(), r.dir.z());
    const Vec4 inS = f.eventToObserver(onLine);
    const double s = obs[0] - inS[0];
    EXPECT_LT((inS.tail<3>() - (obs.tail<3>() + s * d)).norm(), 1e-12);
    EXPECT_NEAR(s, sigma * r.doppler, 1e-12);
    EXPECT_NEAR(r.dir.norm(), 1.0, 1e-14);
}

// lc::sr::triangleLineHit, the one Moller-Trumbore of intersectRest, intersectFlat and the shaders'
// lcRestTriangleHit / lcFlatTriangleHit, on the unit right triangle in z = 0, where the point of
// barycentrics (u, v) is (u, v, 0): the caller's edge tolerance, the parallel test and the clamp
// of the rasterised (polygon distortion) case, against the geometry worked by hand.
TEST(SrTriangleLineHit, ToleranceParallelAndClamp) {
    const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0), down(0, 0, -1);
    const Eigen::Vector4d h = triangleLineHit<double>(Vec3(0.25, 0.5, 2), down, p0, p1, p2, 0.0, 1e-14);
    EXPECT_NEAR(h[0], 2.0, 1e-15);
    EXPECT_NEAR(h[1], 0.25, 1e-15);
    EXPECT_NEAR(h[2], 0.5, 1e-15);
    EXPECT_EQ(h[3], 1.0);
    // Just outside the edge u = 0: a miss in double, a hit with the GPU's float-sized tolerance.
    EXPECT_EQ(triangleLineHit<double>(Vec3(-1e-7, 0.5, 1), down, p0, p1, p2, 0.0, 1e-14)[3], 0.0);
    EXPECT_EQ(triangleLineHit<double>(Vec3(-1e-7, 0.5, 1), down, p0, p1, p2, 2e-6, 1e-14)[3], 1.0);
    EXPECT_EQ(triangleLineHit<double>(Vec3(0.3, 0.8, 1), down, p0, p1, p2, 0.0, 1e-14)[3], 0.0);  // u + v > 1
    // On the edge exactly: inside (the CPU's `u < 0` rejects only what is outside).
    EXPECT_EQ(triangleLineHit<double>(Vec3(0.0, 0.5, 1), down, p0, p1, p2, 0.0, 1e-14)[3], 1.0);
    // Behind the origin (s < 0) and a line in the triangle's plane: no hit, nothing infinite.
    EXPECT_EQ(triangleLineHit<double>(Vec3(0.25, 0.25, -1), down, p0, p1, p2, 0.0, 1e-14)[3], 0.0);
    const Eigen::Vector4d parallel = triangleLineHit<double>(Vec3(-1, 0.2, 0), Vec3(1, 0, 0), p0, p1, p2, 0.0, 1e-14);
    EXPECT_EQ(parallel[3], 0.0);
    EXPECT_TRUE(parallel.allFinite());
    // Rasterised: a marginal miss is clamped onto the triangle; a non-positive s becomes the distance.
    const Eigen::Vector4d c = triangleLineHit<double>(Vec3(-0.1, 0.5, 1), down, p0, p1, p2, 0.0, 1e-14, true);
    EXPECT_EQ(c[1], 0.0);
    EXPECT_NEAR(c[2], 0.5, 1e-15);
    EXPECT_NEAR(c[0], 1.0, 1e-15);
    EXPECT_EQ(c[3], 1.0);
    const Eigen::Vector4d b = triangleLineHit<double>(Vec3(0.25, 0.25, -1), down, p0, p1, p2, 0.0, 1e-14, true);
    EXPECT_NEAR(b[0], 1.0, 1e-15);
    EXPECT_EQ(b[3], 1.0);
}
