// SPDX-License-Identifier: BSD-3-Clause
#include "core/curvature/ray_bundle.hpp"

#include <algorithm>
#include <cmath>

namespace lc {

RayTerms::RayTerms(const MetricJet& jet, const Vec4& p) : gInverse(jet.g.inverse()), v(gInverse * p) {
    for (int k = 0; k < 4; ++k) A.col(k) = jet.dg[k] * v;
}

Mat8 linearisedHamiltonFlow(const MetricJet& jet, const RayTerms& t) {
    Mat4 H;
    for (int m = 0; m < 4; ++m)
        for (int k = 0; k < 4; ++k) H(m, k) = t.v.dot(jet.ddg[m][k] * t.v);
    const Mat4 giA = t.gInverse * t.A;
    Mat8 M;
    M.topLeftCorner<4, 4>() = -giA;
    M.topRightCorner<4, 4>() = t.gInverse;
    M.bottomLeftCorner<4, 4>() = 0.5 * H - t.A.transpose() * giA;
    M.bottomRightCorner<4, 4>() = t.A.transpose() * t.gInverse;
    return M;
}

DeviationPair viewTurns(const Mat4& g, const LocalFrame& frame, const Vec3& s1, const Vec3& s2, double scale) {
    // A unit turn of n along s changes k = -e0 + n.e by s.e: dp = g (s.e), dx = 0.
    auto turn = [&](const Vec3& s) { return Vec4(scale * (g * frame.spatialVector(s))); };
    DeviationPair d = DeviationPair::Zero();
    d.block<4, 1>(4, 0) = turn(s1);
    d.block<4, 1>(4, 1) = turn(s2);
    return d;
}

std::pair<Vec3, Vec3> screenAxes(const Vec3& n, const Vec3& right, const Vec3& up) {
    Vec3 s1 = right - right.dot(n) * n;
    if (s1.norm() < 1e-6) s1 = up - up.dot(n) * n;
    s1.normalize();
    return {s1, n.cross(s1)};
}

Mat4 parallelTransport(const MetricJet& jet, const RayTerms& t) {
    Mat4 alongV = Mat4::Zero();
    for (int k = 0; k < 4; ++k) alongV += t.v(k) * jet.dg[k];
    return -0.5 * t.gInverse * (alongV + t.A - t.A.transpose());
}

double bundleEscapeLever(const Spacetime& spacetime, const Vec4& observer) {
    return spacetime.asymptoticallyFlat() ? (observer.tail<3>() - spacetime.farField(observer).centre).norm() : 0;
}

double bundleTolerance(const TraceOptions& options) { return std::sqrt(options.absTol + options.relTol); }

RayBundle RayBundle::alongView(const CurvatureProbe& probe, const LocalFrame& frame, const Mat4& g,
                               const PhasePoint& start, const Vec3& n, const Vec3& right, const Vec3& up, double scale,
                               double tolerance) {
    const auto [s1, s2] = screenAxes(n, right, up);
    RayBundle bundle(probe, start, viewTurns(g, frame, s1, s2, scale), frame.spatialVector(s1), tolerance);
    bundle.screen_ = {s1, s2};
    return bundle;
}

RayBundle::RayBundle(const CurvatureProbe& probe, const PhasePoint& start, const DeviationPair& deviations,
                     const Vec4& screenAxis, double tolerance)
    : probe_(probe), deviations_(deviations), screenAxis_(screenAxis), here_(nodeAt(start)), tolerance_(tolerance) {}

RayBundle::Node RayBundle::nodeAt(const PhasePoint& q) const {
    ++jets_;
    const MetricJet jet = probe_.jet(q.x);
    const RayTerms terms(jet, q.p);
    return {linearisedHamiltonFlow(jet, terms), parallelTransport(jet, terms)};
}

RayBundle::Node RayBundle::nodeAt(const Segment& seg, double l) const {
    return nodeAt(l == seg.l1 ? seg.s1 : seg.at(l));
}

void RayBundle::advance(const Segment& seg, double to) {
    carry(seg, affine_, nodeAt(seg, 0.5 * (affine_ + to)), to, nodeAt(seg, to), 0);
}

namespace {

// The classical fourth-order Runge-Kutta step of a linear system dY/dl = M(l) Y over h, with M at
// its start, middle and end.
template <class Matrix, class State>
State rungeKutta4(const Matrix& start, const Matrix& middle, const Matrix& end, const State& y, double h) {
    const State k1 = start * y;
    const State k2 = middle * (y + 0.5 * h * k1);
    const State k3 = middle * (y + 0.5 * h * k2);
    const State k4 = end * (y + h * k3);
    return y + (h / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
}

// One step and its two halves (the quarters' matrices between), extrapolated (Richardson): the
// halves plus (halves - whole) / 15, with that correction, their error, returned beside.
template <class Matrix, class State>
std::pair<State, State> extrapolatedStep(const Matrix& start, const Matrix& firstQuarter, const Matrix& middle,
                                         const Matrix& lastQuarter, const Matrix& end, const State& y, double h) {
    const State whole = rungeKutta4(start, middle, end, y, h);
    const State halves =
        rungeKutta4(middle, lastQuarter, end, rungeKutta4(start, firstQuarter, middle, y, 0.5 * h), 0.5 * h);
    const State error = (halves - whole) / 15;
    return {halves + error, error};
}

}  // namespace

// From a to b with the matrices known at a (here_), the middle and b: the step extrapolated from
// its halves (fifth order). Where the halves' error exceeds the tolerance (displacements, momenta
// and the screen axis each on their own scale: a bundle's width grows with the distance, its
// momenta stay of order one) the two halves are carried the same way, their quarters now known.
void RayBundle::carry(const Segment& seg, double a, const Node& middle, double b, const Node& end, int depth) {
    const double h = b - a, m = a + 0.5 * h;
    const Node first = nodeAt(seg, a + 0.25 * h), last = nodeAt(seg, a + 0.75 * h);
    const auto [deviations, deviationError] =
        extrapolatedStep(here_.flow, first.flow, middle.flow, last.flow, end.flow, deviations_, h);
    const auto [axis, axisError] = extrapolatedStep(here_.transport, first.transport, middle.transport, last.transport,
                                                    end.transport, screenAxis_, h);
    auto relative = [&](int row) {
        const double size = std::max(deviations_.middleRows<4>(row).norm(), deviations.middleRows<4>(row).norm());
        return size > 0 ? deviationError.middleRows<4>(row).norm() / size : 0.0;
    };
    const double error = std::max({relative(0), relative(4), axisError.norm() / std::max(axis.norm(), 1e-300)});
    if (error <= tolerance_ || depth >= kMaxHalvings) {
        deviations_ = deviations;
        screenAxis_ = axis;
        here_ = end;
        affine_ = b;
        return;
    }
    carry(seg, a, first, m, middle, depth + 1);
    carry(seg, m, last, b, end, depth + 1);
}

LensingDistortion LensingDistortion::of(const Eigen::Matrix2d& A) {
    LensingDistortion d;
    const double det = A.determinant();
    // A caustic (det A = 0) would give an infinite magnification: held to a large finite one.
    d.magnification = std::abs(det) > 1e-30 ? 1 / det : std::copysign(1e30, det);
    // A = R(w) S with S symmetric: tan w = (A10 - A01) / (A00 + A11), taken modulo pi (a half
    // turn is S's sign).
    double w = std::atan2(A(1, 0) - A(0, 1), A(0, 0) + A(1, 1));
    if (w > 0.5 * kPi) w -= kPi;
    if (w <= -0.5 * kPi) w += kPi;
    d.rotation = w;
    const Eigen::Matrix2d S = Eigen::Rotation2Dd(-w).toRotationMatrix() * A;
    d.shear = 0.5 * std::hypot(S(0, 0) - S(1, 1), S(0, 1) + S(1, 0));
    return d;
}

std::pair<Vec3, Vec3> sourceAxes(const Vec3& normal, const RayBundle& bundle) {
    const Vec3 reference = bundle.screenAxis().tail<3>();
    Vec3 a1 = reference - reference.dot(normal) * normal;
    if (a1.norm() < 1e-9 * reference.norm()) a1 = normal.unitOrthogonal();
    a1.normalize();
    return {a1, normal.cross(a1)};
}

Eigen::Matrix2d escapeDirectionMap(const RayBundle& bundle, const Vec4& v) {
    const Vec3 vs = v.tail<3>();
    const double speed = vs.norm();
    const Vec3 k = vs / speed;
    const auto [a1, a2] = sourceAxes(k, bundle);
    const DeviationPair rates = bundle.rates();
    Eigen::Matrix2d A;
    for (int c = 0; c < 2; ++c) {
        // The direction's change: the tangent's change without its part along k, over |v|.
        const Vec3 dk = rates.block<3, 1>(1, c) / speed;
        A(0, c) = a1.dot(dk);
        A(1, c) = a2.dot(dk);
    }
    return A;
}

Eigen::Matrix2d sourcePlaneMap(const RayBundle& bundle, const Vec4& v, const Vec3& chord) {
    const double distance = chord.norm();
    const Vec3 c = chord / distance, vs = v.tail<3>();
    const auto [a1, a2] = sourceAxes(c, bundle);
    Eigen::Matrix2d A;
    for (int col = 0; col < 2; ++col) {
        const Vec3 dx = bundle.deviations().block<3, 1>(1, col);
        // Moved along the ray (dx + s v) until it lies in the plane: c . (dx + s v) = 0.
        const Vec3 onPlane = dx - (c.dot(dx) / c.dot(vs)) * vs;
        A(0, col) = a1.dot(onPlane) / distance;
        A(1, col) = a2.dot(onPlane) / distance;
    }
    return A;
}

}  // namespace lc
