// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconeKillingFieldSource
 * @brief   the five Killing fields of the Goedel universe sampled on a grid
 *
 * vtkLightconeKillingFieldSource is a source (no input) producing vtkImageData: a regular
 * grid (Origin, Spacing, Dimensions) in the Cartesian chart (X, Y, z) of GodelCartesian at
 * the time slice t = Time. For each Killing field of docs/PHYSICS.md section 4
 * (lc::godel::killingCartesian) and for the linear combination
 * c1 d/dt + c2 d/dphi + c3 d/dz + c4 xi4 + c5 xi5 (SetCoefficients), with names
 * "xi_t", "xi_phi", "xi_z", "xi_4", "xi_5" and "combination", the point data holds:
 *
 * - "<name>": 3-component vector, the spatial (X, Y, z) components of the field;
 * - "<name>_t": its time component;
 * - "<name>_norm": sqrt(|g(xi, xi)|) with the Goedel metric at the point;
 * - "<name>_causal": +1 where g(xi, xi) > 0 (timelike), -1 where < 0 (spacelike), 0 if null.
 *
 * The active vectors are "combination". Signature (+,-,-,-).
 *
 * @sa vtkLightconeIsometryOrbitSource
 */
#ifndef vtkLightconeKillingFieldSource_h
#define vtkLightconeKillingFieldSource_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT
#include "vtkLightconeOutputChart.h" // vtkLightconeGodelAMacro

#include <vtkImageAlgorithm.h>

#include <string>

class LIGHTCONEFILTERS_EXPORT vtkLightconeKillingFieldSource : public vtkImageAlgorithm
{
public:
  static vtkLightconeKillingFieldSource* New();
  vtkTypeMacro(vtkLightconeKillingFieldSource, vtkImageAlgorithm) // no ";" (-Wpedantic)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Goedel parameter a > 0 (default 1).
   */
  vtkLightconeGodelAMacro();
  ///@}

  ///@{
  /**
   * Time slice t of the grid (default 0; the fields do not depend on t).
   */
  vtkSetMacro(Time, double);
  vtkGetMacro(Time, double);
  ///@}

  ///@{
  /**
   * The grid in (X, Y, z): origin (default (-2, -2, 0)), spacing (default (0.2, 0.2, 1)),
   * number of points per axis (default (21, 21, 1), each at least 1).
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
   * Coefficients (c1..c5) of the combination c1 d/dt + c2 d/dphi + c3 d/dz + c4 xi4 + c5 xi5
   * (default (0, 1, 0, 0, 0): the rotation).
   */
  vtkSetVectorMacro(Coefficients, double, 5);
  void SetCoefficients(double c1, double c2, double c3, double c4, double c5)
  {
    const double c[5] = { c1, c2, c3, c4, c5 };
    this->SetCoefficients(c);
  }
  vtkGetVectorMacro(Coefficients, double, 5);
  ///@}

protected:
  vtkLightconeKillingFieldSource();
  ~vtkLightconeKillingFieldSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double GodelA = 1.0;
  double Time = 0.0;
  double Origin[3] = { -2.0, -2.0, 0.0 };
  double Spacing[3] = { 0.2, 0.2, 1.0 };
  int Dimensions[3] = { 21, 21, 1 };
  double Coefficients[5] = { 0.0, 1.0, 0.0, 0.0, 0.0 };

private:
  // The steps of RequestData: what is wrong with the parameters (empty: nothing), then every
  // field and its norm sampled on the grid of `out`.
  std::string ParameterProblem() const;
  void SampleFields(vtkImageData* out);

  vtkLightconeKillingFieldSource(const vtkLightconeKillingFieldSource&) = delete;
  void operator=(const vtkLightconeKillingFieldSource&) = delete;
};

#endif
