#pragma once
// Scenes in flat spacetime whose objects move at constant velocity: rendered by local ray
// tracing of triangles in each object's rest frame (seed 003), with Doppler-shifted Planck
// colours. The result is both colour and the per-pixel record.
#include "core/render.hpp"
#include "core/sr/renderer.hpp"

namespace lc {

struct SpecialRelativityResult {
    RenderResult records;    // object, frequency ratio (Doppler D), depth, emission time
    std::vector<float> rgb;  // linear RGB (the SR renderer's display colours, decoded)
};

// A flat-spacetime lc::Scene as the special-relativity renderers' input: each object in its
// rest frame (constant velocity or rest), the first light, the pinhole camera at the observer.
// Throws for what SR cannot draw (moving observer, panorama, free fall, world lines).
struct SrSceneAndCamera {
    sr::SrScene scene;
    sr::PinholeCamera camera;
};
SrSceneAndCamera toSpecialRelativity(const Scene& scene);

// True for the 'minkowski' metric: every object at rest or at constant velocity.
bool isSpecialRelativityScene(const Scene& scene);
SpecialRelativityResult renderSpecialRelativity(const Scene& scene, bool polygonDistortion = false);

}  // namespace lc
