// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Post-rendering (seed 000 section 5.2, "render once, explore after"): an image coloured again
// from the per-pixel data of a render without tracing again. Three effects:
//   (a) re-texturing: another texture per object, its (u, v) offset and scaled (turn a sphere
//       about its axis by a u offset);
//   (b) frequency shift: every object a black body of temperature T, seen at D T (D = the pixel's
//       frequency ratio), Planck -> CIE XYZ -> sRGB;
//   (c) time shift: light emitted inside a window [t0, t1] of coordinate time shows the object's
//       texture, the rest a second texture (or nothing); time-dependent textures: lights that
//       blink together in coordinate time, seen blinking at their emission times.
// lc::shadePixels is the CPU reference; the GPU post-renderer (views/postrender/vtkLightconePostRenderer)
// calls the GLSL generated from the formulas below, which are written once over the scalar.
#include "core/numerics/select.hpp"
#include "core/scene/texture.hpp"

#include <Eigen/Core>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace lc {

struct Scene;
struct RenderResult;

struct PostRender {
    // (a) Per object (spheres first, then meshes): a texture in place of the scene's; a missing
    // or null entry keeps the scene's.
    std::vector<TexturePtr> objectTextures;
    double uOffset = 0, vOffset = 0, uScale = 1, vScale = 1;
    // (b) Every object a black body of this temperature (K) instead of the scene's.
    std::optional<double> temperature;
    // (c) Light emitted outside [t0, t1] shows `outsideTexture`; none: the background.
    std::optional<std::pair<double, double>> timeWindow;
    TexturePtr outsideTexture;
    // Blinking: every object lit during the first `blinkDuty` of each `blinkPeriod` of emission
    // time from `blinkPhase`, at `blinkOffLevel` of its colour otherwise; period 0: no blinking.
    double blinkPeriod = 0, blinkDuty = 0.5, blinkPhase = 0, blinkOffLevel = 0.1;
};

// Objects are numbered spheres first, then meshes (PixelRecord::object, PostRender::objectTextures).
std::size_t objectCount(const Scene& scene);
// The texture object k shows under `post`: the chosen one, or its own. References to the pointers
// the scene and `post` hold: per pixel, no reference count changes hands between threads.
const TexturePtr& shownTexture(const Scene& scene, const PostRender& post, std::size_t k);
// Object k's night texture (spheres only; null for none) and its own emitter temperature (0: none).
const TexturePtr& objectNightTexture(const Scene& scene, std::size_t k);
double objectTemperature(const Scene& scene, std::size_t k);

// The range of D T the shading clamps to (K): the span of the black-body table
// (colour::kStandardTableMinK and kStandardTableMaxK).
constexpr double kShadeMinTemperature = 500.0;
constexpr double kShadeMaxTemperature = 1e7;

// x - floor(x), in [0, 1).
template <class S>
S wrapToUnit(const S& x) {
    using std::floor;
    return x - floor(x);
}

// (a) An object's texture coordinates after the offset and scale: u wraps (around the sphere),
// v is clamped to the poles.
template <class S>
Eigen::Matrix<S, 2, 1> retexturedUv(const S& u, const S& v, const S& uOffset, const S& vOffset, const S& uScale,
                                    const S& vScale) {
    using std::max;
    using std::min;
    return {wrapToUnit(uScale * u + uOffset), min(max(vScale * v + vOffset, S(0.0)), S(1.0))};
}

// (c) 1 for an emission time inside [t0, t1] (ends included), 0 outside.
template <class S>
S insideTimeWindow(const S& t, const S& t0, const S& t1) {
    return ifPositive(t0 - t, S(0.0), ifPositive(t - t1, S(0.0), S(1.0)));
}

// (c) The brightness of a light blinking with `period` and `duty` from `phase`, seen in light
// emitted at time t: 1 while on, `offLevel` while off.
template <class S>
S blinkLevel(const S& t, const S& period, const S& duty, const S& phase, const S& offLevel) {
    return ifPositive(duty - wrapToUnit((t - phase) / period), S(1.0), offLevel);
}

// The frequency-shifted temperature D T, clamped to the range the Planck colour is defined in.
template <class S>
S shiftedTemperature(const S& frequencyRatio, const S& temperature) {
    using std::max;
    using std::min;
    return min(max(frequencyRatio * temperature, S(kShadeMinTemperature)), S(kShadeMaxTemperature));
}

// The brightness of black-body light seen with frequency ratio g: the bolometric intensity goes
// as g^4 (I / nu^3 invariant, nu^4 integrated), times the emitted brightness b.
template <class S>
S shiftedBrightness(const S& frequencyRatio, const S& brightness) {
    const S g2 = frequencyRatio * frequencyRatio;
    return g2 * g2 * brightness;
}

// An accretion disk's local temperature (core/accretion/thin_disk.hpp): the Page-Thorne black body
// has T proportional to F^(1/4), and a pixel stores g and the observed intensity g^4 F / F_max, so
// T = T_peak (intensity / g^4)^(1/4) without the flux again. The factor after T_peak depends on the
// pixel only: a temperature sweep computes it once (PixelShader).
template <class S>
S diskTemperatureFactor(const S& intensity, const S& frequencyRatio) {
    using std::max;
    using std::sqrt;
    const S g2 = max(frequencyRatio * frequencyRatio, S(1e-30));
    return sqrt(sqrt(max(intensity, S(0.0)) / (g2 * g2)));
}
template <class S>
S diskLocalTemperature(const S& peakTemperature, const S& intensity, const S& frequencyRatio) {
    return peakTemperature * diskTemperatureFactor(intensity, frequencyRatio);
}

// Object pixels whose emission time lies outside the window.
std::size_t countOutsideTimeWindow(const RenderResult& r, const std::pair<double, double>& window);

}  // namespace lc
