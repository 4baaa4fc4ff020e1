#include "core/analysis/shadow.hpp"

#include "core/metrics/kerr_newman.hpp"
#include "core/scene/frame_camera.hpp"

#include <cmath>
#include <stdexcept>

namespace lc {
namespace {

constexpr double kDegrees = 180 / kPi;

Vec3 along(const Vec3& axis, const Vec3& towards, double angle) {
    return std::cos(angle) * axis + std::sin(angle) * towards;
}

// The CPU's edge finder: bisection between rays the tracer sees fall in and rays that escape.
class BisectionEdges {
public:
    BisectionEdges(const Scene& scene, double relTol)
        : st_(*scene.spacetime), frame_(observerFrame(scene)), x_(scene.observer), relTol_(relTol) {
        opt_ = scene.settings.trace;
        opt_.absTol = opt_.relTol = std::min(opt_.relTol, 1e-11);
        // Only capture or escape matters, not the direction: an outgoing ray beyond the
        // capture radius is known to escape.
        opt_.escapeAngle = 4;
    }
    bool captured(const Vec3& n) const {
        return traceGeodesic(st_, PhasePoint{x_, frame_.pastNullMomentum(st_, n)}, opt_).reason == StopReason::Horizon;
    }
    double operator()(const Vec3& axis, const Vec3& towards) const {
        if (!captured(axis))
            throw std::invalid_argument("the camera's forward ray does not fall into the hole: point it at the shadow");
        double in = 0, out = kPi / 2;
        if (captured(along(axis, towards, out)))
            throw std::invalid_argument("the shadow fills more than the half sky towards the camera's side");
        while (out - in > relTol_ * in + 1e-15) {
            const double mid = 0.5 * (in + out);
            (captured(along(axis, towards, mid)) ? in : out) = mid;
        }
        return 0.5 * (in + out);
    }

private:
    const Spacetime& st_;
    LocalFrame frame_;
    Vec4 x_;
    double relTol_;
    TraceOptions opt_;
};

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
    if (!(relTol >= 1e-14 && relTol <= 1e-2)) throw std::invalid_argument("shadow tolerance outside [1e-14, 1e-2]");
    if (!scene.spacetime->asymptoticallyFlat())  // before the frame: Goedel's static frame may not exist
        throw std::invalid_argument("a shadow is measured for black holes (asymptotically flat metrics), not " +
                                    scene.spacetime->name());
    return measureShadow(scene, BisectionEdges(scene, relTol));
}

ShadowSize measureShadow(const Scene& scene, const ShadowEdgeFinder& edge) {
    if (!scene.spacetime->asymptoticallyFlat())
        throw std::invalid_argument("a shadow is measured for black holes (asymptotically flat metrics), not " +
                                    scene.spacetime->name());
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

double bardeenEdgeOnWidth(double M, double a) {
    if (a == 0) return 6 * std::sqrt(3.0) * M;
    const double x = a / M;
    const double prograde = 2 * M * (1 + std::cos(2.0 / 3 * std::acos(-std::abs(x))));
    const double retrograde = 2 * M * (1 + std::cos(2.0 / 3 * std::acos(std::abs(x))));
    return std::abs(photonOrbitImpact(M, std::abs(a), prograde)) +
           std::abs(photonOrbitImpact(M, std::abs(a), retrograde));
}

}  // namespace lc
