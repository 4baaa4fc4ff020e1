// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconeGodelHorizonSource
 * @brief   the optical horizon r = 2a of the Goedel universe and the light cone of the origin
 *
 * vtkLightconeGodelHorizonSource is a source (no input) with two polygonal outputs, for an
 * observer on the axis of the Goedel universe (parameter a, docs/PHYSICS.md sections 1-2):
 *
 * - port 0: the horizon, the cylinder r = 2a (the Goedel radius): light leaving the axis
 *   never gets beyond it. Quads, Resolution in azimuth by HeightResolution along the third
 *   output coordinate, whose range is ZRange (z in the EMBEDDING chart, t in RPHIT).
 *   EMBEDDING: points (2a cos phi, 2a sin phi, z), closed in phi (no seam points);
 *   RPHIT: points (2a, phi, t), phi in [0, 2 pi] (the plane r = 2a).
 * - port 1 (when GenerateLightCone is on): the past light cone of the origin event from the
 *   closed form of its null geodesics (lc::godel::OriginGeodesic, past-directed, k0 = -1),
 *   for the rays of azimuth LightConeAzimuth (degrees): the grid (psi, lambda), psi in
 *   [0, pi] (polar angle of the ray's direction at the origin) and lambda in
 *   [0, LightConeAffineLength], is mapped to EMBEDDING (X, Y, z) or RPHIT (r, phi, t) with
 *   phi = phi0 - Phi(lambda) continuous. Point data "t", "affine", "psi", "r".
 *
 *   With LightConeSheet = PLANAR instead, the sheet of the planar rays (psi = pi/2) over
 *   (phi0, lambda), phi0 in [0, 2 pi] with LightConePsiResolution cells: points (X, Y, t) in
 *   the EMBEDDING chart (z = 0 for these rays, so t takes the third axis: the usual picture
 *   of the Goedel light cone refocusing on the axis) or (r, phi, t) in RPHIT. Point data
 *   then also has "phi0".
 *
 * Point data of port 0: "r", "phi"; normals in the EMBEDDING chart.
 *
 * @sa vtkLightconeNullGeodesicSource
 */
#ifndef vtkLightconeGodelHorizonSource_h
#define vtkLightconeGodelHorizonSource_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT
#include "vtkLightconeOutputChart.h"

#include <vtkPolyDataAlgorithm.h>

#include <string>

class vtkPolyData;
namespace lc
{
namespace godel
{
class Isometry;
}
}

class LIGHTCONEFILTERS_EXPORT vtkLightconeGodelHorizonSource : public vtkPolyDataAlgorithm
{
public:
  static vtkLightconeGodelHorizonSource* New();
  vtkTypeMacro(vtkLightconeGodelHorizonSource,
    vtkPolyDataAlgorithm) // no ";": the macro ends with a function body (-Wpedantic)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // OutputChart: EMBEDDING or RPHIT (vtkLightconeOutputChart); XYT is refused (the horizon is a
  // surface in space, not a curve in time).
  enum
  {
    EMBEDDING = vtkLightconeOutputChart::EMBEDDING,
    RPHIT = vtkLightconeOutputChart::RPHIT
  };
  enum LightConeSheets
  {
    PSI_LAMBDA = 0,
    PLANAR = 1
  };

  ///@{
  /**
   * Goedel parameter a > 0 (default 1); the horizon radius is 2a.
   */
  vtkLightconeGodelAMacro();
  // The observer event (t, x, y, z) in the axis-regular chart; default the origin.
  vtkSetVector4Macro(Observer, double);
  vtkGetVector4Macro(Observer, double);
  ///@}

  ///@{
  /**
   * Range of the third output coordinate of the horizon (z, or t in RPHIT). Default (-1, 1).
   */
  vtkSetVector2Macro(ZRange, double);
  vtkGetVector2Macro(ZRange, double);
  ///@}

  ///@{
  /**
   * Cells of the horizon in azimuth (default 64, at least 3) and along ZRange (default 8).
   */
  vtkSetClampMacro(Resolution, int, 3, VTK_INT_MAX);
  vtkGetMacro(Resolution, int);
  vtkSetClampMacro(HeightResolution, int, 1, VTK_INT_MAX);
  vtkGetMacro(HeightResolution, int);
  ///@}

  ///@{
  /**
   * Chart of both outputs: EMBEDDING (default) or RPHIT.
   */
  vtkLightconeOutputChartMacro();
  ///@}

  ///@{
  /**
   * Light cone of the origin on output port 1 (default on), its grid (cells in psi,
   * default 32, and in lambda, default 128), the largest affine parameter (default 2 pi,
   * one loop of the planar rays for a = 1) and the azimuth phi0 of its rays in degrees.
   */
  vtkSetMacro(GenerateLightCone, bool);
  vtkGetMacro(GenerateLightCone, bool);
  vtkBooleanMacro(GenerateLightCone, bool);
  vtkSetClampMacro(LightConePsiResolution, int, 1, VTK_INT_MAX);
  vtkGetMacro(LightConePsiResolution, int);
  vtkSetClampMacro(LightConeAffineResolution, int, 1, VTK_INT_MAX);
  vtkGetMacro(LightConeAffineResolution, int);
  vtkSetClampMacro(LightConeAffineLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LightConeAffineLength, double);
  vtkSetMacro(LightConeAzimuth, double);
  vtkGetMacro(LightConeAzimuth, double);
  ///@}

  ///@{
  /**
   * Which 2D sheet of the (3D) light cone port 1 shows: PSI_LAMBDA (default) or PLANAR.
   */
  vtkSetClampMacro(LightConeSheet, int, PSI_LAMBDA, PLANAR);
  vtkGetMacro(LightConeSheet, int);
  void SetLightConeSheetToPsiLambda() { this->SetLightConeSheet(PSI_LAMBDA); }
  void SetLightConeSheetToPlanar() { this->SetLightConeSheet(PLANAR); }
  ///@}

  /**
   * The horizon (port 0) and the light cone (port 1).
   */
  vtkPolyData* GetHorizonOutput() { return this->GetOutput(0); }
  vtkPolyData* GetLightConeOutput() { return this->GetOutput(1); }

protected:
  vtkLightconeGodelHorizonSource();
  ~vtkLightconeGodelHorizonSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double GodelA = 1.0;
  double Observer[4] = { 0.0, 0.0, 0.0, 0.0 };
  double ZRange[2] = { -1.0, 1.0 };
  int Resolution = 64;
  int HeightResolution = 8;
  int OutputChart = EMBEDDING;
  bool GenerateLightCone = true;
  int LightConePsiResolution = 32;
  int LightConeAffineResolution = 128;
  double LightConeAffineLength = 6.283185307179586;
  double LightConeAzimuth = 0.0;
  int LightConeSheet = PSI_LAMBDA;

private:
  // The steps of RequestData: what is wrong with the parameters (empty: nothing), then each
  // output built in the observer's chart and carried to the world chart by toWorld.
  std::string ParameterProblem() const;
  void BuildHorizon(const lc::godel::Isometry& toWorld, vtkPolyData* horizon) const;
  void BuildLightCone(const lc::godel::Isometry& toWorld, vtkPolyData* cone) const;

  vtkLightconeGodelHorizonSource(const vtkLightconeGodelHorizonSource&) = delete;
  void operator=(const vtkLightconeGodelHorizonSource&) = delete;
};

#endif
