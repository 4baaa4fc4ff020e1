// SPDX-License-Identifier: BSD-3-Clause
#include "core/input/ranges.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace lc::input {

// clang-format off
const Range kCoordinate{"event coordinate (t, x, y, z)", -1e12, 1e12, false, "",
    "beyond this, double-precision steps and float emission times lose all resolution"};
const Range kGodelAxisDistance{"Goedel event distance from the axis r / a", 0, 1e4, false, "",
    "the isometry moving an event to the axis stays accurate to 1e-8 there; the horizon is at 2"};
const Range kObjects{"objects in a scene", 0, 4096, true, "", "per-pixel data stores the object as a 16-bit index"};
const Range kLights{"lights in a scene", 0, 256, true, "", "each light costs a shadow test per pixel"};
const Range kLength{"sphere radius, box edge", 1e-6, 1e6, false, "",
    "twelve decades around the metric's scale (M or a = 1)"};
const Range kDiskRadius{"disk inner and outer radius", 1, 1e5, false, "M",
    "Boyer-Lindquist r; the inner edge may not lie inside the ISCO, the flux table spans the disk in 768 nodes"};
const Range kScale{"mesh scale", 1e-6, 1e6, false, "", "as for lengths"};
const Range kBoxSubdivisions{"box subdivisions", 1, 512, true, "", "6 x 2 x 512^2 triangles is already 3 million"};
const Range kDirectionComponent{"camera forward/up component", -1e6, 1e6, false, "",
    "directions are normalised; larger values only invite overflow"};
const Range kAngle{"angle (phi0)", -1e6, 1e6, false, "rad", "any finite angle; larger values lose precision"};
const Range kObserverVelocityComponent{"observer velocity component", -1e6, 1e6, false, "",
    "a 4-velocity, normalised on reading"};
const Range kObserverGamma{"observer Lorentz factor", 1, 1e3, false, "",
    "relative to the static observer; at 0.9999995c the tracer still conserves H and the image is "
    "the aberrated forward cone, beyond it rays carry momenta the tolerance cannot resolve"};
const Range kSpeed{"object speed (norm of beta), free-fall speed", 0, 0.99999999, false, "c",
    "gamma up to 7071; the Doppler factor stays finite in single precision"};
const Range kFreeFallEnergy{"free-fall k0", 1, 1e4, false, "", "gamma of the fall, as for speeds"};
const Range kFreeFallK3{"free-fall k3", -1e4, 1e4, false, "", "and k3^2 <= k0^2 - 1"};
const Range kWorldLineEvents{"world-line events", 2, 1e6, true, "", "memory: 32 bytes an event"};
const Range kWorldLineSegments{"world-line segments", 1, 1000, true, "", "a trip of a few legs; each is evaluated in closed form"};
const Range kProperTimeSpan{"segment proper time", 1e-6, 1e6, false, "", "in the units of a, as lengths; a whole trip at most 1e6"};
const Range kCircleTurns{"circle turns", -1e4, 1e4, false, "", "signed (> 0: phi increasing); non-zero"};
const Range kCircleDtDphi{"circle dt/dphi", -1e6, 1e6, false, "", "coordinate time per radian; < 0 runs into the chart's past"};
const Range kRocketAcceleration{"rocket acceleration", 1e-6, 1e3, false, "1/a", "proper acceleration; 1e3 / a reaches gamma 1e3 within a / 1e3 of proper time"};
const Range kRocketBurnTime{"rocket burn proper time", 1e-6, 250, false, "", "a burn is integrated and kept at 4000 samples per unit (1e6 at 250); it may not pass gamma 7071, as for speeds"};
const Range kColourComponent{"colour component (linear RGB)", 0, 1e3, false, "",
    "high-dynamic-range colours up to 1000 x white"};
const Range kTemperature{"temperature (objects and lights)", 300, 1e6, false, "K",
    "the Planck table's span; Doppler shifts D T are clamped to it"};
const Range kSkyTemperature{"sky temperature (black-body sky)", 1, 1e6, false, "K",
    "down to the 2.725 K background; each pixel is drawn at g T, the Planck colour's reddest (500 K) below the table"};
const Range kLightIntensity{"light intensity", 1e-6, 1e6, false, "", "relative to 1 = full daylight"};
const Range kCheckerCells{"checker cells", 1, 4096, true, "", "more cells than texels is aliasing"};
const Range kStars{"stars in a star sky", 1, 1e6, true, "", "each is spread over the sky's map once, when the scene is read"};
const Range kStarSize{"star size (the Gaussian's standard deviation)", 0.18, 10, false, "deg",
    "the sky's map has two texels per star size: 4000 x 2000 (64 MB) at 0.18 degrees"};
const Range kStarMagnitude{"faintest star magnitude", 0, 15, false, "",
    "brightness 10^(-0.4 m) of the brightest; 15 is a millionth"};
const Range kStarSeed{"star sky seed", 0, 2147483647, true, "", "the random generator's seed"};
const Range kImageSide{"image width, height", 1, 16384, true, "px", "the largest OpenGL texture"};
const Range kImagePixels{"image pixels (width x height)", 1, 33554432, true, "px",
    "2^25 = 8192 x 4096: the per-pixel data then takes 1.5 GiB of the 24 GiB machines"};
const Range kFieldOfView{"field of view", 1e-8, 360, false, "deg", "pinhole below 180 degrees; down to 36 micro-arcseconds (a horizon-scale view from 8 kpc, or a fast observer's forward cone)"};
const Range kTolerance{"tolerance", 1e-15, 0.1, false, "", "below 1e-15 is below double rounding"};
const Range kWindings{"windings (Goedel)", 0, 1000, true, "", "each winding adds two images and 2 pi a of ray"};
const Range kMaxAffine{"max affine length", 1e-6, 1e15, false, "", "finite: every ray must end"};
const Range kEscapeRadius{"escape radius", 0, 1e12, false, "", "0 = automatic: outside every object"};
const Range kEscapeAngle{"escape angle", 1e-15, 3.2, false, "rad", "bending still allowed after escape; above pi: direction not needed"};
const Range kMaxSteps{"max steps", 1, 1e8, true, "", "a ray of 1e8 steps takes minutes"};
const Range kInitialStep{"initial step", 1e-12, 1e6, false, "", "adaptive steppers start here"};
const Range kThreads{"threads", 0, 256, true, "", "0 = all cores"};
const Range kMeshLatitudes{"sphere mesh latitudes", 3, 4096, true, "", "per-vertex tessellation"};
const Range kMeshLongitudes{"sphere mesh longitudes", 3, 8192, true, "", "per-vertex tessellation"};
const Range kMeshResolutionVertices{"sphere mesh vertices (latitudes x longitudes)", 9, 4194304, true, "",
    "2^22 vertices, each with its images for every winding"};
const Range kSceneFileBytes{"scene file size", 1, 67108864, true, "bytes", "64 MiB of JSON"};
const Range kMeshFileBytes{"mesh file size", 1, 2147483648.0, true, "bytes", "2 GiB"};
const Range kMeshVertices{"mesh vertices", 3, 16777216, true, "", "2^24, indices stay exact in float"};
const Range kMeshTriangles{"mesh triangles", 1, 33554432, true, "", "2^25"};
const Range kTextureFileBytes{"texture file size", 1, 1073741824, true, "bytes", "1 GiB"};
const Range kTexturePixels{"texture pixels", 1, 268435456, true, "px", "16384 x 16384, 3 GiB as floats"};
const Range kAnimationFrames{"frames (animate)", 1, 100000, true, "", "a 1000-frame movie a hundred times over"};
const Range kFrameIndex{"--frames (animate)", 0, 99999, true, "", "frame numbers start at 0"};
const Range kFramesPerSecond{"--fps", 1, 240, true, "", "the fastest common display rate"};
const Range kTurnDegrees{"--pan, --orbit", -36000, 36000, false, "deg", "a hundred turns"};
const Range kOrbitFrames{"--orbit-frames", 1, 3600, true, "", "a minute at 60 fps"};
const Range kRays{"--rays", 1, 720, true, "", "rays drawn in fans and cones: one every half degree"};
const Range kExportMegabytes{"--max-size (export)", 0, 1e6, false, "MB", "0: no limit; the default 500 MB is what ParaView opens at ease"};
const Range kDiagramSize{"--size (diagram)", 200, 8000, true, "px", "image height; the legend to the right of the square plot widens it"};
const Range kDiagramWindings{"--windings (diagram)", 0, 50, true, "", "beyond 50 loops the paths fill the disc"};
const Range kImpactParameter{"--impact", 0, 1e12, false, "", "as for coordinates"};
const Range kLaunchDistance{"--distance", 1, 1e12, false, "", "as for coordinates"};
const Range kUvOffset{"--uv-offset (shade)", -1e6, 1e6, false, "", "texture periods; u wraps, v is clamped to the poles"};
const Range kUvScale{"--uv-scale (shade)", -1e6, 1e6, false, "", "texture repeats per object; negative mirrors"};
const Range kBlinkPeriod{"--blink period (shade)", 1e-9, 1e12, false, "", "in coordinate time, as for coordinates"};
const Range kUnitFraction{"--blink duty, off level (shade)", 0, 1, false, "", "fractions of a period and of full brightness"};
const Range kGridSide{"--dims (curvature)", 1, 4096, true, "", "points per axis; all values together stay below 5e7"};
const Range kCosmologicalConstant{"--lambda (curvature)", -1e12, 1e12, false, "", "in 1/length^2, as for coordinates"};
const Range kTideSamples{"--samples (curvature)", 2, 100000, true, "", "points along the world line"};
const Range kOutlinePoints{"--outline-points (sweep)", 8, 100000, true, "", "edge points round the shadow's outline"};
// clang-format on

const std::vector<const Range*>& allRanges() {
    static const std::vector<const Range*> rows{&kCoordinate,
                                                &kGodelAxisDistance,
                                                &kObjects,
                                                &kLights,
                                                &kLength,
                                                &kDiskRadius,
                                                &kScale,
                                                &kBoxSubdivisions,
                                                &kDirectionComponent,
                                                &kAngle,
                                                &kObserverVelocityComponent,
                                                &kObserverGamma,
                                                &kSpeed,
                                                &kFreeFallEnergy,
                                                &kFreeFallK3,
                                                &kWorldLineEvents,
                                                &kWorldLineSegments,
                                                &kProperTimeSpan,
                                                &kCircleTurns,
                                                &kCircleDtDphi,
                                                &kRocketAcceleration,
                                                &kRocketBurnTime,
                                                &kColourComponent,
                                                &kTemperature,
                                                &kSkyTemperature,
                                                &kLightIntensity,
                                                &kCheckerCells,
                                                &kStars,
                                                &kStarSize,
                                                &kStarMagnitude,
                                                &kStarSeed,
                                                &kImageSide,
                                                &kImagePixels,
                                                &kFieldOfView,
                                                &kTolerance,
                                                &kWindings,
                                                &kMaxAffine,
                                                &kEscapeRadius,
                                                &kEscapeAngle,
                                                &kMaxSteps,
                                                &kInitialStep,
                                                &kThreads,
                                                &kMeshLatitudes,
                                                &kMeshLongitudes,
                                                &kMeshResolutionVertices,
                                                &kSceneFileBytes,
                                                &kMeshFileBytes,
                                                &kMeshVertices,
                                                &kMeshTriangles,
                                                &kTextureFileBytes,
                                                &kTexturePixels,
                                                &kAnimationFrames,
                                                &kFrameIndex,
                                                &kFramesPerSecond,
                                                &kTurnDegrees,
                                                &kOrbitFrames,
                                                &kRays,
                                                &kExportMegabytes,
                                                &kDiagramSize,
                                                &kDiagramWindings,
                                                &kImpactParameter,
                                                &kLaunchDistance,
                                                &kUvOffset,
                                                &kUvScale,
                                                &kBlinkPeriod,
                                                &kUnitFraction,
                                                &kGridSide,
                                                &kCosmologicalConstant,
                                                &kTideSamples,
                                                &kOutlinePoints};
    return rows;
}

bool Range::contains(double v) const {
    return std::isfinite(v) && v >= min && v <= max && (!integer || v == std::floor(v));
}

std::string formatBound(double v) {
    char buf[32];
    if (v == std::floor(v) && std::abs(v) < 1e5) {  // small whole numbers as written: 300, 16384
        std::snprintf(buf, sizeof buf, "%.0f", v);
        return buf;
    }
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

std::string Range::describe() const {
    std::string s =
        std::string(integer ? "an integer" : "a number") + " in [" + formatBound(min) + ", " + formatBound(max) + "]";
    if (*unit) s += std::string(" ") + unit;
    return s;
}

std::string Range::problem(double v) const {
    const std::string got = std::isnan(v) ? "NaN" : std::isinf(v) ? (v > 0 ? "inf" : "-inf") : formatBound(v);
    return "expected " + describe() + ", got " + got;
}

void Range::require(double v, const std::string& what) const {
    if (!contains(v)) throw std::invalid_argument(what + ": " + problem(v));
}

std::string rangesMarkdown() {
    std::string md = "| what | accepted | unit | why |\n|---|---|---|---|\n";
    for (const Range* r : allRanges())
        md += std::string("| ") + r->key + " | " + (r->integer ? "integer " : "") + "[" + formatBound(r->min) + ", " +
              formatBound(r->max) + "] | " + r->unit + " | " + r->why + " |\n";
    return md;
}

std::optional<double> parseNumber(std::string_view text) {
    if (text.empty() || text.size() > 64) return std::nullopt;
    const char c0 = text.front();
    if (!(c0 == '-' || c0 == '+' || c0 == '.' || (c0 >= '0' && c0 <= '9'))) return std::nullopt;  // no blanks, nan, inf
    const std::string copy(text);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(copy.c_str(), &end);
    if (end != copy.c_str() + copy.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace lc::input
