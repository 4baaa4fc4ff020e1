// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconeIsometryOrbitSource
 * @brief   flow lines (orbits) of a Killing field of the Goedel universe
 *
 * vtkLightconeIsometryOrbitSource is a source (no input): for every seed point (X, Y, z) at
 * time SeedTime (Cartesian chart of GodelCartesian) one polyline, the orbit x(s) of the
 * Killing field xi = c1 d/dt + c2 d/dphi + c3 d/dz + c4 xi4 + c5 xi5 (SetCoefficients;
 * lc::godel::killingCartesian), dx/ds = xi(x), x(0) = seed, sampled at NumberOfSamples + 1
 * equally spaced s in FlowRange (which may contain negative s: the orbit runs backwards).
 *
 * Where c4 = c5 = 0 the orbit is in closed form (time shift c1 s, rotation c2 s about the
 * axis, z shift c3 s). Otherwise the ODE is integrated with Boost.Odeint's dense-output
 * dopri5 at absolute = relative tolerance Tolerance (1e-12). Orbits of xi4 / xi5 leave
 * every bounded region exponentially in s: keep FlowRange moderate.
 *
 * Points: (X, Y, z) in the EMBEDDING chart, (X, Y, t) in XYT. Point data (double): "s",
 * "t", "r" (= sqrt(X^2 + Y^2)), "z", "g_xi_xi" (g(xi, xi) at the point, constant along an
 * orbit since xi is Killing). Cell data: "seed" (int, index of the seed).
 *
 * @sa vtkLightconeKillingFieldSource
 */
#ifndef vtkLightconeIsometryOrbitSource_h
#define vtkLightconeIsometryOrbitSource_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT
#include "vtkLightconeOutputChart.h"

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkPoints;

class LIGHTCONEFILTERS_EXPORT vtkLightconeIsometryOrbitSource : public vtkPolyDataAlgorithm
{
public:
  static vtkLightconeIsometryOrbitSource* New();
  vtkTypeMacro(vtkLightconeIsometryOrbitSource, vtkPolyDataAlgorithm) // no ";" (-Wpedantic)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Goedel parameter a > 0 (default 1).
   */
  vtkLightconeGodelAMacro();
  ///@}

  ///@{
  /**
   * Coefficients (c1..c5) of the Killing field (default (0, 1, 0, 0, 0): the rotation).
   */
  vtkSetVectorMacro(Coefficients, double, 5);
  void SetCoefficients(double c1, double c2, double c3, double c4, double c5)
  {
    const double c[5] = { c1, c2, c3, c4, c5 };
    this->SetCoefficients(c);
  }
  vtkGetVectorMacro(Coefficients, double, 5);
  ///@}

  ///@{
  /**
   * Seed points (X, Y, z) (use double points; call Modified() on them after editing). Without
   * seeds (default) one orbit starts at (1, 0, 0). SeedTime: their t (default 0).
   */
  void SetSeeds(vtkPoints* seeds);
  vtkPoints* GetSeeds();
  vtkSetMacro(SeedTime, double);
  vtkGetMacro(SeedTime, double);
  ///@}

  ///@{
  /**
   * Flow parameter range (default (0, 2 pi)), intervals per orbit (default 128, at least 1),
   * ODE tolerance (default 1e-12).
   */
  vtkSetVector2Macro(FlowRange, double);
  vtkGetVector2Macro(FlowRange, double);
  vtkSetClampMacro(NumberOfSamples, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfSamples, int);
  vtkSetClampMacro(Tolerance, double, 1e-16, 1.0);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Chart of the points: EMBEDDING (X, Y, z) (default) or XYT (X, Y, t).
   */
  vtkLightconeOutputChartMacro();
  ///@}

  /**
   * Includes the seed points' modification time.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkLightconeIsometryOrbitSource();
  ~vtkLightconeIsometryOrbitSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double GodelA = 1.0;
  double Coefficients[5] = { 0.0, 1.0, 0.0, 0.0, 0.0 };
  vtkSmartPointer<vtkPoints> Seeds;
  double SeedTime = 0.0;
  double FlowRange[2] = { 0.0, 6.283185307179586 };
  int NumberOfSamples = 128;
  double Tolerance = 1e-12;
  int OutputChart = vtkLightconeOutputChart::EMBEDDING;

private:
  // The output under construction: one polyline per seed and its point and cell data.
  struct OrbitArrays;
  // The steps of RequestData: what is wrong with the parameters (empty: nothing), the seed
  // events, the orbit of one seed at the flow parameters s (closed form where the flow is
  // a translation and rotation, else integrated), and that orbit appended to the output.
  std::string ParameterProblem() const;
  std::vector<lc::Vec4> SeedEvents() const;
  std::vector<lc::Vec4> SampleOrbit(const lc::Vec4& x0, const std::vector<double>& s) const;
  void AppendOrbit(const std::vector<double>& s, const std::vector<lc::Vec4>& xs, int seed,
    OrbitArrays& arrays) const;

  vtkLightconeIsometryOrbitSource(const vtkLightconeIsometryOrbitSource&) = delete;
  void operator=(const vtkLightconeIsometryOrbitSource&) = delete;
};

#endif
