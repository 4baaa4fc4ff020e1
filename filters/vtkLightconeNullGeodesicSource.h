// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconeNullGeodesicSource
 * @brief   polylines of past-directed null geodesics leaving an observer event
 *
 * vtkLightconeNullGeodesicSource is a source (no input) that traces the light rays an
 * observer sees: from the observer event (SetObserver(t, x1, x2, x3), coordinates of the
 * metric's chart) past-directed null geodesics are integrated with the Hamiltonian tracer
 * of the physics core (lc::traceGeodesic). Each ray leaves along a unit spatial direction n
 * given in the orthonormal frame of the static observer there (lc::LocalFrame::staticObserver).
 *
 * The metric is either given by name and parameters (lc::makeSpacetime, e.g. "godel" with
 * a = 1) or as a shared lc::SpacetimePtr (SetSpacetime), which then takes precedence.
 *
 * Directions: a fan in a plane (FanNormal, FanStartAngle..FanEndAngle in degrees), a cone
 * about an axis (ConeAxis, ConeAngle = opening half-angle in degrees), or an explicit list
 * (SetDirections with a vtkPoints of directions, normalised here).
 *
 * Output: one polyline cell per ray; a point at the start, and at every accepted step at
 * least SamplesPerStep points from the step's dense output (the last one is the accepted
 * state itself). Point coordinates depend on OutputChart:
 *   - EMBEDDING: (x, y, z) = (r cos phi, r sin phi, z), the spatial Cartesian picture;
 *   - RPHIT:     (x, y, z) = (r, phi, t) with phi continuous ("phi" array below);
 *   - XYT:       (x, y, z) = (r cos phi, r sin phi, t), a spacetime diagram of the plane
 *   (vtkLightconeOutputChart, shared by every Lightcone source).
 * Point data (all double): "t", "affine" (parameter lambda), "r" (cylindrical radius >= 0),
 * "signed_r" ((-1)^winding r), "phi" (continuous azimuth with (X, Y) = signed_r (cos phi,
 * sin phi), so for Goedel rays through the axis phi = phi0 + k0 Phi(lambda) of docs/PHYSICS.md
 * section 2), "z", "winding" (int: passages through the z axis so far, i.e. closest approaches
 * to it closer than AxisTolerance), "hamiltonian_drift" (H = 1/2 g^{mu nu} p_mu p_nu at the
 * point, 0 for an exact null ray).
 * Cell data: "stop_reason" (int, lc::StopReason), "stop_reason_name" (string), "steps" (int),
 * "phi0" and "psi" (double: azimuth and polar angle of the ray's initial direction).
 *
 * Charts: metrics whose coordinates are named (t, r, phi, z) are cylindrical; all others are
 * taken as Cartesian (t, x, y, z).
 *
 * @sa vtkLightconeGodelHorizonSource
 */
#ifndef vtkLightconeNullGeodesicSource_h
#define vtkLightconeNullGeodesicSource_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT
#include "core/spacetime/spacetime.hpp"

#include "vtkLightconeOutputChart.h"

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <map>
#include <string>
#include <vector>

class vtkPoints;

class LIGHTCONEFILTERS_EXPORT vtkLightconeNullGeodesicSource : public vtkPolyDataAlgorithm
{
public:
  static vtkLightconeNullGeodesicSource* New();
  vtkTypeMacro(vtkLightconeNullGeodesicSource,
    vtkPolyDataAlgorithm) // no ";": the macro ends with a function body (-Wpedantic)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum DirectionModes
  {
    FAN = 0,
    CONE = 1,
    LIST = 2
  };
  enum Methods
  {
    AUTO = 0, // closed form for the Goedel metric, numeric otherwise
    NUMERIC = 1, // Hamiltonian integration (any metric)
    CLOSED_FORM = 2 // Goedel only (error otherwise)
  };

  ///@{
  /**
   * Observer event (t, x1, x2, x3) in the metric's chart. Default (0, 0, 0, 0).
   */
  vtkSetVector4Macro(Observer, double);
  vtkGetVector4Macro(Observer, double);
  ///@}

  ///@{
  /**
   * Metric by name (see lc::knownMetrics()), default "godel", and its parameters (missing
   * ones take the factory's defaults). Ignored while a spacetime is set with SetSpacetime.
   */
  vtkSetStringMacro(MetricName);
  vtkGetStringMacro(MetricName);
  void SetMetricParameter(const std::string& name, double value);
  void ClearMetricParameters();
  const std::map<std::string, double>& GetMetricParameters() const
  {
    return this->MetricParameters;
  }
  ///@}

  ///@{
  /**
   * A spacetime shared with other parts of the application; takes precedence over
   * MetricName. Set an empty pointer to go back to MetricName.
   */
  void SetSpacetime(lc::SpacetimePtr spacetime);
  lc::SpacetimePtr GetSpacetime() const { return this->Spacetime; }
  ///@}

  ///@{
  /**
   * How the initial directions are chosen: FAN (default), CONE or LIST.
   */
  vtkSetClampMacro(DirectionMode, int, FAN, LIST);
  vtkGetMacro(DirectionMode, int);
  void SetDirectionModeToFan() { this->SetDirectionMode(FAN); }
  void SetDirectionModeToCone() { this->SetDirectionMode(CONE); }
  void SetDirectionModeToList() { this->SetDirectionMode(LIST); }
  ///@}

  ///@{
  /**
   * Number of rays of a fan or a cone. Default 16.
   */
  vtkSetClampMacro(NumberOfRays, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfRays, int);
  ///@}

  ///@{
  /**
   * Fan: plane normal (default (0, 0, 1)) and angular range in degrees (default 0..360; a
   * range of 360 degrees or more does not repeat its end ray). Angle 0 is the unit vector
   * closest to +x (+y if the normal is close to x) in the plane; angles turn right-handed
   * about the normal.
   */
  vtkSetVector3Macro(FanNormal, double);
  vtkGetVector3Macro(FanNormal, double);
  vtkSetMacro(FanStartAngle, double);
  vtkGetMacro(FanStartAngle, double);
  vtkSetMacro(FanEndAngle, double);
  vtkGetMacro(FanEndAngle, double);
  ///@}

  ///@{
  /**
   * Cone: axis (default (0, 0, 1)) and opening half-angle in degrees (default 45). The
   * rays are evenly spaced in azimuth about the axis, azimuth 0 as angle 0 of the fan.
   */
  vtkSetVector3Macro(ConeAxis, double);
  vtkGetVector3Macro(ConeAxis, double);
  vtkSetClampMacro(ConeAngle, double, 0.0, 180.0);
  vtkGetMacro(ConeAngle, double);
  ///@}

  ///@{
  /**
   * Explicit directions (LIST mode), one point per ray, in the static observer's frame.
   * Changing the points' contents re-executes the source (GetMTime includes them; call
   * Modified() on the points after SetPoint, as everywhere in VTK). Use double-precision
   * points (SetDataTypeToDouble): float directions are off by about 1e-8 from the start.
   */
  void SetDirections(vtkPoints* directions);
  vtkPoints* GetDirections();
  ///@}

  ///@{
  /**
   * Integration: stepper name ("rk4", "cash_karp54", "dopri5" (default), "dopri87",
   * "bulirsch_stoer"), tolerance (absolute = relative, default 1e-10), largest affine
   * parameter, step limit (default 100000), first step (default 1e-2).
   * MaxAffine 0 (the default) fits the metric: an asymptotically flat one (Schwarzschild, Kerr,
   * wormholes, warp drives) draws each ray until it has escaped (beyond EscapeRadius, 0: twice
   * the observer's distance from the origin and at least 20, moving out, the bending still ahead
   * below EscapeAngle, default 0.01 rad; "stop_reason_name" escaped) or met a horizon; Goedel
   * rays run 20 a (about one and a half windings); other metrics 20. A MaxAffine > 0 draws every
   * ray to that affine length (or a horizon), escaping or not.
   */
  vtkSetStringMacro(Stepper);
  vtkGetStringMacro(Stepper);
  vtkSetClampMacro(Tolerance, double, 1e-16, 1.0);
  vtkGetMacro(Tolerance, double);
  vtkSetClampMacro(MaxAffine, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaxAffine, double);
  vtkSetClampMacro(EscapeRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(EscapeRadius, double);
  vtkSetClampMacro(EscapeAngle, double, 1e-15, 3.2);
  vtkGetMacro(EscapeAngle, double);
  vtkSetClampMacro(MaxSteps, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaxSteps, int);
  vtkSetClampMacro(InitialStep, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(InitialStep, double);
  ///@}

  ///@{
  /**
   * Points per accepted step taken from the dense output (default 4, at least 1).
   */
  vtkSetClampMacro(SamplesPerStep, int, 1, 1000);
  vtkGetMacro(SamplesPerStep, int);
  ///@}

  ///@{
  /**
   * A closest approach to the z axis closer than this counts as an axis passage for the
   * "winding" array (default 1e-6, in units of the chart).
   */
  vtkSetClampMacro(AxisTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AxisTolerance, double);
  ///@}

  ///@{
  /**
   * Chart of the output points: EMBEDDING (default) or RPHIT.
   */
  /**
   * How rays are computed: AUTO (default: closed form for 'godel', numeric otherwise),
   * NUMERIC or CLOSED_FORM. Closed-form rays are sampled uniformly in the affine parameter
   * (SamplesPerStep points per 0.05 a) and have stop reason max_affine.
   */
  vtkSetClampMacro(Method, int, AUTO, CLOSED_FORM);
  vtkGetMacro(Method, int);
  void SetMethodToAuto() { this->SetMethod(AUTO); }
  void SetMethodToNumeric() { this->SetMethod(NUMERIC); }
  void SetMethodToClosedForm() { this->SetMethod(CLOSED_FORM); }

  vtkLightconeOutputChartMacro();
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkLightconeNullGeodesicSource();
  ~vtkLightconeNullGeodesicSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Observer[4] = { 0, 0, 0, 0 };
  char* MetricName = nullptr;
  std::map<std::string, double> MetricParameters;
  lc::SpacetimePtr Spacetime;
  int DirectionMode = FAN;
  int NumberOfRays = 16;
  double FanNormal[3] = { 0, 0, 1 };
  double FanStartAngle = 0.0;
  double FanEndAngle = 360.0;
  double ConeAxis[3] = { 0, 0, 1 };
  double ConeAngle = 45.0;
  vtkSmartPointer<vtkPoints> Directions;
  char* Stepper = nullptr;
  double Tolerance = 1e-10;
  double MaxAffine = 0.0;
  double EscapeRadius = 0.0;
  double EscapeAngle = 1e-2;
  int MaxSteps = 100000;
  double InitialStep = 1e-2;
  int SamplesPerStep = 4;
  double AxisTolerance = 1e-6;
  int Method = AUTO;
  int OutputChart = vtkLightconeOutputChart::EMBEDDING;

private:
  vtkLightconeNullGeodesicSource(const vtkLightconeNullGeodesicSource&) = delete;
  // The rays' unit directions in the observer's static frame (fan, cone or list); false after
  // reporting a bad setting.
  bool InitialDirections(std::vector<lc::Vec3>& dirs);
  void operator=(const vtkLightconeNullGeodesicSource&) = delete;
};

#endif
