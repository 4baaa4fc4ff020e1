// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconeKerrHorizonSource
 * @brief   the horizons and ergosurfaces of a Kerr-Newman black hole
 *
 * vtkLightconeKerrHorizonSource is a source (no input) with one polygonal output: the surfaces
 * of a Kerr-Newman hole of mass M, spin a (along +z) and charge Q (docs/PHYSICS.md section 12),
 * in the outgoing Kerr-Schild Cartesian chart every Kerr renderer and tracer uses (lc::KerrNewman):
 * a surface of Boyer-Lindquist radius r(theta) is the spheroid
 *   (x, y, z) = (sqrt(r^2 + a^2) sin theta cos phi, sqrt(r^2 + a^2) sin theta sin phi, r cos
 * theta).
 *
 * - surface 0, "outer_horizon": r_+ = M + sqrt(M^2 - a^2 - Q^2), the event horizon;
 * - surface 1, "inner_horizon": r_- = M - sqrt(M^2 - a^2 - Q^2), the Cauchy horizon (left out
 *   where r_- = 0: Schwarzschild);
 * - surface 2, "ergosurface": r_E(theta) = M + sqrt(M^2 - Q^2 - a^2 cos^2 theta), where
 *   g_tt = 0: inside it no observer can stay at rest (the static limit);
 * - surface 3, "inner_ergosurface": r = M - sqrt(M^2 - Q^2 - a^2 cos^2 theta) (left out with
 *   the inner horizon).
 * Quads over (theta, phi) with PolarResolution by AzimuthResolution cells (poles shared).
 * Cell data: "surface" (int, above) and "surface_name" (string). Point data: "r" (the
 * Boyer-Lindquist radius), "theta". An extremal hole (a^2 + Q^2 = M^2) has r_+ = r_- = M.
 * Parameters outside a^2 + Q^2 <= M^2, M > 0 (a naked singularity) or non-finite are refused
 * with an error naming the accepted spin, and the output is left empty.
 *
 * @sa vtkLightconeNullGeodesicSource vtkLightconeCurvatureSource
 */
#ifndef vtkLightconeKerrHorizonSource_h
#define vtkLightconeKerrHorizonSource_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT

#include <vtkPolyDataAlgorithm.h>

class LIGHTCONEFILTERS_EXPORT vtkLightconeKerrHorizonSource : public vtkPolyDataAlgorithm
{
public:
  static vtkLightconeKerrHorizonSource* New();
  vtkTypeMacro(vtkLightconeKerrHorizonSource,
    vtkPolyDataAlgorithm) // no ";": the macro ends with a function body (-Wpedantic)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Surfaces
  {
    OUTER_HORIZON = 0,
    INNER_HORIZON = 1,
    ERGOSURFACE = 2,
    INNER_ERGOSURFACE = 3
  };

  ///@{
  /**
   * The hole: mass M > 0 (default 1), spin a and charge Q (default 0), a^2 + Q^2 <= M^2.
   */
  vtkSetMacro(Mass, double);
  vtkGetMacro(Mass, double);
  vtkSetMacro(Spin, double);
  vtkGetMacro(Spin, double);
  vtkSetMacro(Charge, double);
  vtkGetMacro(Charge, double);
  ///@}

  ///@{
  /**
   * Which surfaces: the horizons (default on), the ergosurfaces (default on), and the inner
   * ones of each (default off: they lie inside the event horizon, where nothing is seen).
   */
  vtkSetMacro(GenerateHorizons, bool);
  vtkGetMacro(GenerateHorizons, bool);
  vtkBooleanMacro(GenerateHorizons, bool);
  vtkSetMacro(GenerateErgosurfaces, bool);
  vtkGetMacro(GenerateErgosurfaces, bool);
  vtkBooleanMacro(GenerateErgosurfaces, bool);
  vtkSetMacro(GenerateInnerSurfaces, bool);
  vtkGetMacro(GenerateInnerSurfaces, bool);
  vtkBooleanMacro(GenerateInnerSurfaces, bool);
  ///@}

  ///@{
  /**
   * Cells from pole to pole (default 32, at least 2) and about the axis (default 64, at least 3).
   */
  vtkSetClampMacro(PolarResolution, int, 2, VTK_INT_MAX);
  vtkGetMacro(PolarResolution, int);
  vtkSetClampMacro(AzimuthResolution, int, 3, VTK_INT_MAX);
  vtkGetMacro(AzimuthResolution, int);
  ///@}

protected:
  vtkLightconeKerrHorizonSource();
  ~vtkLightconeKerrHorizonSource() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkLightconeKerrHorizonSource(const vtkLightconeKerrHorizonSource&) = delete;
  void operator=(const vtkLightconeKerrHorizonSource&) = delete;

  double Mass = 1.0;
  double Spin = 0.0;
  double Charge = 0.0;
  bool GenerateHorizons = true;
  bool GenerateErgosurfaces = true;
  bool GenerateInnerSurfaces = false;
  int PolarResolution = 32;
  int AzimuthResolution = 64;
};

#endif
