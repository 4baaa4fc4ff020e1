// SPDX-License-Identifier: BSD-3-Clause
#include "filters_from_scene.hpp"

#include "core/godel/proper_time_world_line.hpp"
#include "core/metrics/godel.hpp"
#include "vtkLightconeCurvatureSource.h"
#include "vtkLightconeGodelHorizonSource.h"
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeKillingFieldSource.h"
#include "vtkLightconeNullGeodesicSource.h"
#include "vtkLightconePhotoObjectFilter.h"
#include "vtkLightconeWorldLineSource.h"

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lc::views {
namespace {

double requireGodelA(const Scene& scene) {
    const double a = sceneGodelA(scene);
    if (a <= 0)
        throw std::invalid_argument("this filter needs the 'godel' metric (got '" + scene.spacetime->name() + "')");
    return a;
}

bool sameMetric(const SpacetimePtr& a, const SpacetimePtr& b) {
    return a && b && a->name() == b->name() && a->parameters() == b->parameters();
}

}  // namespace

double sceneGodelA(const Scene& scene) { return scene.spacetime->godelRadius().value_or(0.0); }

double rayAffineLength(const Scene& scene) {
    const double a = sceneGodelA(scene);
    return a > 0 ? (scene.settings.windings + 1) * 2 * kPi * a : 60.0;
}

void configureNullGeodesics(vtkLightconeNullGeodesicSource* source, const Scene& scene) {
    if (!sameMetric(source->GetSpacetime(), scene.spacetime)) source->SetSpacetime(scene.spacetime);
    const Vec4& obs = scene.observer;
    source->SetObserver(obs(0), obs(1), obs(2), obs(3));
    source->SetStepper("dopri5");
    source->SetTolerance(1e-10);
    source->SetMaxAffine(rayAffineLength(scene));
}

bool configureCurvature(vtkLightconeCurvatureSource* source, const Scene& scene, const std::string& quantity,
                        bool cube) {
    const Spacetime& st = *scene.spacetime;
    if (!st.symbolic()) return false;
    const Vec4& o = scene.observer;
    double centre[2] = {o(1), o(2)}, half = 10;
    if (const double a = sceneGodelA(scene); a > 0) {
        half = 3 * a;
    } else if (st.asymptoticallyFlat()) {
        const FarField far = st.farField(o);
        centre[0] = far.centre(0), centre[1] = far.centre(1);
        half = std::max({3 * far.captureRadius, 1.2 * std::hypot(o(1) - centre[0], o(2) - centre[1]), 1.0});
    }
    if (!sameMetric(source->GetSpacetime(), scene.spacetime)) source->SetSpacetime(scene.spacetime);
    const int points = cube ? 65 : 161;
    const double spacing = 2 * half / (points - 1);
    source->SetDimensions(points, points, cube ? points : 1);
    source->SetTime(o(0));
    source->SetOrigin(centre[0] - half, centre[1] - half, cube ? o(3) - half : o(3));
    source->SetSpacing(spacing, spacing, cube ? spacing : 1);
    if (source->GetNumberOfQuantities() != 1 || quantity != source->GetQuantity(0)) {
        source->RemoveAllQuantities();
        source->AddQuantity(quantity.c_str());
    }
    return true;
}

void configureHorizon(vtkLightconeGodelHorizonSource* source, const Scene& scene) {
    const double a = requireGodelA(scene);
    const Vec4& obs = scene.observer;
    source->SetGodelA(a);
    source->SetObserver(obs(0), obs(1), obs(2), obs(3));
    source->SetZRange(obs(3) - 2 * a, obs(3) + 2 * a);
    source->GenerateLightConeOn();
    source->SetLightConeAffineLength(2 * kPi * a);
}

void configureKillingFields(vtkLightconeKillingFieldSource* source, const Scene& scene) {
    const double a = requireGodelA(scene);
    const Vec4& obs = scene.observer;
    source->SetGodelA(a);
    source->SetTime(obs(0));
    source->SetDimensions(25, 25, 5);
    source->SetOrigin(obs(1) - 3 * a, obs(2) - 3 * a, obs(3) - a);
    source->SetSpacing(0.25 * a, 0.25 * a, 0.5 * a);
}

void configureOrbits(vtkLightconeIsometryOrbitSource* source, const Scene& scene) {
    const double a = requireGodelA(scene);
    source->SetGodelA(a);
    // Seeds along X through the axis; new points only when they move (the source's MTime has them).
    vtkNew<vtkPoints> seeds;
    seeds->SetDataTypeToDouble();
    for (int k = -4; k <= 4; ++k) seeds->InsertNextPoint(0.4 * a * k, 0, 0);
    vtkPoints* old = source->GetSeeds();
    bool same = old && old->GetNumberOfPoints() == seeds->GetNumberOfPoints();
    for (vtkIdType p = 0; same && p < seeds->GetNumberOfPoints(); ++p) {
        double x[3], y[3];
        old->GetPoint(p, x);
        seeds->GetPoint(p, y);
        same = x[0] == y[0] && x[1] == y[1] && x[2] == y[2];
    }
    if (!same) source->SetSeeds(seeds);
    source->SetSeedTime(scene.observer(0));
    source->SetFlowRange(-1.5, 1.5);
}

void configureSphereMesh(vtkSphereSource* sphere, double radius) {
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
}

bool configurePhotoObject(vtkLightconePhotoObjectFilter* filter, const Scene& scene, const Vec4& centre,
                          const Motion& motion) {
    const double a = sceneGodelA(scene);
    const Vec4& obs = scene.observer;
    if (a > 0 && motion.kind == Motion::Kind::Rest) {
        filter->SetModeToGodel();
        filter->SetGodelA(a);
        filter->SetCentreEvent(centre(0), centre(1), centre(2), centre(3));
        filter->SetMaxWinding(scene.settings.windings);
    } else if (a <= 0 && scene.spacetime->name() == "minkowski") {
        filter->SetModeToSpecialRelativity();
        filter->SetBeta(motion.beta.data());
        filter->SetObjectOrigin(centre(0), centre(1), centre(2), centre(3));
    } else {
        return false;
    }
    filter->SetObserver(obs(0), obs(1), obs(2), obs(3));
    return true;
}

bool configureWorldLine(vtkLightconeWorldLineSource* source, const Scene& scene, const Vec4& centre,
                        const Motion& motion) {
    const double a = sceneGodelA(scene);
    if (a > 0 && motion.kind == Motion::Kind::FreeFall) {
        source->SetModeToGodelFreeFall();
        source->SetGodelA(a);
        source->SetEnergy(motion.k0);
        source->SetK3(motion.k3);
        source->SetAzimuth(motion.phi0 * 180 / kPi);
    } else if (motion.kind == Motion::Kind::ConstantVelocity) {
        source->SetModeToMinkowski();
        source->SetBeta(motion.beta.data());
    } else if (a > 0 && motion.kind == Motion::Kind::ProperTime) {
        // The whole trip: its own proper time from the centre event.
        source->SetModeToGodelProperTime();
        source->SetGodelA(a);
        source->SetProperTimeWorldLine(motion.properTimeLine);
        source->SetStartEvent(centre(0), centre(1), centre(2), centre(3));
        source->SetProperTimeRange(0, motion.properTimeLine->duration());
        source->SetNumberOfSamples(2000);
        return true;
    } else {
        return false;
    }
    source->SetStartEvent(centre(0), centre(1), centre(2), centre(3));
    source->SetProperTimeRange(-10, 2);
    return true;
}

}  // namespace lc::views
