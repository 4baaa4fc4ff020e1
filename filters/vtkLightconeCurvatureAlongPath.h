// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconeCurvatureAlongPath
 * @brief   curvature, matter or tides at every point of a path through spacetime (a light ray)
 *
 * vtkLightconeCurvatureAlongPath takes polydata whose points are the spatial chart coordinates
 * x^1..x^3 of events and whose point array TimeArrayName (default "t") holds their chart time,
 * as vtkLightconeNullGeodesicSource and vtkLightconeWorldLineSource write them in the EMBEDDING
 * chart of a Cartesian metric. It passes the input through and adds one point array, Quantity
 * (lc::curvatureQuantities(), default "kretschmann"), its value at each event, as the active
 * scalars: what the light of a picked pixel met on its way. Values come from the metric's exact
 * second derivatives (core/curvature, the same as vtkLightconeCurvatureSource's); NaN where the
 * metric is singular and, for observer quantities, where the observer field has none (the
 * field data "singular_points" and "points_without_observer" count them).
 *
 * The spacetime is required (SetSpacetime: the scene's, built-in or formula). Without it, without
 * the time array, or with an unknown quantity the output is empty and one error names the cause.
 *
 * @sa vtkLightconeCurvatureSource vtkLightconeNullGeodesicSource
 */
#ifndef vtkLightconeCurvatureAlongPath_h
#define vtkLightconeCurvatureAlongPath_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT
#include "vtkLightconeCurvatureSource.h" // its ObserverField values
#include "core/spacetime/spacetime.hpp"

#include <vtkPolyDataAlgorithm.h>

#include <string>

class LIGHTCONEFILTERS_EXPORT vtkLightconeCurvatureAlongPath : public vtkPolyDataAlgorithm
{
public:
  static vtkLightconeCurvatureAlongPath* New();
  vtkTypeMacro(vtkLightconeCurvatureAlongPath, vtkPolyDataAlgorithm) // no ";" (-Wpedantic)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The spacetime the path lies in (required).
   */
  void SetSpacetime(lc::SpacetimePtr spacetime);
  lc::SpacetimePtr GetSpacetime() const { return this->Spacetime; }
  ///@}

  ///@{
  /**
   * The quantity added (default "kretschmann"; one of lc::curvatureQuantities()).
   */
  vtkSetStringMacro(Quantity);
  vtkGetStringMacro(Quantity);
  ///@}

  ///@{
  /**
   * The point array holding each point's chart time (default "t").
   */
  vtkSetStringMacro(TimeArrayName);
  vtkGetStringMacro(TimeArrayName);
  ///@}

  ///@{
  /**
   * Lambda in G_ab = 8 pi T_ab + Lambda g_ab (default 0), as vtkLightconeCurvatureSource's.
   */
  vtkSetMacro(CosmologicalConstant, double);
  vtkGetMacro(CosmologicalConstant, double);
  ///@}

  ///@{
  /**
   * Which observers measure matter and tides: vtkLightconeCurvatureSource::AUTO (the default:
   * static where d/dt is timelike, else the normal observers of t = const), STATIC or NORMAL.
   */
  vtkSetClampMacro(
    ObserverField, int, vtkLightconeCurvatureSource::AUTO, vtkLightconeCurvatureSource::NORMAL);
  vtkGetMacro(ObserverField, int);
  ///@}

protected:
  vtkLightconeCurvatureAlongPath();
  ~vtkLightconeCurvatureAlongPath() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  lc::SpacetimePtr Spacetime;
  char* Quantity = nullptr;
  char* TimeArrayName = nullptr;
  double CosmologicalConstant = 0.0;
  int ObserverField = vtkLightconeCurvatureSource::AUTO;

private:
  vtkLightconeCurvatureAlongPath(const vtkLightconeCurvatureAlongPath&) = delete;
  void operator=(const vtkLightconeCurvatureAlongPath&) = delete;
};

#endif
