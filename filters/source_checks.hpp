// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the sources and filters check before any work: every parameter finite, events where the
// isometries stay accurate (core/input/ranges.hpp, as scene files), and a bound on the points
// an output may have, so that a typo in a resolution cannot allocate gigabytes. Each returns
// an empty string or the problem, which RequestData reports with vtkErrorMacro before leaving
// its outputs empty.
#include "core/input/ranges.hpp"

#include <vtkDataObject.h>
#include <vtkInformation.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cmath>
#include <string>

// Two namespace blocks: VTK 9.1's wrapper parser (this header is in the module) reads no
// nested namespace definitions.
namespace lc
{
namespace filters
{
// More points than this in one output is refused (a 7000 x 7000 grid; ~1 GB of arrays).
constexpr double kMaxSourcePoints = 5e7;

inline std::string CheckFinite(const char* name, const double* values, int n)
{
  for (int k = 0; k < n; ++k)
  {
    if (!std::isfinite(values[k]))
    {
      return std::string(name) + " has a non-finite component (" + std::to_string(values[k]) + ")";
    }
  }
  return "";
}

inline std::string CheckPointCount(const char* what, double points)
{
  if (points <= kMaxSourcePoints)
  {
    return "";
  }
  return std::string(what) + " would have " + lc::input::formatBound(points) +
    " points, more than " + lc::input::formatBound(kMaxSourcePoints) + " (lower the resolution)";
}

// A frame of special relativity: velocity Beta finite with |Beta| < 1, and the event its origin
// passes (ObjectOrigin, t x y z) finite.
inline std::string CheckMovingFrame(const double* beta, const double* originEvent)
{
  const std::string finite =
    CheckFinite("Beta", beta, 3) + CheckFinite("ObjectOrigin", originEvent, 4);
  if (!finite.empty())
  {
    return finite;
  }
  if (!(beta[0] * beta[0] + beta[1] * beta[1] + beta[2] * beta[2] < 1.0))
  {
    return "|beta| must be < 1";
  }
  return "";
}

// An image source's grid: Origin and Spacing finite, Dimensions at least 1 each.
inline std::string CheckGrid(const double* origin, const double* spacing, const int* dims)
{
  std::string problem = CheckFinite("Origin", origin, 3);
  if (problem.empty())
  {
    problem = CheckFinite("Spacing", spacing, 3);
  }
  if (problem.empty() && (dims[0] < 1 || dims[1] < 1 || dims[2] < 1))
  {
    problem = "Dimensions must be at least 1 each, got " + std::to_string(dims[0]) + " x " +
      std::to_string(dims[1]) + " x " + std::to_string(dims[2]);
  }
  return problem;
}

// An image source's RequestInformation: the whole extent of `dims` points (at least 1 each),
// origin and spacing.
inline void SetGridInformation(
  vtkInformation* outInfo, const double* origin, const double* spacing, const int* dims)
{
  const int ext[6] = { 0, std::max(dims[0], 1) - 1, 0, std::max(dims[1], 1) - 1, 0,
    std::max(dims[2], 1) - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), ext, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
}

// Goedel events beyond input::kGodelAxisDistance from the axis are refused, as in scene files.
inline std::string CheckGodelEvent(const char* name, const double* event, double a)
{
  const std::string finite = CheckFinite(name, event, 4);
  if (!finite.empty())
  {
    return finite;
  }
  const double r = std::hypot(event[1], event[2]) / a;
  if (!lc::input::kGodelAxisDistance.contains(r))
  {
    return std::string(name) + " lies at r = " + lc::input::formatBound(r) +
      " a from the axis: " + lc::input::kGodelAxisDistance.problem(r);
  }
  return "";
}
} // namespace filters
} // namespace lc
