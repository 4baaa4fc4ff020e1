// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconeWorldLineSource
 * @brief   a timelike world line sampled in proper time
 *
 * vtkLightconeWorldLineSource is a source (no input) producing one polyline: the world line
 * x(tau), tau in ProperTimeRange with NumberOfSamples intervals, x(0) = StartEvent
 * (t, x1, x2, x3). Modes:
 *
 * - GODEL_FREE_FALL (default): the timelike geodesic of docs/PHYSICS.md section 2 through the
 *   origin (lc::godel::OriginGeodesic::timelike with Energy k0, K3 and Azimuth phi0 in
 *   degrees; |k0| >= sqrt(1 + k3^2), k0 < 0 is past-directed) moved by
 *   lc::godel::Isometry::movingOriginTo(a, StartEvent) (lc::godel::FreeFall). Cartesian
 *   chart (t, X, Y, z) of GodelCartesian.
 * - GODEL_REST: the static observer (the rotating dust) through StartEvent:
 *   x = StartEvent + (tau, 0, 0, 0), u = d/dt.
 * - MINKOWSKI: constant velocity Beta (|beta| < 1) in Minkowski space:
 *   x = StartEvent + gamma tau (1, beta), u = gamma (1, beta).
 *
 * Points: (x1, x2, x3) in the EMBEDDING chart (default), (x1, x2, t) in XYT. Point data
 * (double): "tau", "t", "velocity" (4 components, contravariant dx/dtau), "r"
 * (= sqrt(x1^2 + x2^2), the distance from the z axis). A bad parameter (energy too low,
 * |beta| >= 1) is an error (vtkErrorMacro) and leaves the output empty.
 */
#ifndef vtkLightconeWorldLineSource_h
#define vtkLightconeWorldLineSource_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT
#include "vtkLightconeOutputChart.h"

#include <vtkPolyDataAlgorithm.h>

#include <functional>
#include <memory>

namespace lc
{
namespace godel
{
class ProperTimeWorldLine;
}
} // VTK's wrapper parser reads no C++17 nested namespace

class LIGHTCONEFILTERS_EXPORT vtkLightconeWorldLineSource : public vtkPolyDataAlgorithm
{
public:
  static vtkLightconeWorldLineSource* New();
  vtkTypeMacro(vtkLightconeWorldLineSource, vtkPolyDataAlgorithm) // no ";" (-Wpedantic)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    GODEL_FREE_FALL = 0,
    GODEL_REST = 1,
    MINKOWSKI = 2,
    GODEL_PROPER_TIME = 3
  };

  ///@{
  /**
   * Kind of world line (default GODEL_FREE_FALL).
   */
  vtkSetClampMacro(Mode, int, GODEL_FREE_FALL, GODEL_PROPER_TIME);
  vtkGetMacro(Mode, int);
  void SetModeToGodelFreeFall() { this->SetMode(GODEL_FREE_FALL); }
  void SetModeToGodelRest() { this->SetMode(GODEL_REST); }
  void SetModeToMinkowski() { this->SetMode(MINKOWSKI); }
  void SetModeToGodelProperTime() { this->SetMode(GODEL_PROPER_TIME); }
  ///@}

  /**
   * GODEL_PROPER_TIME: a world line by proper time built from segments (a traveller's trip,
   * docs/PHYSICS.md section 11; its own start event, StartEvent is not used). Coordinate time may
   * decrease along it. Without one the output is empty, with an error.
   */
  void SetProperTimeWorldLine(std::shared_ptr<const lc::godel::ProperTimeWorldLine> line);

  ///@{
  /**
   * Goedel parameter a > 0 (default 1).
   */
  vtkLightconeGodelAMacro();
  ///@}

  ///@{
  /**
   * Free fall: energy k0 = p_t (default 1.5), k3 = dz/dtau (default 0), azimuth phi0 of the
   * motion at the start in degrees (default 0), in the start event's static frame.
   */
  vtkSetMacro(Energy, double);
  vtkGetMacro(Energy, double);
  vtkSetMacro(K3, double);
  vtkGetMacro(K3, double);
  vtkSetMacro(Azimuth, double);
  vtkGetMacro(Azimuth, double);
  ///@}

  ///@{
  /**
   * Event at tau = 0 (default (0, 0, 0, 0)); Minkowski velocity beta (default (0.5, 0, 0)).
   */
  vtkSetVector4Macro(StartEvent, double);
  vtkGetVector4Macro(StartEvent, double);
  vtkSetVector3Macro(Beta, double);
  vtkGetVector3Macro(Beta, double);
  ///@}

  ///@{
  /**
   * Proper-time range (default (0, 10)) and number of intervals (default 256, at least 1).
   */
  vtkSetVector2Macro(ProperTimeRange, double);
  vtkGetVector2Macro(ProperTimeRange, double);
  vtkSetClampMacro(NumberOfSamples, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * Chart of the points: EMBEDDING (x1, x2, x3) (default) or XYT (x1, x2, t).
   */
  vtkLightconeOutputChartMacro();
  ///@}

protected:
  vtkLightconeWorldLineSource();
  ~vtkLightconeWorldLineSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = GODEL_FREE_FALL;
  std::shared_ptr<const lc::godel::ProperTimeWorldLine> ProperTimeLine;
  double GodelA = 1.0;
  double Energy = 1.5;
  double K3 = 0.0;
  double Azimuth = 0.0;
  double StartEvent[4] = { 0.0, 0.0, 0.0, 0.0 };
  double Beta[3] = { 0.5, 0.0, 0.0 };
  double ProperTimeRange[2] = { 0.0, 10.0 };
  int NumberOfSamples = 256;
  int OutputChart = vtkLightconeOutputChart::EMBEDDING;

private:
  // The world line as functions of proper time (event and four-velocity), then sampled into
  // the output polyline: the two steps of RequestData.
  struct WorldLine
  {
    std::function<lc::Vec4(double)> Position, Velocity;
  };
  WorldLine MakeWorldLine() const;
  void SampleWorldLine(const WorldLine& line, vtkPolyData* out);

  vtkLightconeWorldLineSource(const vtkLightconeWorldLineSource&) = delete;
  void operator=(const vtkLightconeWorldLineSource&) = delete;
};

#endif
