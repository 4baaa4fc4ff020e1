// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The Jacobi map of a light ray (docs/PHYSICS.md section 13): how a thin bundle of rays around it
// spreads, from the variational equations of Hamilton's flow integrated beside the ray with exact
// second derivatives of the metric (core/curvature's jet). Two deviation vectors start at the
// observer with no displacement and the momentum change of a unit turn of the viewing direction
// along the two screen axes; where the ray meets a source plane their displacements, moved along
// the ray onto the plane, form the 2 x 2 map D from image angles to source-plane positions. For a
// source plane at flat distance D_s, the image's magnification is mu = D_s^2 / det D (signed: a
// negative mu is an image of reversed parity).
#include "core/curvature/curvature.hpp"
#include "core/spacetime/frame.hpp"

#include <array>

namespace lc {

struct JacobiRayOptions {
    double tolerance = 1e-12;  // dopri5's absolute and relative error per step
    double maxAffine = 1e12;
    std::size_t maxSteps = 1000000;
};

// A plane of the chart's spatial coordinates: the points y with normal . (y - point) = 0.
struct SourcePlane {
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitX();
};

struct JacobiRayResult {
    bool reached = false;   // the ray met the plane (else it stopped at maxAffine or maxSteps)
    Vec4 x = Vec4::Zero();  // where it met it
    Vec4 p = Vec4::Zero();
    double affine = 0;  // from the observer, in units of the observed frequency (|dx/dl| = 1 far away)
    Eigen::Matrix2d map = Eigen::Matrix2d::Zero();  // D: source-plane displacement per radian of image angle
    Vec3 screenAxes[2];  // the plane's axes the map's rows are written in (orthonormal, chart)
    std::size_t steps = 0;
    double magnification(double sourceDistance) const { return sourceDistance * sourceDistance / map.determinant(); }
};

// The past-directed ray the observer sees along frame direction n, with its Jacobi map at `plane`.
// The screen axes s1, s2 are the frame directions orthonormal to n (s1 along the frame's e3 x n,
// or e2 x n when n is along e3). Throws std::invalid_argument when the metric has no expressions.
JacobiRayResult traceJacobiRay(const Spacetime& spacetime, const LocalFrame& observer, const Vec3& direction,
                               const SourcePlane& plane, const JacobiRayOptions& options = {});

}  // namespace lc
