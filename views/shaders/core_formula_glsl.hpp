// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The core formulas the shaders call, generated from their C++ templates (core/codegen's
// functionGlsl on codegen::Expr), so that the GPU runs the formula the CPU runs: no hand copy.
#include "core/codegen/expression.hpp"

#include <string>

namespace lc::views {

// vec2 lcSkyUv(vec3 d): lc::skyUv (core/scene/sky.hpp); calls lcAtan2 (glsl/atan2_finite).
std::string skyUvGlsl();
// vec3 lcOtherEndDirection(vec3 x, vec3 k): a two-ended metric's far-side direction (lc::inversionReflected).
std::string otherEndDirectionGlsl();
// float lcBesselJ0(float x) and float lcBesselJ1(float x): lc::besselJ0Approximation and
// lc::besselJ1Approximation (core/numerics/bessel.hpp), which generated metrics call.
std::string besselGlsl();
// vec3 lcSrgbDecode(vec3 e): lc::colour::srgbToLinear per channel (core/colour/srgb.hpp).
std::string srgbDecodeGlsl();
// vec3 lcAberrateToRest(vec3 beta, vec3 k): lc::sr::boostDirection(-beta, k), k a unit vector
// (core/sr/doppler.hpp).
std::string aberrationGlsl();
// vec3 lcBoostDirection(vec3 u, vec3 k) and float lcRestRayDoppler(vec3 beta, vec3 d):
// lc::sr::boostDirection and lc::sr::restRayDoppler, the rest-frame ray of lc::sr::makeRestRay.
std::string restRayGlsl();
// vec3 lcDayNight(vec3 day, vec3 night, vec3 lit): lc::dayNightLit (core/scene/scene.hpp), lit =
// the light with its ambient part.
std::string dayNightGlsl();
// vec2 lcScreenCoordinates(float x, float yDown, float width, float height),
// vec3 lcPinholeScreenDirection(float sx, float sy, float tx, float ty, vec3 f, vec3 r, vec3 u) and
// vec3 lcPanoramaScreenDirection(float sx, float sy, float hx, float hy, vec3 f, vec3 r, vec3 u):
// lc::screenCoordinates, lc::pinholeScreenDirection and lc::panoramaScreenDirection
// (core/scene/camera.hpp), which glsl/camera_direction calls.
std::string cameraDirectionsGlsl();
// vec4 lcPastNullMomentum(vec3 n, vec4 e0, vec4 e1, vec4 e2, vec4 e3, vec4 g0, vec4 g1, vec4 g2,
// vec4 g3): lc::pastNullMomentumAlong (core/spacetime/frame.hpp), g0..g3 the rows of the metric;
// glsl/geodesic_trace launches its rays with it.
std::string pastNullMomentumGlsl();
// float lcPlanckSampleIndex(float T, float tMin, float tMax, float samples):
// lc::colour::blackbodySampleIndex (core/colour/blackbody.hpp), followed by glsl/planck_lookup
// (the texture lookup that calls it): the whole Planck lookup of the shaders.
std::string planckLookupGlsl();
// vec2 lcTexelPosition(vec2 uv, vec2 size), vec2 lcTexelIndex(vec2 xy, vec2 size) and vec3
// lcBilinear(vec3 c00, vec3 c10, vec3 c01, vec3 c11, vec2 f): lc::texelPosition, lc::texelIndex and
// lc::bilinear (core/scene/texture.hpp, ImageTexture::sample), which glsl/texture_atlas calls.
std::string textureSampleGlsl();
// vec3 lcPinholeHomogeneous(vec3 d, vec3 f, vec3 r, vec3 u, float tanHalfX, float tanHalfY) and
// vec2 lcPanoramaScreen(vec3 d, vec3 f, vec3 r, vec3 u, float halfX, float halfY): the inverse,
// lc::pinholeHomogeneous and lc::panoramaScreen (core/scene/camera.hpp, Camera::project), with
// lcAtan2 (glsl/atan2_finite); glsl/godel_projection calls them.
std::string cameraProjectionGlsl();

// The post-rendering formulas (core/render/post_render.hpp) and the display encode:
// vec2 lcRetexturedUv(vec2 uv, vec2 offset, vec2 scale), float lcInsideTimeWindow(float t, vec2 w),
// float lcBlinkLevel(float t, vec4 blink) (period, duty, phase, off level),
// float lcShiftedTemperature(float d, float T) and vec3 lcSrgbEncodeDisplay(vec3 c).
std::string postRenderGlsl();

// float lcDiskRadius(vec4 X): the radius label of a chart event, `radius` (the metric's
// Spacetime::equatorialRadius), for glsl/geodesic_disk.
std::string diskRadiusGlsl(const codegen::Expr& radius);
// The thin disk's formulas for glsl/geodesic_disk: float lcKeplerianRedshift(vec4 x, vec4 p,
// float omega, float ut, float e) (lc::keplerianRedshift, core/accretion/thin_disk.hpp) and
// float lcDiskLocalTemperature(float peak, float intensity, float g) (lc::diskLocalTemperature,
// core/render/post_render.hpp).
std::string diskGlsl();

}  // namespace lc::views
