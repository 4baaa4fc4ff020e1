// SPDX-License-Identifier: BSD-3-Clause
// The Goedel horizon from an installed Lightcone: the core's closed-form light ray (leaving the
// axis in the plane, it turns back at r = 2a) and the VTK source's light cone of the origin,
// which reaches the horizon cylinder it draws and never passes it. Exit status 0 when all three
// agree on r = 2a (docs/PHYSICS.md section 2).
#include "core/godel/geodesic.hpp"
#include "vtkLightconeGodelHorizonSource.h"

#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

int main() {
    const double a = 1.5, halfPi = 0.5 * M_PI;
    const auto ray = lc::godel::OriginGeodesic::null(a, halfPi, 0.0, +1);
    vtkNew<vtkLightconeGodelHorizonSource> horizon;
    horizon->SetGodelA(a);
    horizon->SetLightConeSheet(vtkLightconeGodelHorizonSource::PLANAR);  // the rays in the plane
    horizon->SetLightConeAffineLength(10 * a);
    horizon->Update();
    // The largest distance from the axis of a port's points.
    const auto farthest = [&](int port) {
        vtkPolyData* points = horizon->GetOutput(port);
        double r = 0;
        for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
            double p[3];
            points->GetPoint(i, p);
            r = std::max(r, std::hypot(p[0], p[1]));
        }
        return r;
    };
    const double cylinder = farthest(0), cone = farthest(1);
    std::printf(
        "2a = %.12f: the closed-form ray turns at r = %.12f, the horizon cylinder lies at %.12f, "
        "the light cone reaches %.12f\n",
        2 * a, ray.rMax(), cylinder, cone);
    const bool ok = std::abs(ray.rMax() - 2 * a) < 1e-12 && std::abs(cylinder - 2 * a) < 1e-9 * a &&
                    cone <= 2 * a * (1 + 1e-12) && cone > 2 * a * (1 - 1e-2);
    return ok ? 0 : 1;
}
