// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A thin bundle of light rays around one traced ray (docs/PHYSICS.md section 13a): two deviation
// vectors (dx, dp), carried along the tracer's accepted steps by the linearised Hamilton
// equations with exact second derivatives of the metric (CurvatureProbe's jet), give the ray's
// Jacobi map and from it the image's magnification, shear and rotation. The renderer carries one
// per pixel (RenderSettings::magnification); core/curvature/jacobi_map traces a single ray to a
// source plane with the same equations.
#include "core/curvature/curvature.hpp"
#include "core/spacetime/frame.hpp"
#include "core/spacetime/integrator.hpp"

namespace lc {

using Mat8 = Eigen::Matrix<double, 8, 8>;
// Two deviations of a ray, each a column (dx^0..3, dp_0..3).
using DeviationPair = Eigen::Matrix<double, 8, 2>;

// What the equations along a ray are made of at a phase point with momentum p: g^-1, the tangent
// v = g^-1 p and A = [d_0 g v .. d_3 g v] (Hamilton's dp/dl is A^T v / 2).
struct RayTerms {
    Mat4 gInverse;
    Vec4 v;
    Mat4 A;
    RayTerms(const MetricJet& jet, const Vec4& p);
};

// M of the linearised Hamilton equations d(dx, dp)/dl = M (dx, dp) for H = 1/2 p g^-1 p, with
// H_mk = v . d_m d_k g v:
//   d(dx)/dl = -g^-1 A dx + g^-1 dp,   d(dp)/dl = (H/2 - A^T g^-1 A) dx + A^T g^-1 dp.
Mat8 linearisedHamiltonFlow(const MetricJet& jet, const RayTerms& t);

// The deviations at the observer of two unit turns of the viewing direction, along the frame
// directions s1 and s2 (orthogonal to it): no displacement, and the momentum's change
// scale g (s_a . e) (scale: the factor the traced momentum was multiplied by).
DeviationPair viewTurns(const Mat4& g, const LocalFrame& frame, const Vec3& s1, const Vec3& s2, double scale = 1);

// Two unit frame directions completing the viewing direction n to a right-handed screen
// (s1, s2 = n x s1): s1 along `right` made orthogonal to n (along `up` where n is along right).
std::pair<Vec3, Vec3> screenAxes(const Vec3& n, const Vec3& right, const Vec3& up);

// The change of a vector parallel transported along the ray: dE/dl = T E with T = -Gamma(v, .),
// T = -1/2 g^-1 (d_v g + A - A^T) (d_v g = v^k d_k g).
Mat4 parallelTransport(const MetricJet& jet, const RayTerms& t);

// The lever of TraceOptions::escapeLever for bundles seen from `observer`: its distance from the
// field's centre (0 where the metric is not asymptotically flat).
double bundleEscapeLever(const Spacetime& spacetime, const Vec4& observer);

// The bundle's error per step relative to its size beside a tracer of these options: the square
// root of its tolerance (the bundle is a derivative of the ray's map).
double bundleTolerance(const TraceOptions& options);

class RayBundle {
public:
    // The bundle of the ray the observer (its frame, g there) sees along unit frame direction n,
    // from `start` (momentum `scale` times the unit-frequency one): its screen (s1 along `right`,
    // s2 = n x s1: screenAxes), the deviations of unit turns along them (viewTurns), and s1 as the
    // transported axis.
    static RayBundle alongView(const CurvatureProbe& probe, const LocalFrame& frame, const Mat4& g,
                               const PhasePoint& start, const Vec3& n, const Vec3& right, const Vec3& up, double scale,
                               double tolerance);
    // At the ray's start (the observer), with the deviations given (viewTurns) and the screen's
    // first axis as a chart vector (s1 . e), parallel transported along the ray as the reference
    // the image's rotation is measured against. `tolerance`: the error allowed per step relative
    // to the deviations' size.
    RayBundle(const CurvatureProbe& probe, const PhasePoint& start, const DeviationPair& deviations,
              const Vec4& screenAxis, double tolerance = 1e-4);
    // Carries the deviations over the tracer's accepted step from seg.l0 to `to` (seg.l0 < to <=
    // seg.l1): Runge-Kutta steps of the linear equations, extrapolated from the step and its two
    // halves (fifth order) and halved again where their error exceeds the tolerance, the ray between
    // taken from the step's dense output (M at the step's ends, middle and quarters: four jets a
    // step). The bundle must stand at seg.l0 (the previous call's `to`).
    void advance(const Segment& seg, double to);
    const DeviationPair& deviations() const { return deviations_; }
    // d/dl of the deviations where the bundle stands: the rows 0..3 are the changes of the ray's
    // tangent v = dx/dl.
    DeviationPair rates() const { return here_.flow * deviations_; }
    // The screen's first axis, parallel transported to where the bundle stands.
    const Vec4& screenAxis() const { return screenAxis_; }
    // The image's axes (s1, s2) in the observer's frame, as alongView chose them (zero otherwise).
    const std::pair<Vec3, Vec3>& screen() const { return screen_; }
    double affine() const { return affine_; }
    // Jets evaluated so far (the bundle's cost: about 20 metric evaluations each).
    std::size_t jets() const { return jets_; }

private:
    static constexpr int kMaxHalvings = 12;
    // The linear equations' matrices at one point of the ray.
    struct Node {
        Mat8 flow;       // of the deviations
        Mat4 transport;  // of the screen axis
    };
    Node nodeAt(const Segment& seg, double l) const;
    Node nodeAt(const PhasePoint& q) const;
    void carry(const Segment& seg, double a, const Node& middle, double b, const Node& end, int depth);

    const CurvatureProbe& probe_;
    DeviationPair deviations_;
    Vec4 screenAxis_;
    std::pair<Vec3, Vec3> screen_{Vec3::Zero(), Vec3::Zero()};
    Node here_;  // where the bundle stands
    double tolerance_;
    double affine_ = 0;
    mutable std::size_t jets_ = 0;
};

// The lensing of an image element, from the 2 x 2 map A from image angles to source angles (the
// identity without lensing): A = R(rotation) [(1 - kappa) I - shear (cos 2 phi, sin 2 phi;
// sin 2 phi, -cos 2 phi)].
struct LensingDistortion {
    double magnification = 0;  // 1 / det A; negative for an image of reversed parity
    double shear = 0;          // |gamma| >= 0
    double rotation = 0;       // radians, in (-pi/2, pi/2]
    static LensingDistortion of(const Eigen::Matrix2d& A);
};

// The axes (a1, a2 = normal x a1) the maps below are written on, on the plane normal to the unit
// `normal`: a1 along the bundle's transported screen axis made orthogonal to it.
std::pair<Vec3, Vec3> sourceAxes(const Vec3& normal, const RayBundle& bundle);

// A for a ray that escaped to a source at infinity: the change of the direction of its tangent
// (chart components, asymptotically Cartesian) per radian of image angle, written on the axes
// (a1, a2 = k x a1) orthogonal to its direction k, a1 along the transported screen axis.
Eigen::Matrix2d escapeDirectionMap(const RayBundle& bundle, const Vec4& v);

// A for a ray that met a source at x (a surface): the deviations moved along the ray onto the
// plane through x normal to the chart chord from the observer (the thin-lens source plane),
// written on its axes (a1 along the transported screen axis, a2 = c x a1) and divided by the
// chord's length, so that flat space gives the identity.
Eigen::Matrix2d sourcePlaneMap(const RayBundle& bundle, const Vec4& v, const Vec3& chord);

}  // namespace lc
