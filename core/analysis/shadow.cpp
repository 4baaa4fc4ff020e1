// SPDX-License-Identifier: BSD-3-Clause
#include "core/analysis/shadow.hpp"

#include "core/analysis/radial_potential_fate.hpp"

#include "core/metrics/kerr_newman.hpp"
#include "core/numerics/parallel.hpp"
#include "core/render/render.hpp"
#include "core/scene/frame_camera.hpp"

#include <algorithm>

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

namespace lc {
namespace {

constexpr double kDegrees = 180 / kPi;

Vec3 along(const Vec3& axis, const Vec3& towards, double angle) {
    return std::cos(angle) * axis + std::sin(angle) * towards;
}

// The CPU's edge finder: bisection between rays the tracer sees fall in and rays that escape,
// along the great circle from the axis to its antipode (a shadow may be larger than a hemisphere:
// observers inside the photon region, or falling in).
class BisectionEdges {
public:
    BisectionEdges(const Scene& scene, double relTol)
        : st_(*scene.spacetime), frame_(observerFrame(scene)), x_(scene.observer), relTol_(relTol) {
        opt_ = scene.settings.trace;
        opt_.stepper = fateStepper(scene.settings);  // only a ray's fate counts here
        // The tracer one order tighter than the edge asked (1e-11 at least: measureShadow's
        // default), so a ray's fate is decided correctly to the bracket's width.
        opt_.absTol = opt_.relTol = std::min(opt_.relTol, std::max(0.1 * relTol, 1e-11));
        // Only capture or escape matters, not the direction: an outgoing ray beyond the
        // capture radius is known to escape.
        opt_.escapeAngle = 4;
    }
    const LocalFrame& frame() const { return frame_; }
    bool captured(const Vec3& n) const { return capturedWith(opt_, n); }
    // The region whose edge is sought: the dark one, or (observers just outside a horizon, whose
    // sky is a small cap) the bright one.
    void seekFromSky() { fromSky_ = true; }
    bool inRegion(const Vec3& n) const { return captured(n) != fromSky_; }
    // Keep every final bracket (serial callers only: measureShadow), for confirmedError.
    void keepBrackets() { brackets_ = std::make_shared<std::vector<Bracket>>(); }
    // The error of every edge found since keepBrackets, radians: each was reported as the midpoint
    // of its last bracket; the bracket's two ends are traced again with the tracer 10 times
    // tighter and, where one changes its fate, grown until the tighter tracer confirms it. The
    // edge the tighter tracer sees then lies in the bracket: the largest distance from the midpoint
    // to the confirmed bracket's ends bounds the error.
    double confirmedError(int threads) const {
        if (!brackets_) return std::numeric_limits<double>::quiet_NaN();
        TraceOptions tight = opt_;
        tight.absTol = tight.relTol = std::max(opt_.relTol / 10, 1e-15);
        const std::vector<Bracket>& log = *brackets_;
        // Each bracket end on its own, both cores at work: the ends are near-critical rays (slow).
        std::vector<double> distance(2 * log.size(), 0.0);
        FirstError error;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
        for (int task = 0; task < static_cast<int>(distance.size()); ++task)
            error.run([&] {
                const Bracket& b = log[std::size_t(task / 2)];
                auto dark = [&](double angle) {
                    return capturedWith(tight, along(b.axis, b.towards, angle)) != fromSky_;
                };
                const double mid = 0.5 * (b.in + b.out);
                double end = task % 2 == 0 ? b.in : b.out;
                if (task % 2 == 0)
                    for (double step = b.out - b.in; end > 0 && !dark(end); step *= 2) end = std::max(0.0, end - step);
                else
                    for (double step = b.out - b.in; end < kPi && dark(end); step *= 2) end = std::min(kPi, end + step);
                distance[std::size_t(task)] = std::abs(end - mid);
            });
        error.rethrow();
        return *std::max_element(distance.begin(), distance.end());
    }
    // The whole half great circle, scanned in kScan steps first: the captured directions must form
    // one arc starting at the axis (one dark cap along it), else the edge is not defined.
    double operator()(const Vec3& axis, const Vec3& towards) const {
        if (!inRegion(axis))
            throw std::invalid_argument(fromSky_ ? "the outline's inside point does not see the sky"
                                                 : "the camera's forward ray does not fall into the hole: point it at "
                                                   "the shadow");
        // Finer scans only when the sky left is small (observers just outside a horizon).
        for (int scan = 12; scan <= 12 * 32; scan *= 2) {
            int firstEscape = 0;
            for (int j = 1; j <= scan; ++j) {
                const bool dark = inRegion(along(axis, towards, kPi * j / scan));
                if (!dark && firstEscape == 0) firstEscape = j;
                if (dark && firstEscape != 0)
                    throw std::invalid_argument(
                        "the sky is dark in two separate regions along a great circle from the camera's forward "
                        "direction: the shadow's edge is not defined there");
            }
            if (firstEscape != 0)
                return bisect(axis, towards, kPi * (firstEscape - 1) / scan, kPi * firstEscape / scan);
        }
        throw NoSkyAlongGreatCircle(
            "every direction along a great circle from the camera's forward direction falls in (to 0.5 degrees): "
            "the observer sees no sky there (inside a horizon?)");
    }
    // The edge near `guess` (an outline's neighbouring point): a bracket grown from guess by
    // `spread` radians, then bisection. No scan of the whole circle: the outline's caller checked
    // its shape once along the symmetry line.
    double near(const Vec3& axis, const Vec3& towards, double guess, double spread) const {
        double in = std::max(0.0, guess - spread), out = std::min(kPi, guess + spread);
        for (double step = spread; in > 0 && !inRegion(along(axis, towards, in)); step *= 2)
            out = in, in = std::max(0.0, in - step);
        for (double step = spread; inRegion(along(axis, towards, out)); step *= 2) {
            if (out >= kPi)
                throw std::invalid_argument("the shadow's outline is not star-shaped about its centre: no edge found");
            in = out, out = std::min(kPi, out + step);
        }
        return bisect(axis, towards, in, out);
    }

private:
    struct Bracket {
        Vec3 axis, towards;
        double in, out;
    };
    // Inside the shadow: a black hole's rays end at the horizon, a wormhole's throat's reach the
    // other side.
    // A Kerr-Newman hole's rays are decided by their radial potential, exactly and without
    // tracing (radial_potential_fate); where it cannot decide, and for every other metric, traced.
    bool capturedWith(const TraceOptions& opt, const Vec3& n) const {
        const Vec4 p = frame_.pastNullMomentum(st_, n);
        if (hole_)
            if (const std::optional<RayFate> fate = radialPotentialFate(*hole_, st_, x_, p))
                return *fate == RayFate::Captured;
        const StopReason r = traceGeodesic(st_, PhasePoint{x_, p}, opt).reason;
        return r == StopReason::Horizon || r == StopReason::OtherEnd;
    }
    double bisect(const Vec3& axis, const Vec3& towards, double in, double out) const {
        while (out - in > relTol_ * in + 1e-15) {
            const double mid = 0.5 * (in + out);
            (inRegion(along(axis, towards, mid)) ? in : out) = mid;
        }
        if (brackets_) brackets_->push_back({axis, towards, in, out});
        return 0.5 * (in + out);
    }

    const Spacetime& st_;
    std::optional<Spacetime::KerrNewmanParameters> hole_ = st_.kerrNewmanParameters();
    LocalFrame frame_;
    Vec4 x_;
    double relTol_;
    TraceOptions opt_;
    bool fromSky_ = false;
    std::shared_ptr<std::vector<Bracket>> brackets_;  // shared by the copies a ShadowEdgeFinder makes
};

void checkShadowScene(const Scene& scene) {
    if (!scene.spacetime->asymptoticallyFlat())  // before the frame: Goedel's static frame may not exist
        throw std::invalid_argument("a shadow is measured for black holes (asymptotically flat metrics), not " +
                                    scene.spacetime->name());
}

void checkTolerance(double relTol) {
    if (!(relTol >= 1e-14 && relTol <= 1e-2)) throw std::invalid_argument("shadow tolerance outside [1e-14, 1e-2]");
}

// L_z / E of a ray from its covariant momentum in the Kerr-Schild chart (d/dphi = -y d/dx + x d/dy).
double axialImpact(const Vec4& x, const Vec4& p) { return -(x(1) * p(2) - x(2) * p(1)) / p(0); }

double photonOrbitImpact(double M, double a, double r) {
    return (M * (r * r - a * a) - r * (r * r - 2 * M * r + a * a)) / (a * (r - M));
}

}  // namespace

double ShadowSize::widthImpact(double distance) const {
    return distance * (std::tan(leftDegrees / kDegrees) + std::tan(rightDegrees / kDegrees));
}

ShadowSize measureShadow(const Scene& scene, double relTol) {
    checkTolerance(relTol);
    checkShadowScene(scene);
    BisectionEdges edges(scene, relTol);
    edges.keepBrackets();
    ShadowSize s = measureShadow(scene, edges);
    s.edgeErrorDegrees = edges.confirmedError(renderThreads(scene.settings)) * kDegrees;
    return s;
}

ShadowSize measureShadow(const Scene& scene, const ShadowEdgeFinder& edge) {
    checkShadowScene(scene);
    scene.camera.validate();
    const Spacetime& st = *scene.spacetime;
    const LocalFrame frame = observerFrame(scene);
    const Camera cam = frameCamera(scene.camera, st, frame);
    const Vec3 forward = cam.forward.normalized();
    const Vec3 right = forward.cross(cam.up).normalized();
    const Vec3 up = right.cross(forward);
    ShadowSize s;
    // The symmetry line: by the reflection symmetry, the midpoint of the vertical chord through
    // forward lies on it (exactly when the camera's right is orthogonal to e_theta).
    const double top = edge(forward, up), bottom = edge(forward, -up);
    const double elevation = 0.5 * (top - bottom);
    s.centreUpDegrees = elevation * kDegrees;
    const Vec3 axis = along(forward, up, elevation);
    const Vec3 across = along(up, -forward, elevation);  // normal of the symmetry line's plane
    s.rightDegrees = edge(axis, right) * kDegrees;
    s.leftDegrees = edge(axis, -right) * kDegrees;
    const Vec3 centre = along(axis, right, s.offsetDegrees() / kDegrees);
    s.heightDegrees = (edge(centre, across) + edge(centre, -across)) * kDegrees;

    if (const auto kn = st.kerrNewmanParameters()) {
        const Vec4& x = scene.observer;
        auto impact = [&](double angle, const Vec3& towards) {
            return axialImpact(x, frame.pastNullMomentum(st, along(axis, towards, angle)));
        };
        const double r = kerrSchildRadius(x(1), x(2), x(3), kn->spin);
        const double sinTheta = std::sqrt(std::max(0.0, 1 - x(3) * x(3) / (r * r)));
        const double xiRight = impact(s.rightDegrees / kDegrees, right);
        if (sinTheta > 1e-12) {
            s.rightAlpha = -xiRight / sinTheta / kn->mass;
            s.leftAlpha = -impact(s.leftDegrees / kDegrees, -right) / sinTheta / kn->mass;
        }
        s.rightEdgeSense = kn->spin == 0 ? 0 : (xiRight * kn->spin > 0 ? 1 : -1);
    }
    return s;
}

double ShadowOutline::polarDegrees(std::size_t k) const {
    return std::acos(std::clamp(points[k].dot(forward), -1.0, 1.0)) * kDegrees;
}

double ShadowOutline::azimuthDegrees(std::size_t k) const {
    return std::atan2(points[k].dot(up), points[k].dot(right)) * kDegrees;
}

namespace {

// A point of the sky near the middle of its bright cap: the first escaping direction of ever finer
// Fibonacci spheres (from the one opposite forward), then centred between its edges along two
// orthogonal great circles, twice.
Vec3 skyCentre(const BisectionEdges& edges, const Vec3& forward) {
    std::optional<Vec3> bright;
    if (!edges.captured(-forward)) bright = -forward;
    for (int count = 256; !bright && count <= 65536; count *= 4)
        for (int k = 0; k < count && !bright; ++k) {
            const double z = 1 - (2 * k + 1.0) / count, ring = std::sqrt(1 - z * z),
                         phi = k * kPi * (3 - std::sqrt(5.0));
            const Vec3 n(ring * std::cos(phi), ring * std::sin(phi), z);
            if (!edges.captured(n)) bright = n;
        }
    if (!bright)
        throw std::invalid_argument("the observer sees no sky in any direction (to 0.5 degrees): no outline exists");
    Vec3 c = *bright;
    auto escapes = [&](const Vec3& n) { return !edges.captured(n); };
    for (int pass = 0; pass < 2; ++pass)
        for (int axis = 0; axis < 2; ++axis) {
            const Vec3 any = std::abs(c(0)) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
            Vec3 t = c.cross(any).normalized();
            if (axis == 1) t = c.cross(t);
            // Edges of the bright arc along +-t from c, by bisection to 1e-6 rad (enough for a centre).
            auto edge = [&](const Vec3& towards) {
                double in = 0, out = kPi;
                while (out - in > 1e-6) ((escapes(along(c, towards, 0.5 * (in + out)))) ? in : out) = 0.5 * (in + out);
                return in;
            };
            const double plus = edge(t), minus = edge(-t);
            c = along(c, t, 0.5 * (plus - minus));
        }
    return c;
}

}  // namespace

ShadowOutline traceShadowOutline(const Scene& scene, int points, double relTol) {
    checkTolerance(relTol);
    checkShadowScene(scene);
    if (!(points >= 8 && points <= 100000)) throw std::invalid_argument("outline points outside [8, 100000]");
    scene.camera.validate();
    BisectionEdges edges(scene, relTol);
    const Camera cam = frameCamera(scene.camera, *scene.spacetime, edges.frame());
    ShadowOutline o;
    o.forward = cam.forward.normalized();
    o.right = o.forward.cross(cam.up).normalized();
    o.up = o.right.cross(o.forward);
    // The inside point: measureShadow's centre, on the symmetry line (which also checks, along
    // that line, that the dark region is one cap). Where a great circle through forward sees no
    // sky at all (just outside a horizon), the outline is traced from the sky's side instead.
    const double kRad = 1 / kDegrees;
    try {
        const ShadowSize size = measureShadow(scene, edges);
        o.inside = along(along(o.forward, o.up, size.centreUpDegrees * kRad), o.right, size.offsetDegrees() * kRad);
    } catch (const NoSkyAlongGreatCircle&) {
        o.fromSky = true;
        o.inside = skyCentre(edges, o.forward);
        edges.seekFromSky();
    }
    const Vec3 right = (o.right - o.right.dot(o.inside) * o.inside).normalized();
    const Vec3 up = right.cross(o.inside);
    auto towards = [&](double psi) { return Vec3(std::cos(psi) * right + std::sin(psi) * up); };

    // A coarse ring first (each edge found by scanning its whole great circle), then every point
    // bisected from a bracket around the ring's interpolated radius.
    constexpr int kRing = 16;
    std::vector<double> ring(kRing);
    const int team = renderThreads(scene.settings);
    FirstError error;
#pragma omp parallel for schedule(dynamic, 1) num_threads(team)
    for (int j = 0; j < kRing; ++j)
        error.run([&] { ring[std::size_t(j)] = edges(o.inside, towards(2 * kPi * j / kRing)); });
    error.rethrow();
    const auto n = static_cast<std::size_t>(points);
    o.positionAngles.resize(n);
    o.radii.resize(n);
    o.points.resize(n);
#pragma omp parallel for schedule(dynamic, 4) num_threads(team)
    for (int k = 0; k < points; ++k)
        error.run([&] {
            const double psi = 2 * kPi * k / points, slot = psi / (2 * kPi) * kRing;
            const int j0 = static_cast<int>(slot) % kRing, j1 = (j0 + 1) % kRing;
            const double w = slot - std::floor(slot);
            const double guess = (1 - w) * ring[std::size_t(j0)] + w * ring[std::size_t(j1)];
            const double spread = 0.05 * std::abs(ring[std::size_t(j1)] - ring[std::size_t(j0)]) + 1e-3 * guess + 1e-9;
            const double rho = edges.near(o.inside, towards(psi), guess, spread);
            const auto i = static_cast<std::size_t>(k);
            o.positionAngles[i] = psi;
            o.radii[i] = rho;
            o.points[i] = along(o.inside, towards(psi), rho);
        });
    error.rethrow();
    // Trapezoids over a periodic function (spectrally accurate): the solid angle, and the area
    // integral of the direction, int_0^rho (cos s inside + sin s t) sin s ds.
    Vec3 sum = Vec3::Zero();
    for (std::size_t k = 0; k < n; ++k) {
        const double rho = o.radii[k];
        o.solidAngle += (1 - std::cos(rho)) * 2 * kPi / points;
        sum += (0.5 * std::sin(rho) * std::sin(rho)) * o.inside +
               (0.5 * rho - 0.25 * std::sin(2 * rho)) * towards(o.positionAngles[k]);
    }
    if (o.fromSky) {  // the dark region is the rest of the sphere, whose direction integral is zero
        o.solidAngle = 4 * kPi - o.solidAngle;
        sum = -sum;
    }
    o.centroid = sum.normalized();
    return o;
}

double bardeenEdgeOnWidth(double M, double a) {
    if (a == 0) return 6 * std::sqrt(3.0) * M;
    const double x = a / M;
    const double prograde = 2 * M * (1 + std::cos(2.0 / 3 * std::acos(-std::abs(x))));
    const double retrograde = 2 * M * (1 + std::cos(2.0 / 3 * std::acos(std::abs(x))));
    return std::abs(photonOrbitImpact(M, std::abs(a), prograde)) +
           std::abs(photonOrbitImpact(M, std::abs(a), retrograde));
}

}  // namespace lc
