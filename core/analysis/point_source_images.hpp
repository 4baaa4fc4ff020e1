// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every image of a point source at infinity that the observer's camera sees, with its
// magnification (docs/PHYSICS.md section 13b): the escape directions of a grid of camera rays give
// seeds (where they come nearest the source), and Newton's method refines each, the ray bundle's
// map A (image angles to source angles, core/curvature/ray_bundle) as its Jacobian, until the ray
// escapes towards the source. The images' magnifications add up to what a detector that does not
// resolve them receives (microlensing's light curve).
#include "core/scene/scene.hpp"

#include <vector>

namespace lc {

struct PointSourceImage {
    Vec3 direction = Vec3::Zero();  // unit, in the observer's frame (as Camera::direction)
    double magnification = 0;       // signed: negative for a mirrored image
    double residual = 0;            // angle between the image ray's escape direction and the source, rad
};

struct PointSourceImages {
    std::vector<PointSourceImage> images;  // brightest first
    double totalMagnification() const;     // sum of |mu|: the unresolved images' flux over the unlensed
    double signedMagnification() const;    // sum of mu (1 for a point lens: Schneider et al. 1992, eq. 2.25)
};

struct PointSourceOptions {
    int seedColumns = 96;  // the seeds' grid over the camera's view (rows: half as many)
    // An image is converged when its ray escapes this close to the source (rad), and no closer than
    // 10 times the tracer's tolerance (absTol + relTol): its escape directions are no better.
    double angleTolerance = 1e-11;
};

// The images inside the camera's view of a source at infinity in chart direction `source`
// (asymptotically flat metrics written as expressions; the scene's tracer settings). Throws
// std::invalid_argument otherwise.
PointSourceImages findPointSourceImages(const Scene& scene, const Vec3& source, const PointSourceOptions& options = {});

}  // namespace lc
