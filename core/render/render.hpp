// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// CPU reference renderer (seed 000 section 4, the "4D ray tracing" baseline of seed 001):
// per pixel the past-directed null geodesic is traced and its 4D segments are intersected
// with the scene. The result is per-pixel data, not colour, so that textures, colour maps and
// time windows can be changed afterwards without re-tracing ("render once, explore after").
#include "core/render/post_render.hpp"
#include "core/scene/scene.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>

namespace lc {

struct PhotoSceneObject;  // core/render/photo_scene.hpp
struct PostRender;        // core/render/post_render.hpp

struct PixelRecord {
    // Disk: an accretion disk (Scene::disks[object]); u = phi / 2 pi, v = (r - r_in) / (r_out - r_in).
    enum Kind : std::int8_t { Background = 0, Object = 1, Sky = 2, Horizon = 3, Failed = 4, Disk = 5 };
    std::int8_t kind = Background;
    std::int8_t stopReason = 0;  // StopReason of the ray
    std::int16_t object = -1;    // index into Scene::spheres
    float u = 0, v = 0;          // texture coordinates on the object, or sky direction
    // nu_observed / nu_emitted: an object's or disk's emitter; for sky pixels (numeric tracer) a
    // source at rest at infinity, (-p.u_obs) / (-p_t); 0 on horizon pixels (no light); 1 elsewhere.
    float frequencyRatio = 1;
    float emissionTime = 0;  // coordinate time of the emission event
    float affine = 0;        // affine length from the observer (depth)
    float drift = 0;         // |H| reached on this ray
    float steps = 0;
    float light[3] = {1, 1, 1};  // linear RGB light at the hit point (1: unlit scene, texture as is)
    // Disk pixels: the emission's Boyer-Lindquist radius, the observed bolometric intensity
    // g^4 F(r) / F_max (1: the hottest ring seen without shift) and the image order (how often the
    // ray crossed the equatorial plane before it met the disk: 0 direct, 1 secondary, ...).
    float diskRadius = 0;
    float intensity = 0;
    std::int8_t order = 0;
    // Sky pixels: the asymptotic end the ray reached, 0 this one, 1 a two-ended metric's other
    // (a wormhole's far side, drawn with Scene::otherSky).
    std::int8_t end = 0;
    std::int8_t unused[2] = {0, 0};  // no padding left undefined: records compare and travel byte for byte
    // Renders with RenderSettings::magnification, sky pixels (a source at infinity) and object and
    // disk pixels (a source on the thin-lens plane through the hit): the image element's
    // magnification (negative: reversed parity), shear |gamma| and rotation (radians) from the
    // ray's Jacobi map (core/curvature/ray_bundle, docs/PHYSICS.md section 13a). 0 elsewhere.
    float magnification = 0, shear = 0, rotation = 0;
};

struct RenderStats {
    double seconds = 0;
    double worstDrift = 0;
    double meanSteps = 0;
    std::size_t rays = 0;
    std::size_t hits = 0;
    std::array<std::size_t, 9> stopCounts{};  // by StopReason
    // Numeric renders of a whole image with a sky (core/render/error_estimate): the escape
    // directions' estimated error in pixels over the sampled rays; errorRays = 0 when none.
    int errorRays = 0;
    double errorMaxPixels = 0, errorMedianPixels = 0, errorTighterTolerance = 0;
};

struct RenderResult {
    int width = 0, height = 0;
    std::vector<PixelRecord> pixels;
    bool lensing = false;  // the pixels carry magnification, shear and rotation (RenderSettings::magnification)
    RenderStats stats;
};

// Called with the fraction of rows done, from inside the render loop (one thread). To stop a
// render (a GUI's Cancel), throw RenderCancelled from it: the renderers finish at most the rows
// being traced and rethrow it to the caller.
using ProgressCallback = std::function<void(double fraction)>;
struct RenderCancelled : std::runtime_error {
    RenderCancelled() : std::runtime_error("render cancelled") {}
};

// Shared by the renderers: an empty result of the camera's size, the thread count to use,
// and the statistics of a finished result (time since t0).
RenderResult blankResult(const Camera& camera);
int renderThreads(const RenderSettings& settings);
// The rows to trace (RenderSettings::rowBegin/rowEnd inside the camera); throws when the band is empty
// or outside the image.
struct RowBand {
    int begin = 0, end = 0;
    int rows() const { return end - begin; }
};
RowBand rowsToTrace(const RenderSettings& settings, const Camera& camera);
// Statistics over the rows of `band` (all rows when not given).
void summarise(RenderResult& result, std::chrono::steady_clock::time_point t0);
void summarise(RenderResult& result, std::chrono::steady_clock::time_point t0, const RowBand& band);

// Throws naming the first object that the per-pixel tracers cannot draw (meshes, moving objects).
void requireStaticSpheres(const Scene& scene, const std::string& who);

// The numeric tracer's options for a scene: the file's and command line's, with what they leave
// open chosen from the scene (escape beyond every object, the escape direction to 1/100 of a
// pixel, steps no longer than half an object's radius).
TraceOptions traceOptionsFor(const Scene& scene);

// The numeric path: works for every metric.
RenderResult renderNumeric(const Scene& scene, const ProgressCallback& progress = {});

// Sky texture coordinates of a unit escape direction: u = 1/2 + atan2(y, x) / 2 pi (across),
// v = acos(z) / pi (v = 0 at the north pole).
void toSkyUv(const Vec3& direction, float& u, float& v);

// Goedel only, static observer anywhere: closed-form null geodesics, no ODE.
RenderResult renderGodelClosedForm(const Scene& scene, const ProgressCallback& progress = {});

// Goedel only, static observer anywhere: every vertex of a tessellated sphere gets its images
// from the inverse problem and each (winding, branch) layer is rasterised (seed 001 section 6).
// vertexSeconds, if given, receives the time of the vertex-image step alone.
// `prebuilt`: photo-objects already built for this scene with these latitudes and longitudes
// (e.g. for the shader renderer), drawn instead of building them again.
RenderResult renderGodelPerVertex(const Scene& scene, int latitudes = 100, int longitudes = 200,
                                  double* vertexSeconds = nullptr, const ProgressCallback& progress = {},
                                  const std::vector<PhotoSceneObject>* prebuilt = nullptr);

// Chooses by scene.settings.method (Auto resolved by resolveMethod).
RenderSettings::Method resolveMethod(const Scene& scene);
// "auto", "numeric", "closed_form", "per_vertex"; throws listing them.
RenderSettings::Method parseRenderMethod(const std::string& name);
std::string renderMethodName(RenderSettings::Method m);
// The pixel kinds by code ("background", "object", "sky", "horizon", "failed", "disk"): the
// names Python's lightcone.PixelKind and docs/SCENES.md's table of pixel codes use.
const std::vector<std::string>& pixelKindNames();
// `prebuiltPhotoScene`: see renderGodelPerVertex (photoSceneOptions(scene)); other methods ignore it.
RenderResult render(const Scene& scene, const ProgressCallback& progress = {},
                    const std::vector<PhotoSceneObject>* prebuiltPhotoScene = nullptr);

// Colour from per-pixel data (linear RGB): texture lookups only, no tracing. `post` changes
// textures, temperature and time window afterwards (core/render/post_render.hpp).
std::vector<float> shadePixels(const Scene& scene, const RenderResult& r);
std::vector<float> shadePixels(const Scene& scene, const RenderResult& r, const PostRender& post);

// What an object pixel's colour starts from, before the time window, blinking and lighting: its
// texture's colour (shifted, scaled or chosen anew) or its black body's at D T, and its night
// texture's (lit scenes with one).
struct ObjectPixelSamples {
    Vec3 own = Vec3::Zero();
    Vec3 night = Vec3::Zero();
};

// shadePixels for many settings of one render (a `shade --sweep`, a slider), the same image bit
// for bit: the pixels no setting changes (sky, horizon, background) are coloured once and kept in
// the shader's frame; each call colours the objects' and disks' pixels again on every core, and
// looks up their textures and black bodies again only when the settings those depend on changed
// since the previous call (a time-window or blinking sweep reuses them).
class PixelShader {
public:
    // Keeps references: the scene and the data must outlive it.
    PixelShader(const Scene& scene, const RenderResult& data);
    // The frame for `post`, linear RGB; valid until the next call (one caller at a time).
    const std::vector<float>& shade(const PostRender& post);
    // Whether a setting can change the pixel's colour (an object's or a disk's pixel).
    static bool settingsChange(const PixelRecord& px) {
        return px.kind == PixelRecord::Object || px.kind == PixelRecord::Disk;
    }

private:
    const Scene& scene_;
    const RenderResult& data_;
    std::vector<float> frame_;                       // the last frame (at first shadePixels')
    std::vector<std::size_t> objects_, disks_;       // the pixels a setting may change, by kind
    std::vector<ObjectPixelSamples> objectSamples_;  // per object pixel, under last_'s textures
    std::vector<Vec3> diskLight_;                    // per disk pixel, under last_'s temperature
    std::vector<double> diskFactor_;                 // per disk pixel, its diskTemperatureFactor
    std::optional<PostRender> last_;
};

}  // namespace lc
