// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconeCurvatureSource
 * @brief   curvature, the matter it implies and tidal forces of any metric, sampled on a grid
 *
 * vtkLightconeCurvatureSource is a source (no input) producing vtkImageData: a regular grid
 * (Origin, Spacing, Dimensions) of the spatial chart coordinates x^1..x^3 at the chart time
 * Time; one point per Dimensions' third axis gives a slice. Each quantity added with
 * AddQuantity is one point array of that name (lc::curvatureQuantities(): "kretschmann",
 * "ricci_scalar", "ricci_squared", "weyl_squared", "energy_density", "energy_flux" (3),
 * "principal_pressures" (3), "hawking_ellis_type", "null_energy_violation",
 * "weak_energy_violation", "strong_energy_violation", "dominant_energy_violation",
 * "tidal_eigenvalues" (3)); the first is the active scalars. Values come from exact second
 * derivatives of the metric (core/curvature, docs/PHYSICS.md section 13).
 *
 * Matter and tides are what an observer measures: ObserverField STATIC (along d/dt), NORMAL (of
 * the slices t = const) or AUTO (static where d/dt is timelike, else normal, the default). The
 * matter is T_ab = (G_ab - Lambda g_ab) / 8 pi with Lambda = CosmologicalConstant.
 *
 * Values are NaN where the metric is singular and, for observer quantities, where the field
 * has no observer; the field data "singular_points" and "points_without_observer" count them.
 * The metric is given by name and parameters (lc::makeSpacetime) or as a shared
 * lc::SpacetimePtr (SetSpacetime, which takes precedence: formula metrics). Both cores work;
 * progress is reported and AbortExecute stops the sampling (the rest NaN).
 *
 * @sa vtkLightconeKillingFieldSource
 */
#ifndef vtkLightconeCurvatureSource_h
#define vtkLightconeCurvatureSource_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT
#include "core/spacetime/spacetime.hpp"

#include <vtkImageAlgorithm.h>

#include <map>
#include <string>
#include <vector>

class LIGHTCONEFILTERS_EXPORT vtkLightconeCurvatureSource : public vtkImageAlgorithm
{
public:
  static vtkLightconeCurvatureSource* New();
  vtkTypeMacro(vtkLightconeCurvatureSource, vtkImageAlgorithm) // no ";" (-Wpedantic)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Metric by name (see lc::knownMetrics()), default "schwarzschild", and its parameters
   * (missing ones take the factory's defaults). Ignored while a spacetime is set.
   */
  vtkSetStringMacro(MetricName);
  vtkGetStringMacro(MetricName);
  void SetMetricParameter(const std::string& name, double value);
  void ClearMetricParameters();
  ///@}

  ///@{
  /**
   * A spacetime shared with other parts of the application (a formula metric); takes
   * precedence over MetricName. An empty pointer goes back to MetricName.
   */
  void SetSpacetime(lc::SpacetimePtr spacetime);
  lc::SpacetimePtr GetSpacetime() const { return this->Spacetime; }
  ///@}

  ///@{
  /**
   * Chart time t of the grid (default 0).
   */
  vtkSetMacro(Time, double);
  vtkGetMacro(Time, double);
  ///@}

  ///@{
  /**
   * The grid in (x^1, x^2, x^3): origin (default (-10, -10, 0)), spacing (default
   * (0.2, 0.2, 1)), points per axis (default (101, 101, 1), each at least 1).
   */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  vtkSetVector3Macro(Spacing, double);
  vtkGetVector3Macro(Spacing, double);
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  ///@{
  /**
   * The quantities sampled, in order (default: "kretschmann" alone until one is added).
   */
  void AddQuantity(const char* name);
  void RemoveAllQuantities();
  int GetNumberOfQuantities() const { return static_cast<int>(this->Quantities.size()); }
  const char* GetQuantity(int i) const;
  ///@}

  ///@{
  /**
   * Lambda in G_ab = 8 pi T_ab + Lambda g_ab (default 0): e.g. -1/(2 a^2) reads Goedel's
   * universe as dust.
   */
  vtkSetMacro(CosmologicalConstant, double);
  vtkGetMacro(CosmologicalConstant, double);
  ///@}

  enum
  {
    AUTO = 0,
    STATIC = 1,
    NORMAL = 2
  };
  ///@{
  /**
   * Which observers measure matter and tides (default AUTO).
   */
  vtkSetClampMacro(ObserverField, int, AUTO, NORMAL);
  vtkGetMacro(ObserverField, int);
  void SetObserverFieldToAuto() { this->SetObserverField(AUTO); }
  void SetObserverFieldToStatic() { this->SetObserverField(STATIC); }
  void SetObserverFieldToNormal() { this->SetObserverField(NORMAL); }
  ///@}

protected:
  vtkLightconeCurvatureSource();
  ~vtkLightconeCurvatureSource() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* MetricName = nullptr;
  std::map<std::string, double> MetricParameters;
  lc::SpacetimePtr Spacetime;
  double Time = 0.0;
  double Origin[3] = { -10.0, -10.0, 0.0 };
  double Spacing[3] = { 0.2, 0.2, 1.0 };
  int Dimensions[3] = { 101, 101, 1 };
  std::vector<std::string> Quantities;
  double CosmologicalConstant = 0.0;
  int ObserverField = AUTO;

private:
  // The steps of RequestData: what is wrong with the parameters (empty: nothing), the metric,
  // then the quantities sampled into `out`.
  std::string ParameterProblem() const;
  lc::SpacetimePtr ResolveSpacetime() const;
  void SampleQuantities(const lc::Spacetime& spacetime, vtkImageData* out);

  vtkLightconeCurvatureSource(const vtkLightconeCurvatureSource&) = delete;
  void operator=(const vtkLightconeCurvatureSource&) = delete;
};

#endif
