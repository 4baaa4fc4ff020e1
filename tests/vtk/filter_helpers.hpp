// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What several filter tests share: point arrays looked up with a test failure when missing, the
// Goedel null geodesic through the origin in closed form (docs/PHYSICS.md section 2, typed in
// here as the oracle), the Goedel metric in the Cartesian chart, and the check that a source
// refuses a bad setting.
#include "tests/common/vtk_event_counter.hpp"

#include "core/metrics/godel.hpp"
#include "core/numerics/types.hpp"

#include <vtkAlgorithm.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace lc::test
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

inline vtkDataArray* PointArray(vtkDataSet* ds, const char* name)
{
  vtkDataArray* a = ds->GetPointData()->GetArray(name);
  EXPECT_NE(a, nullptr) << "missing point array " << name;
  return a;
}

// Past-directed (k0 = -1) null geodesic of the Goedel universe through the origin, local
// direction at the origin with polar angle psi from +z and azimuth phi0, with the signed radius
// r_max sin(omega l) that holds after axis passages.
struct GodelRay
{
  double a, psi, phi0;
  double k3() const { return std::cos(psi); }
  double omega() const { return std::sqrt(1 + k3() * k3()) / (2 * a); }
  double rMax() const { return 2 * a * std::sqrt((1 - k3() * k3()) / (1 + k3() * k3())); }
  double Phi(double l) const
  {
    const double th = omega() * l;
    return std::atan(std::sqrt(2 / (1 + k3() * k3())) * std::tan(th)) +
      kPi * std::floor(th / kPi + 0.5);
  }
  double t(double l) const { return -(2 * std::sqrt(2.0) * a * Phi(l) - l); }
  double rho(double l) const { return rMax() * std::sin(omega() * l); } // signed radius
  double phi(double l) const { return phi0 - Phi(l); }
  double X(double l) const { return rho(l) * std::cos(phi(l)); }
  double Y(double l) const { return rho(l) * std::sin(phi(l)); }
  double z(double l) const { return k3() * l; }
};

// Goedel metric in the Cartesian chart (t, X, Y, z).
inline Mat4 GodelMetric(double a, const Vec4& x)
{
  return GodelCartesian(a).metric(x);
}

// Runs `source` with a bad setting: one error naming `expected`, empty outputs `empty()`.
inline void ExpectRefused(
  vtkAlgorithm* source, const std::function<bool()>& empty, const char* expected)
{
  EventCounter errors;
  errors.watch(source);
  source->Update();
  EXPECT_EQ(errors.count, 1) << expected;
  EXPECT_NE(errors.text.find(expected), std::string::npos)
    << "the error does not name " << expected << ": " << errors.text;
  EXPECT_TRUE(empty()) << "output left after refusing " << expected;
}
} // namespace lc::test
