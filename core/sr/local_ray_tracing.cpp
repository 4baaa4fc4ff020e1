// SPDX-License-Identifier: BSD-3-Clause
#include "core/sr/local_ray_tracing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/sr/doppler.hpp"
#include "core/sr/photo_object.hpp"

namespace lc::sr {

RestTriangle RestTriangle::fromMesh(const TriMesh& mesh, int triangle) {
    RestTriangle t;
    const auto& idx = mesh.triangles[static_cast<size_t>(triangle)];
    for (int k = 0; k < 3; ++k) {
        t.p[k] = mesh.positions[static_cast<size_t>(idx[k])];
        t.n[k] = mesh.normals.empty() ? Vec3::Zero() : mesh.normals[static_cast<size_t>(idx[k])];
    }
    if (mesh.normals.empty()) {
        const Vec3 n = (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]).normalized();
        t.n = {n, n, n};
    }
    return t;
}

RestRay makeRestRay(const MovingFrame& frame, const Vec4& observer, const Vec3& viewDir) {
    RestRay r;
    r.origin = frame.eventToRest(observer);
    // The light-cone generator (-1, d) of S becomes (-w, w d') in S' (Lambda(-beta)):
    // d' = boostDirection(beta, d), w = nu_em / nu_obs = 1 / restRayDoppler(beta, d).
    r.dir = boostDirection<double>(frame.beta(), viewDir);
    r.doppler = restRayDoppler<double>(frame.beta(), viewDir);
    return r;
}

std::optional<RayHit> intersectRest(const RestTriangle& tri, const RestRay& ray) {
    // Exact edges (tolerance 0) in double: neighbouring triangles share the edge's rays.
    const Vec4 hit = triangleLineHit<double>(ray.origin.tail<3>(), ray.dir, tri.p[0], tri.p[1], tri.p[2], 0.0, 1e-14);
    if (!(hit[3] > 0.0)) return std::nullopt;  // a miss, or light that would come from the future
    const double sigma = hit[0], u = hit[1], v = hit[2];
    RayHit h;
    h.sigma = sigma;
    h.barycentric = Vec3(1.0 - u - v, u, v);
    // S-frame parameter of the same null line: s = sigma / w = sigma * D.
    h.depth = sigma * ray.doppler;
    h.doppler = ray.doppler;
    return h;
}

void completeHit(RayHit& h, const RestTriangle& tri, const RestRay& ray, const MovingFrame& frame) {
    h.restPoint = h.barycentric[0] * tri.p[0] + h.barycentric[1] * tri.p[1] + h.barycentric[2] * tri.p[2];
    h.emissionRest[0] = ray.origin[0] - h.sigma;  // eq. 7
    h.emissionRest.tail<3>() = h.restPoint;
    h.emission = frame.eventToObserver(h.emissionRest);  // eq. 8
}

std::optional<RayHit> intersectLocal(const RestTriangle& tri, const MovingFrame& frame, const Vec4& observer,
                                     const Vec3& viewDir) {
    const RestRay ray = makeRestRay(frame, observer, viewDir.normalized());
    auto h = intersectRest(tri, ray);
    if (h) completeHit(*h, tri, ray, frame);
    return h;
}

std::array<Vec3, 3> apparentTriangle(const RestTriangle& tri, const MovingFrame& frame, const Vec4& observer) {
    return {apparentPosition(frame, tri.p[0], observer), apparentPosition(frame, tri.p[1], observer),
            apparentPosition(frame, tri.p[2], observer)};
}

std::optional<FlatHit> intersectFlat(const std::array<Vec3, 3>& tri, const Vec3& origin, const Vec3& dir) {
    const Vec4 hit = triangleLineHit<double>(origin, dir, tri[0], tri[1], tri[2], 0.0, 1e-14);
    if (!(hit[3] > 0.0)) return std::nullopt;
    return FlatHit{hit[0], Vec3(1.0 - hit[1] - hit[2], hit[1], hit[2])};
}

namespace {
double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// The observer-frame offset from the eye of the apparent image of rest point p: the emission
// event on the observer's past light cone (eq. 7), carried to S (eq. 8).
Vec3 apparentOffset(const MovingFrame& frame, const Vec4& obsRest, const Vec3& eye, const Vec3& p) {
    const double dist = (p - obsRest.tail<3>()).norm();
    return frame.eventToObserver(Vec4(obsRest[0] - dist, p.x(), p.y(), p.z())).tail<3>() - eye;
}

// Screen position of the apparent image of rest point p through a pinhole and its derivative
// along the rest direction e (chain rule through eq. 7, eq. 8 and Camera::project's formula).
struct ScreenMap {
    const MovingFrame& frame;
    Vec4 obsRest;
    Vec3 eye;
    Camera::Axes b;
    Vec2 focal;  // Camera::pinholeFocalPixels
    double cx, cy;

    bool operator()(const Vec3& p, const Vec3& e, Vec2& px, Vec2* dpx) const {
        const Vec3 r = p - obsRest.tail<3>();
        const double dist = r.norm();
        const Vec3 v = apparentOffset(frame, obsRest, eye, p);
        const double z = v.dot(b.forward);
        if (!(z > 1e-12 * v.norm())) return false;
        const double xr = v.dot(b.right), yu = v.dot(b.up);
        px = Vec2(cx + focal.x() * xr / z, cy - focal.y() * yu / z);
        if (dpx) {
            const Vec4 dX(-r.dot(e) / dist, e.x(), e.y(), e.z());
            const Vec3 dv = (frame.toObserverMatrix() * dX).tail<3>();
            const double dz = dv.dot(b.forward);
            *dpx = Vec2(focal.x() * (dv.dot(b.right) * z - xr * dz) / (z * z),
                        -focal.y() * (dv.dot(b.up) * z - yu * dz) / (z * z));
        }
        return true;
    }
};

// Distance from q to the flat triangle p: to its plane where the foot falls inside, else to the
// nearest edge.
double distanceToTriangle(const Vec3& q, const std::array<Vec3, 3>& p) {
    const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
    const double n2 = n.squaredNorm();
    if (n2 > 0) {
        const Vec3 foot = q - n * (n.dot(q - p[0]) / n2);
        bool inside = true;
        for (int i = 0; i < 3; ++i) inside = inside && (p[(i + 1) % 3] - p[i]).cross(foot - p[i]).dot(n) >= 0;
        if (inside) return (q - foot).norm();
    }
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        const Vec3 e = p[(i + 1) % 3] - p[i];
        const double e2 = e.squaredNorm();
        const double t = e2 > 0 ? std::clamp((q - p[i]).dot(e) / e2, 0.0, 1.0) : 0.0;
        best = std::min(best, (q - p[i] - t * e).norm());
    }
    return best;
}

// Whether the apparent image of the whole rest triangle lies outside the camera's view (behind it
// or beyond a side of the frustum, with marginPx to spare). Rest point p (r = p - eye', all in S')
// is seen along the observer-frame direction v = L (-|r|, r); a frustum plane keeps n . v >= 0, and
// n . v = a |r| + b . r. For a >= 0 that is convex in p, so its maximum over the triangle is at a
// corner; for a < 0 it is at most a d + max over the corners of b . r, d the triangle's distance
// from the eye. Where that maximum is below zero no pixel's ray meets the triangle.
bool outsideView(const RestTriangle& tri, const MovingFrame& frame, const Vec3& eyeRest, const ScreenMap& m, int width,
                 int height, double marginPx) {
    const Mat4& L = frame.toObserverMatrix();
    const Camera::Axes& b = m.b;
    const double fx = m.focal.x(), fy = m.focal.y();
    const double x0 = -marginPx, x1 = width + marginPx, y0 = -marginPx, y1 = height + marginPx;
    // px = cx + fx (v.right) / (v.forward), py = cy - fy (v.up) / (v.forward), v.forward > 0.
    const std::array<Vec3, 5> planes{b.forward, fx * b.right + (m.cx - x0) * b.forward,
                                     (x1 - m.cx) * b.forward - fx * b.right, (m.cy - y0) * b.forward - fy * b.up,
                                     fy * b.up + (y1 - m.cy) * b.forward};
    std::array<Vec3, 3> r;
    std::array<double, 3> dist;
    for (int k = 0; k < 3; ++k) r[k] = tri.p[k] - eyeRest, dist[k] = r[k].norm();
    const double nearest = distanceToTriangle(eyeRest, tri.p);
    for (const Vec3& n : planes) {
        const double a = -n.dot(L.block<3, 1>(1, 0));
        const Vec3 bv = L.block<3, 3>(1, 1).transpose() * n;
        double most = -std::numeric_limits<double>::infinity(), scale = 0;
        for (int k = 0; k < 3; ++k) {
            most = std::max(most, a >= 0 ? a * dist[k] + bv.dot(r[k]) : bv.dot(r[k]));
            scale = std::max(scale, (std::abs(a) + bv.norm()) * dist[k]);
        }
        if (a < 0) most += a * nearest;
        if (most < -1e-9 * scale) return true;  // below rounding: wholly outside this plane
    }
    return false;
}
}  // namespace

ApparentFootprint apparentFootprint(const RestTriangle& tri, const MovingFrame& frame, const Vec4& observer,
                                    const ObserverCamera& camera, double marginPx) {
    ApparentFootprint fp;
    const Vec4 obsRest = frame.eventToRest(observer);
    const Vec3 eye = observer.tail<3>();
    if (camera.projection == Camera::Projection::Panorama) {
        const Camera::Axes a = camera.axes();
        const auto contains = [&](const Vec3& d) {
            return intersectRest(tri, makeRestRay(frame, observer, d)).has_value();
        };
        fp.rect = panoramaFootprint(
            tri.p, [&](const Vec3& p) -> std::optional<Vec3> { return apparentOffset(frame, obsRest, eye, p); },
            contains(a.up), contains(-a.up), camera, marginPx);
        return fp;
    }
    const ScreenMap map{
        frame, obsRest, eye, camera.axes(), camera.pinholeFocalPixels(), 0.5 * camera.width, 0.5 * camera.height};
    auto full = [&]() {
        fp.fullScreen = true;
        fp.rect = PixelRect{0, 0, camera.width - 1, camera.height - 1};
        return fp;
    };
    if (outsideView(tri, frame, map.obsRest.tail<3>(), map, camera.width, camera.height, marginPx)) return fp;
    // An image containing the backward direction wraps around the camera.
    if (intersectRest(tri, makeRestRay(frame, observer, -map.b.forward))) return full();

    std::array<Vec2, 3> tStart, tEnd;  // derivative at edge start / end along the edge
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const Vec3 e = tri.p[j] - tri.p[i];
        Vec2 pj;
        if (!map(tri.p[i], e, fp.corners[i], &tStart[i]) || !map(tri.p[j], e, pj, &tEnd[i])) return full();
        // Interior samples must be in front too (an arc through infinity is not bounded).
        for (int s = 1; s < 16; ++s) {
            Vec2 q;
            if (!map(tri.p[i] + (s / 16.0) * e, e, q, nullptr)) return full();
        }
    }
    Vec2 lo = fp.corners[0], hi = fp.corners[0];
    for (int i = 0; i < 3; ++i) {
        const Vec2 a = fp.corners[i], c = fp.corners[(i + 1) % 3];
        const Vec2 delta = c - a;
        const Vec2 ti = tStart[i], tj = -tEnd[i];  // tangent at the end, pointing back
        const double len = delta.norm();
        // Nearly straight: the arc stays within len * sin(angle) of the chord, < 0.05 px.
        const double si = len > 0 ? std::abs(cross2(ti.normalized(), delta)) : 0.0;
        const double sj = len > 0 ? std::abs(cross2(tj.normalized(), delta)) : 0.0;
        if (len == 0.0 || (std::max(si, sj) < 0.05 && ti.dot(delta) > 0 && tj.dot(delta) < 0)) {
            fp.apexes[i] = 0.5 * (a + c);
        } else {
            const double det = cross2(ti, tj);
            if (std::abs(det) < 1e-15 * ti.norm() * tj.norm()) return full();
            // a + s ti = c + t tj (tj points back from c).
            const double s = cross2(delta, tj) / det, t = cross2(delta, ti) / det;
            if (s < 0.0 || t < 0.0) return full();
            fp.apexes[i] = a + s * ti;
        }
        lo = lo.cwiseMin(fp.corners[i]).cwiseMin(fp.apexes[i]);
        hi = hi.cwiseMax(fp.corners[i]).cwiseMax(fp.apexes[i]);
    }
    // Pixel centre i + 0.5 inside [lo - margin, hi + margin]; clamp before the int cast.
    auto toPixel = [](double v, int size) { return static_cast<int>(std::clamp(v, -1.0, static_cast<double>(size))); };
    fp.rect.x0 = std::max(0, toPixel(std::ceil(lo.x() - 0.5 - marginPx), camera.width));
    fp.rect.y0 = std::max(0, toPixel(std::ceil(lo.y() - 0.5 - marginPx), camera.height));
    fp.rect.x1 = std::min(camera.width - 1, toPixel(std::floor(hi.x() - 0.5 + marginPx), camera.width));
    fp.rect.y1 = std::min(camera.height - 1, toPixel(std::floor(hi.y() - 0.5 + marginPx), camera.height));
    return fp;
}

namespace {
// The boundary walk of panoramaFootprint: directions along the edges in steps below `pixel`
// radians, their azimuth unwrapped along the way (it turns by 2 pi round a pole).
class BoundaryWalk {
public:
    BoundaryWalk(const std::function<std::optional<Vec3>(const Vec3&)>& directionOf, const Camera::Axes& axes,
                 double pixel)
        : directionOf_(directionOf), axes_(axes), pixel_(pixel) {}

    // False where a direction is missing or a step cannot be made small (the path passes the eye).
    bool walk(const std::array<Vec3, 3>& corners) {
        std::optional<Vec3> d = unit(corners[0]);
        if (!d) return false;
        const double az0 = azimuth(*d);
        azimuth_ = az0;
        add(*d);
        Vec3 prev = *d;
        for (int i = 0; i < 3; ++i) {
            const Vec3 &p0 = corners[i], &p1 = corners[(i + 1) % 3];
            constexpr int kPieces = 4;  // then halved where a step exceeds a pixel
            for (int k = 1; k <= kPieces; ++k) {
                const Vec3 q0 = p0 + (double(k - 1) / kPieces) * (p1 - p0), q1 = p0 + (double(k) / kPieces) * (p1 - p0);
                std::optional<Vec3> next = unit(q1);
                if (!next || !refine(q0, prev, q1, *next, 0)) return false;
                prev = *next;
            }
        }
        turns_ = std::lround((azimuth_ - az0) / (2 * kPi));
        return true;
    }

    double azLo = 1e300, azHi = -1e300, elLo = 1e300, elHi = -1e300;
    double widest = 0;  // the largest step, radians
    long turns() const { return turns_; }

private:
    std::optional<Vec3> unit(const Vec3& p) const {
        const std::optional<Vec3> d = directionOf_(p);
        if (!d || !d->allFinite() || !(d->norm() > 0)) return std::nullopt;
        return d->normalized();
    }
    double azimuth(const Vec3& d) const { return std::atan2(-d.dot(axes_.right), d.dot(axes_.forward)); }
    void add(const Vec3& d) {
        const double df = d.dot(axes_.forward), dr = d.dot(axes_.right);
        const double el = std::atan2(d.dot(axes_.up), std::hypot(df, dr));
        azLo = std::min(azLo, azimuth_), azHi = std::max(azHi, azimuth_);
        elLo = std::min(elLo, el), elHi = std::max(elHi, el);
    }
    // The piece from q0 (direction d0, already added) to q1 (d1): halved until each step is below a pixel.
    bool refine(const Vec3& q0, const Vec3& d0, const Vec3& q1, const Vec3& d1, int depth) {
        const double step = std::atan2(d0.cross(d1).norm(), d0.dot(d1));
        if (step > pixel_) {
            if (depth == 30) return false;
            const Vec3 qm = 0.5 * (q0 + q1);
            std::optional<Vec3> dm = unit(qm);
            return dm && refine(q0, d0, qm, *dm, depth + 1) && refine(qm, *dm, q1, d1, depth + 1);
        }
        widest = std::max(widest, step);
        double turn = azimuth(d1) - azimuth_;
        turn -= 2 * kPi * std::floor((turn + kPi) / (2 * kPi));
        azimuth_ += turn;
        add(d1);
        return true;
    }

    const std::function<std::optional<Vec3>(const Vec3&)>& directionOf_;
    Camera::Axes axes_;
    double pixel_;
    double azimuth_ = 0;
    long turns_ = 0;
};
}  // namespace

PixelRect panoramaFootprint(const std::array<Vec3, 3>& corners,
                            const std::function<std::optional<Vec3>(const Vec3&)>& directionOf, bool containsUp,
                            bool containsDown, const Camera& camera, double marginPx) {
    const PixelRect whole{0, 0, camera.width - 1, camera.height - 1};
    const Vec2 half = camera.halfFieldRadians();
    const double pixel = std::min(2 * half.x() / camera.width, 2 * half.y() / camera.height);
    BoundaryWalk w(directionOf, camera.axes(), pixel);
    if (!w.walk(corners)) return whole;
    // A boundary that turns round the up axis encloses a pole; the pole tests say which.
    if (w.turns() != 0 && !containsUp && !containsDown) return whole;
    double elLo = w.elLo - w.widest, elHi = w.elHi + w.widest;
    if (containsUp) elHi = kPi / 2;
    if (containsDown) elLo = -kPi / 2;
    const double steepest = std::max(std::abs(elLo), std::abs(elHi));
    const bool allAzimuths = containsUp || containsDown || std::cos(steepest) < 0.05;
    double xLo = 0, xHi = camera.width;  // continuous image x of the azimuth range
    if (!allAzimuths) {
        const double azMargin = w.widest / std::cos(steepest);
        double lo = w.azLo - azMargin, hi = w.azHi + azMargin;
        if (hi - lo < 2 * kPi) {
            const double shift = 2 * kPi * std::floor((lo + kPi) / (2 * kPi));  // lo into [-pi, pi)
            lo -= shift, hi -= shift;
            // x = width / 2 (1 - az / halfX) (Camera::project); a range past the seam comes back on the left.
            const auto x = [&](double az) { return 0.5 * camera.width * (1 - az / half.x()); };
            xLo = 1e300, xHi = -1e300;
            const auto piece = [&](double a0, double a1) {
                a0 = std::max(a0, -half.x()), a1 = std::min(a1, half.x());
                if (a0 <= a1) xLo = std::min(xLo, x(a1)), xHi = std::max(xHi, x(a0));
            };
            piece(lo, std::min(hi, kPi));
            if (hi > kPi) piece(-kPi, hi - 2 * kPi);
            if (xLo > xHi) return PixelRect{};
        }
    }
    const double yLo = 0.5 * camera.height * (1 - std::min(elHi, half.y()) / half.y());
    const double yHi = 0.5 * camera.height * (1 - std::max(elLo, -half.y()) / half.y());
    if (yLo > yHi) return PixelRect{};
    auto toPixel = [](double v, int size) { return static_cast<int>(std::clamp(v, -1.0, static_cast<double>(size))); };
    PixelRect r;
    r.x0 = std::max(0, toPixel(std::ceil(xLo - 0.5 - marginPx), camera.width));
    r.y0 = std::max(0, toPixel(std::ceil(yLo - 0.5 - marginPx), camera.height));
    r.x1 = std::min(camera.width - 1, toPixel(std::floor(xHi - 0.5 + marginPx), camera.width));
    r.y1 = std::min(camera.height - 1, toPixel(std::floor(yHi - 0.5 + marginPx), camera.height));
    return r;
}

}  // namespace lc::sr
