// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's parameters for each filter of filters/: the one mapping shared by `lightcone export`
// (app/commands/command_export.cpp) and the workbench's spacetime view (vtkLightconeSpacetimeView). Each
// function sets only what the scene decides (observer, metric, Goedel parameter, windings, an
// object's centre and motion) and leaves the caller's own choices (ray count, fan or cone, Killing
// combination) alone. A value that is already set is not set again, so a filter re-executes only
// when its part of the scene changed.
#include "core/scene/scene.hpp"

#include <string>

class vtkLightconeCurvatureSource;
class vtkLightconeGodelHorizonSource;
class vtkLightconeIsometryOrbitSource;
class vtkLightconeKillingFieldSource;
class vtkLightconeNullGeodesicSource;
class vtkLightconePhotoObjectFilter;
class vtkLightconeWorldLineSource;
class vtkPolyData;
class vtkSphereSource;

namespace lc::views {

// The Goedel parameter a of a 'godel' scene, 0 for any other metric.
double sceneGodelA(const Scene& scene);

// The observer's null geodesics in the scene's spacetime (kept while the metric and its
// parameters stay the same), followed for windings + 1 loops (Goedel) or 60 units of affine length.
void configureNullGeodesics(vtkLightconeNullGeodesicSource* source, const Scene& scene);
// The affine length configureNullGeodesics follows the rays for.
double rayAffineLength(const Scene& scene);

// Goedel scenes only (std::invalid_argument otherwise): the horizon and past light cone of the
// observer, the Killing fields on a grid of 6a x 6a x 2a around it, orbits through seeds along X.
void configureHorizon(vtkLightconeGodelHorizonSource* source, const Scene& scene);
void configureKillingFields(vtkLightconeKillingFieldSource* source, const Scene& scene);
void configureOrbits(vtkLightconeIsometryOrbitSource* source, const Scene& scene);

// One curvature quantity on a 161 x 161 slice at the observer's z and time: around the hole of an
// asymptotically flat metric (three capture radii, or 1.2 times the observer's distance), or the
// observer (Goedel: 3a around it; otherwise 10 units). False, leaving the source unchanged, when
// the metric is not written as expressions. `cube`: the same square's cube, 65^3 points centred on
// the slice (for isosurfaces and volume rendering).
bool configureCurvature(vtkLightconeCurvatureSource* source, const Scene& scene, const std::string& quantity,
                        bool cube = false);

// The mesh of a sphere the photo-object filter images.
void configureSphereMesh(vtkSphereSource* sphere, double radius);
// An object's photo-object (Goedel at rest: every winding and branch; Minkowski: the apparent
// mesh) and world line (Goedel free fall, Minkowski constant velocity); false where the filter has
// no mode for this object (the filter is then left unchanged).
bool configurePhotoObject(vtkLightconePhotoObjectFilter* filter, const Scene& scene, const Vec4& centre,
                          const Motion& motion);
bool configureWorldLine(vtkLightconeWorldLineSource* source, const Scene& scene, const Vec4& centre,
                        const Motion& motion);

}  // namespace lc::views
