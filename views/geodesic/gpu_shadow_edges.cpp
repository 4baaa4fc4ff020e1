// SPDX-License-Identifier: BSD-3-Clause
#include "gpu_shadow_edges.hpp"

#include "vtkLightconeNumericImageRenderer.h"

#include "core/scene/frame_camera.hpp"

#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace lc::views {
namespace {

constexpr double kDeg = kPi / 180;

class StripEdges {
public:
    StripEdges(const Scene& scene, const GpuShadowEdgeOptions& o)
        : scene_(scene),
          frame_(observerFrame(scene)),
          options_(o),
          gpu_(vtkSmartPointer<vtkLightconeNumericImageRenderer>::New()) {
        if (o.stripPixels < 8 || o.passes < 1 || !(o.finestAngle > 0))
            throw std::invalid_argument("GPU shadow edges: at least 8 pixels, 1 pass and a positive finest angle");
        // A panorama strip: pixel k looks along the great circle at an angle linear in k, so one
        // strip spans the whole half circle from the axis to its antipode (shadows larger than a
        // hemisphere, as the CPU finder).
        scene_.camera.projection = Camera::Projection::Panorama;
        scene_.camera.width = o.stripPixels;
        scene_.camera.height = 1;
        scene_.camera.lookAt.reset();
        scene_.camera.fovXDeg = 180;
        scene_.camera.fovYDeg = 180.0 / o.stripPixels;
        // Rays that graze a photon orbit close to the horizon (r = 1.07 M at a = 0.998) must not
        // be stopped as captured: a narrower boundary margin and the tightest float tolerance.
        gpu_->SetHorizonEpsilon(o.horizonEpsilon);
        gpu_->SetTolerance(o.tolerance);
        gpu_->SetMaxSteps(o.maxSteps);
        gpu_->SetScene(scene_);  // one shader and window; each strip is a camera change
    }

    double edge(const Vec3& axis, const Vec3& towards) {
        double in = 0, out = kPi;
        for (int pass = 0; pass < options_.passes && out - in > options_.finestAngle; ++pass) {
            const double mid = 0.5 * (in + out), half = std::max(0.51 * (out - in), 0.5 * options_.finestAngle);
            // A panorama strip centred on the bracket: pixel k looks at mid + sx fov / 2.
            const Vec3 f = std::cos(mid) * axis + std::sin(mid) * towards;
            const Vec3 right = std::cos(mid) * towards - std::sin(mid) * axis;
            const Vec3 up = right.cross(f);
            Camera& cam = scene_.camera;
            cam.forward = chartVectorOf(*scene_.spacetime, frame_, f);
            cam.up = chartVectorOf(*scene_.spacetime, frame_, up);
            cam.fovXDeg = 2 * half / kDeg;
            cam.fovYDeg = std::max(1e-6, cam.fovXDeg / options_.stripPixels);
            gpu_->SetCamera(cam);
            const std::vector<int> ids = gpu_->RenderIds();
            auto angleOf = [&](int k) { return mid + (2.0 * (k + 0.5) / options_.stripPixels - 1) * half; };
            const int n = options_.stripPixels;
            // Scan from the last pixel at or before the bracket's inner end: the widened strip
            // starts a little before it (on the far side of the axis in the first pass, which may
            // lie outside the shadow when the shadow is small).
            int k = 0;
            while (k + 1 < n && angleOf(k + 1) <= in) ++k;
            // Inside: a black hole's horizon, or a wormhole's throat (the far side).
            const auto inside = [&](int q) {
                const int id = ids[static_cast<std::size_t>(q)];
                return id == vtkLightconeNumericImageRenderer::Horizon ||
                       id == vtkLightconeNumericImageRenderer::OtherEnd;
            };
            if (pass == 0 && !inside(k))
                throw std::invalid_argument(
                    "the camera's forward ray does not fall into the hole: point it at the shadow");
            const int first = k;
            while (k < n && inside(k)) ++k;
            if (k == n) {
                in = angleOf(n - 1);  // the whole strip falls in: the edge lies beyond it
                out = std::max(out, in + options_.finestAngle);
                continue;
            }
            if (k == first) {  // the strip escapes from its inner end on: the edge lies before it
                out = std::max(in + options_.finestAngle, angleOf(k));
                continue;
            }
            in = std::max(0.0, angleOf(k - 1));
            out = angleOf(k);
        }
        return 0.5 * (in + out);
    }

private:
    Scene scene_;
    LocalFrame frame_;
    GpuShadowEdgeOptions options_;
    vtkSmartPointer<vtkLightconeNumericImageRenderer> gpu_;
};

}  // namespace

ShadowEdgeFinder gpuShadowEdges(const Scene& scene, const GpuShadowEdgeOptions& options) {
    auto strips = std::make_shared<StripEdges>(scene, options);
    return [strips](const Vec3& axis, const Vec3& towards) { return strips->edge(axis, towards); };
}

}  // namespace lc::views
