#include "core/analysis/shadow.hpp"

#include "core/spacetime/frame.hpp"

#include <cmath>
#include <stdexcept>

namespace lc {
namespace {

constexpr double kDegrees = 180 / kPi;

class ShadowProbe {
public:
    explicit ShadowProbe(const Scene& scene)
        : st_(*scene.spacetime),
          frame_(LocalFrame::withVelocity(st_, scene.observer, scene.observerVelocity)),
          x_(scene.observer) {
        const Vec3 f = scene.camera.forward.normalized();
        right_ = f.cross(scene.camera.up).normalized();
        up_ = right_.cross(f);
        forward_ = f;
        opt_ = scene.settings.trace;
        opt_.absTol = opt_.relTol = std::min(opt_.relTol, 1e-10);
        // Only capture or escape matters, not the direction: an outgoing ray beyond the
        // capture radius is known to escape.
        opt_.escapeAngle = 4;
    }
    // Does the ray seen at angle `angle` from `axis` (a unit direction of the frame) towards
    // `towards` fall into the hole?
    bool captured(const Vec3& axis, const Vec3& towards, double angle) const {
        const Vec3 n = std::cos(angle) * axis + std::sin(angle) * towards;
        const PhasePoint start{x_, frame_.pastNullMomentum(st_, n)};
        return traceGeodesic(st_, start, opt_).reason == StopReason::Horizon;
    }
    // The angle from `axis` towards `towards` at which rays stop falling in.
    double edge(const Vec3& axis, const Vec3& towards, double tolerance) const {
        double in = 0, out = kPi / 2;
        if (captured(axis, towards, out))
            throw std::invalid_argument("the shadow fills more than the half sky towards the camera's side");
        while (out - in > tolerance) {
            const double mid = 0.5 * (in + out);
            (captured(axis, towards, mid) ? in : out) = mid;
        }
        return 0.5 * (in + out);
    }
    const Vec3& forward() const { return forward_; }
    const Vec3& right() const { return right_; }
    const Vec3& up() const { return up_; }

private:
    const Spacetime& st_;
    LocalFrame frame_;
    Vec4 x_;
    Vec3 forward_, right_, up_;
    TraceOptions opt_;
};

double photonOrbitImpact(double M, double a, double r) {
    return (M * (r * r - a * a) - r * (r * r - 2 * M * r + a * a)) / (a * (r - M));
}

}  // namespace

double ShadowSize::widthImpact(double distance) const {
    return distance * (std::tan(leftDegrees / kDegrees) + std::tan(rightDegrees / kDegrees));
}

ShadowSize measureShadow(const Scene& scene, double angleTolerance) {
    if (!scene.spacetime->asymptoticallyFlat())
        throw std::invalid_argument("a shadow is measured for black holes (asymptotically flat metrics), not " +
                                    scene.spacetime->name());
    const ShadowProbe probe(scene);
    if (!probe.captured(probe.forward(), probe.right(), 0))
        throw std::invalid_argument("the camera's forward ray does not fall into the hole: point it at the shadow");
    ShadowSize s;
    s.rightDegrees = probe.edge(probe.forward(), probe.right(), angleTolerance) * kDegrees;
    s.leftDegrees = probe.edge(probe.forward(), -probe.right(), angleTolerance) * kDegrees;
    // The vertical through the centre of the horizontal chord.
    const double centre = s.offsetDegrees() / kDegrees;
    const Vec3 axis = std::cos(centre) * probe.forward() + std::sin(centre) * probe.right();
    s.heightDegrees =
        (probe.edge(axis, probe.up(), angleTolerance) + probe.edge(axis, -probe.up(), angleTolerance)) * kDegrees;
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
