// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The accepted range of every number a user gives Lightcone: scene files, the command line and
// the GUI's property editors all check against this one table, so they refuse the same values
// with the same words, and docs/SCENES.md lists exactly these rows (a test compares them).
// Metric parameters carry their ranges in core/metrics/factory.cpp, next to their defaults.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lc::input {

struct Range {
    const char* key;   // what it bounds, as named in docs/SCENES.md
    double min, max;   // inclusive
    bool integer;      // whole numbers only
    const char* unit;  // "" when dimensionless or in units of M or a
    const char* why;   // the reason for the bound, one line for the docs

    bool contains(double v) const;
    std::string describe() const;         // "an integer in [1, 16384] px"
    std::string problem(double v) const;  // "expected an integer in [1, 16384] px, got 2.5"
    // Throws std::invalid_argument("<what>: <problem>") unless the range contains v.
    void require(double v, const std::string& what) const;
};

// Events and geometry.
extern const Range kGodelAxisDistance, kObjects, kLights;
extern const Range kCoordinate, kLength, kDiskRadius, kScale, kBoxSubdivisions, kDirectionComponent, kAngle;
extern const Range kObserverVelocityComponent, kObserverGamma;
// Motion.
extern const Range kSpeed, kFreeFallEnergy, kFreeFallK3, kWorldLineEvents, kWorldLineSegments, kProperTimeSpan,
    kCircleTurns, kCircleDtDphi, kRocketAcceleration, kRocketBurnTime;
// Colour and light.
extern const Range kColourComponent, kTemperature, kSkyTemperature, kLightIntensity, kCheckerCells, kStars, kStarSize,
    kStarMagnitude, kStarSeed;
// Camera and image.
extern const Range kImageSide, kImagePixels, kFieldOfView;
// Tracing.
extern const Range kTolerance, kWindings, kMaxAffine, kEscapeRadius, kEscapeAngle, kMaxSteps, kInitialStep, kThreads;
extern const Range kMeshLatitudes, kMeshLongitudes, kMeshResolutionVertices;
// Files.
extern const Range kSceneFileBytes, kMeshFileBytes, kMeshVertices, kMeshTriangles, kTextureFileBytes, kTexturePixels;
// Command line only.
extern const Range kAnimationFrames, kFrameIndex, kFramesPerSecond, kTurnDegrees;
extern const Range kOrbitFrames, kRays, kExportMegabytes, kDiagramSize, kDiagramWindings, kImpactParameter,
    kLaunchDistance;
extern const Range kUvOffset, kUvScale, kBlinkPeriod, kUnitFraction;
extern const Range kGridSide, kCosmologicalConstant, kTideSamples, kOutlinePoints;

// Every row above, in the order docs/SCENES.md lists them.
const std::vector<const Range*>& allRanges();

// Strict text to number: the whole text must be one finite decimal number ("0.5xyz", "",
// " 1", "nan", "inf" and "1e999" are not).
std::optional<double> parseNumber(std::string_view text);

// "1e+06" style shortest round-trip text of a bound, for messages and docs.
std::string formatBound(double v);

// The table of allRanges() as Markdown rows (| what | accepted | unit | why |), exactly as
// docs/SCENES.md shows it (a test keeps the two equal).
std::string rangesMarkdown();

}  // namespace lc::input
