// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Scenes in flat spacetime whose objects move at constant velocity: rendered by local ray
// tracing of triangles in each object's rest frame (seed 003), with Doppler-shifted Planck
// colours. The result is both colour and the per-pixel record.
#include "core/render/render.hpp"
#include "core/sr/renderer.hpp"

namespace lc {

// An image with its per-pixel records (object, frequency ratio, depth, emission time).
struct ColouredImage {
    RenderResult records;
    std::vector<float> rgb;  // linear RGB, row 0 on top (SR: its display colours, decoded)
};

// A flat-spacetime lc::Scene as the special-relativity renderers' input: each object in its
// rest frame (constant velocity or rest), the first light, the scene's camera at the observer.
// Throws for what SR cannot draw (moving observer, free fall, world lines).
struct SrSceneAndCamera {
    sr::SrScene scene;
    sr::ObserverCamera camera;
};
SrSceneAndCamera toSpecialRelativity(const Scene& scene);

// True for the 'minkowski' metric: every object at rest or at constant velocity.
bool isSrScene(const Scene& scene);
ColouredImage renderSrImage(const Scene& scene, bool polygonDistortion = false);

// Any scene as `lightcone render` and the GUI make it: local ray tracing for special-relativity
// scenes, render() and shadePixels() for the rest. `progress` may throw RenderCancelled (the SR
// renderer reports only its end).
// `prebuiltPhotoScene`: see render().
ColouredImage renderColouredImage(const Scene& scene, const ProgressCallback& progress = {},
                                  bool polygonDistortion = false,
                                  const std::vector<PhotoSceneObject>* prebuiltPhotoScene = nullptr);

}  // namespace lc
