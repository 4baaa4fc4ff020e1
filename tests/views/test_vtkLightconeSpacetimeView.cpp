// SPDX-License-Identifier: BSD-3-Clause
// The spacetime view: each layer toggled on draws its filter's output (the point count of the
// same filter run on its own here), filters re-execute only for what changed (toggles, observer
// moves, object edits, chart changes), a non-Goedel scene draws the layers that make sense and
// says why not the others, the highlighted ray is the closed-form Goedel ray, and a pick at a
// ray's projected point returns that ray. Oracles: the filters run independently, the closed form
// (lc::godel::OriginGeodesic). Runs under Xvfb.
#include "vtkLightconeSpacetimeView.h"

#include "core/godel/geodesic.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "filters_from_scene.hpp"
#include "readers/io/scene_reader.hpp"
#include "tests/common/spacetime_view_checks.hpp"
#include "vtkLightconeCurvatureSource.h"
#include "vtkLightconeGodelHorizonSource.h"
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeKillingFieldSource.h"
#include "vtkLightconeNullGeodesicSource.h"
#include "vtkLightconeOutputChart.h"
#include "vtkLightconePhotoObjectFilter.h"
#include "vtkLightconeWorldLineSource.h"

#include <vtkImageData.h>
#include <vtkAbstractVolumeMapper.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkMapper.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>
#include <vtkWindowToImageFilter.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace {

using View = vtkLightconeSpacetimeView;
using lc::test::drawnPoints;
using lc::test::runsSince;
const auto counts = lc::test::executions;

// data/default.json (a ball at rest) with a second sphere falling freely, so every layer has data.
lc::Scene godelScene() {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    lc::SphereObject faller = scene.spheres.at(0);
    faller.name = "faller";
    faller.centre = lc::Vec4(0, -0.8, 0.3, 0);
    faller.motion.kind = lc::Motion::Kind::FreeFall;
    faller.motion.k0 = 1.5;
    scene.spheres.push_back(faller);
    return scene;
}

// The point count of each layer's filter configured from the scene and run on its own.
vtkIdType independentPoints(int layer, const lc::Scene& scene, View* view) {
    switch (layer) {
        case View::GEODESICS: {
            vtkNew<vtkLightconeNullGeodesicSource> s;
            lc::views::configureNullGeodesics(s, scene);
            s->SetNumberOfRays(view->GetNumberOfRays());
            s->Update();
            return s->GetOutput()->GetNumberOfPoints();
        }
        case View::HORIZON:
        case View::LIGHT_CONE: {
            vtkNew<vtkLightconeGodelHorizonSource> s;
            lc::views::configureHorizon(s, scene);
            s->Update();
            return (layer == View::HORIZON ? s->GetHorizonOutput() : s->GetLightConeOutput())->GetNumberOfPoints();
        }
        case View::KILLING_FIELD: {
            vtkNew<vtkLightconeKillingFieldSource> s;
            lc::views::configureKillingFields(s, scene);
            s->Update();
            return vtkDataSet::SafeDownCast(s->GetOutputDataObject(0))->GetNumberOfPoints();
        }
        case View::ORBITS: {
            vtkNew<vtkLightconeIsometryOrbitSource> s;
            lc::views::configureOrbits(s, scene);
            s->Update();
            return s->GetOutput()->GetNumberOfPoints();
        }
        case View::CURVATURE: {
            vtkNew<vtkLightconeCurvatureSource> s;
            EXPECT_TRUE(lc::views::configureCurvature(s, scene, view->GetCurvatureQuantity()));
            s->Update();
            return s->GetOutput()->GetNumberOfPoints();
        }
        case View::WORLD_LINES: {
            vtkNew<vtkLightconeWorldLineSource> s;
            const auto& faller = scene.spheres.at(1);
            EXPECT_TRUE(lc::views::configureWorldLine(s, scene, faller.centre, faller.motion));
            s->Update();
            return s->GetOutput()->GetNumberOfPoints();
        }
        default: {
            vtkNew<vtkSphereSource> sphere;
            lc::views::configureSphereMesh(sphere, scene.spheres.at(0).radius);
            vtkNew<vtkLightconePhotoObjectFilter> f;
            EXPECT_TRUE(lc::views::configurePhotoObject(f, scene, scene.spheres[0].centre, scene.spheres[0].motion));
            f->SetPointPlacementToDepth();
            f->SetInputConnection(sphere->GetOutputPort());
            f->Update();
            return f->GetOutput()->GetNumberOfPoints();
        }
    }
}

int algorithmOf(int layer) {
    const int algorithms[View::NUMBER_OF_LAYERS] = {
        View::GEODESIC_SOURCE, View::HORIZON_SOURCE,     View::HORIZON_SOURCE,       View::KILLING_FIELD_SOURCE,
        View::ORBIT_SOURCE,    View::WORLD_LINE_SOURCES, View::PHOTO_OBJECT_FILTERS, View::CURVATURE_SOURCE};
    return algorithms[layer];
}

TEST(SpacetimeView, EachToggleDrawsItsFiltersPointsAndRunsOnlyThatFilter) {
    const lc::Scene scene = godelScene();
    vtkNew<View> view;
    for (int layer = 0; layer < View::NUMBER_OF_LAYERS; ++layer) view->SetLayerVisibility(layer, false);
    view->SetScene(scene);
    view->Update();
    for (int a = 0; a < View::NUMBER_OF_ALGORITHMS; ++a) EXPECT_EQ(view->GetExecutionCount(a), 0) << "hidden: " << a;

    for (int layer = 0; layer < View::NUMBER_OF_LAYERS; ++layer) {
        SCOPED_TRACE(View::GetLayerName(layer));
        ASSERT_TRUE(view->IsLayerAvailable(layer)) << view->GetLayerUnavailableReason(layer);
        const auto before = counts(view);
        view->SetLayerVisibility(layer, true);
        view->Update();
        const auto runs = runsSince(view, before);
        for (int a = 0; a < View::NUMBER_OF_ALGORITHMS; ++a)
            // The light cone shares its source with the horizon, which has run already.
            EXPECT_EQ(runs[static_cast<std::size_t>(a)], a == algorithmOf(layer) && layer != View::LIGHT_CONE ? 1 : 0)
                << "algorithm " << a;
        const auto actors = view->GetLayerActors(layer);
        ASSERT_FALSE(actors.empty());
        // Per object: the ball has a photo-object, the faller a world line.
        vtkActor* actor = actors[layer == View::WORLD_LINES ? 1 : 0];
        EXPECT_TRUE(actor->GetVisibility());
        EXPECT_TRUE(view->GetRenderer()->GetActors()->IsItemPresent(actor));
        EXPECT_GT(drawnPoints(actor), 0);
        EXPECT_EQ(drawnPoints(actor), independentPoints(layer, scene, view));

        // Off and on again: nothing re-executes.
        const auto shown = counts(view);
        view->SetLayerVisibility(layer, false);
        view->Update();
        EXPECT_FALSE(actor->GetVisibility());
        view->SetLayerVisibility(layer, true);
        view->Update();
        EXPECT_EQ(counts(view), shown);
    }
}

TEST(SpacetimeView, ObserverMoveRunsTheDependentFiltersOnceAndAnObjectEditOnlyItsOwn) {
    lc::Scene scene = godelScene();
    vtkNew<View> view;
    for (int layer = 0; layer < View::NUMBER_OF_LAYERS; ++layer) view->SetLayerVisibility(layer, true);
    view->SetScene(scene);
    view->Update();
    auto before = counts(view);
    for (int a = 0; a < View::NUMBER_OF_ALGORITHMS; ++a)  // no highlighted ray: its source has not run
        EXPECT_EQ(before[static_cast<std::size_t>(a)], a == View::HIGHLIGHT_SOURCE ? 0 : 1) << a;

    view->SetScene(godelScene());  // read again: a new metric object with the same parameters
    view->Update();
    EXPECT_EQ(runsSince(view, before), std::vector<int>(View::NUMBER_OF_ALGORITHMS, 0))
        << "the same scene again re-ran a filter";

    // The observer moves in space at the same time: the orbits (seeded at that time) and the world
    // lines stay; the highlight source is not drawn.
    scene.observer = lc::Vec4(0, -0.3, 0.2, 0);
    view->SetScene(scene);
    view->Update();
    const auto moved = runsSince(view, before);
    EXPECT_EQ(moved[View::GEODESIC_SOURCE], 1);
    EXPECT_EQ(moved[View::HORIZON_SOURCE], 1);
    EXPECT_EQ(moved[View::KILLING_FIELD_SOURCE], 1);
    EXPECT_EQ(moved[View::PHOTO_OBJECT_FILTERS], 1);
    EXPECT_EQ(moved[View::ORBIT_SOURCE], 0);
    EXPECT_EQ(moved[View::WORLD_LINE_SOURCES], 0);
    EXPECT_EQ(moved[View::HIGHLIGHT_SOURCE], 0);

    // A new radius of the ball: only its photo-object.
    before = counts(view);
    scene.spheres[0].radius = 0.3;
    view->SetScene(scene);
    view->Update();
    auto edited = runsSince(view, before);
    EXPECT_EQ(edited[View::PHOTO_OBJECT_FILTERS], 1);
    edited[View::PHOTO_OBJECT_FILTERS] = 0;
    EXPECT_EQ(edited, std::vector<int>(View::NUMBER_OF_ALGORITHMS, 0));

    // The r-phi-t chart: rays and horizon again; the Killing glyphs and photo-objects are not drawn.
    before = counts(view);
    view->SetOutputChart(vtkLightconeOutputChart::RPHIT);
    view->Update();
    const auto charted = runsSince(view, before);
    EXPECT_EQ(charted[View::GEODESIC_SOURCE], 1);
    EXPECT_EQ(charted[View::HORIZON_SOURCE], 1);
    EXPECT_EQ(charted[View::KILLING_FIELD_SOURCE], 0);
    EXPECT_FALSE(view->IsLayerAvailable(View::KILLING_FIELD));
    EXPECT_NE(view->GetLayerUnavailableReason(View::PHOTO_OBJECTS).find("Embedding"), std::string::npos);
    EXPECT_FALSE(view->GetLayerActors(View::KILLING_FIELD)[0]->GetVisibility());
}

TEST(SpacetimeView, NonGodelSceneDrawsTheLayersThatMakeSenseAndSaysWhyNotTheOthers) {
    const lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/sr_cube.json");
    vtkNew<View> view;
    for (int layer = 0; layer < View::NUMBER_OF_LAYERS; ++layer) view->SetLayerVisibility(layer, true);
    view->SetScene(scene);
    view->Update();
    for (int layer : {View::HORIZON, View::LIGHT_CONE, View::KILLING_FIELD, View::ORBITS}) {
        EXPECT_FALSE(view->IsLayerAvailable(layer)) << View::GetLayerName(layer);
        EXPECT_NE(view->GetLayerUnavailableReason(layer).find("'minkowski'"), std::string::npos)
            << view->GetLayerUnavailableReason(layer);
        EXPECT_FALSE(view->GetLayerActors(layer)[0]->GetVisibility());
    }
    EXPECT_EQ(view->GetExecutionCount(View::HORIZON_SOURCE) + view->GetExecutionCount(View::KILLING_FIELD_SOURCE) +
                  view->GetExecutionCount(View::ORBIT_SOURCE),
              0);
    // Rays in any metric, the moving cube's world line and its apparent shape.
    for (int layer : {View::GEODESICS, View::WORLD_LINES, View::PHOTO_OBJECTS}) {
        SCOPED_TRACE(View::GetLayerName(layer));
        EXPECT_TRUE(view->IsLayerAvailable(layer)) << view->GetLayerUnavailableReason(layer);
        EXPECT_GT(drawnPoints(view->GetLayerActors(layer)[0]), 0);
    }
}

TEST(SpacetimeView, HighlightedRayIsTheClosedFormRayAndAPickReturnsTheRayUnderTheMouse) {
    const lc::Scene scene = godelScene();  // observer at the origin: static frame = coordinate frame
    vtkNew<View> view;
    view->SetScene(scene);
    const lc::Vec3 n = lc::Vec3(0.6, -0.3, 0.2).normalized();
    const double affine = 2.5;
    view->SetHighlightedRay(n, affine);
    view->Update();
    vtkPolyData* ray = view->GetHighlightedRay();
    ASSERT_GT(ray->GetNumberOfPoints(), 10);
    const auto cf =
        lc::godel::OriginGeodesic::nullFromDirection(1.0, n(2), std::hypot(n(0), n(1)), std::atan2(n(1), n(0)), -1);
    const lc::Vec4 end = cf.cartesian(affine);
    double last[3];
    ray->GetPoint(ray->GetNumberOfPoints() - 1, last);
    EXPECT_NEAR(last[0], end(1), 1e-9);
    EXPECT_NEAR(last[1], end(2), 1e-9);
    EXPECT_NEAR(last[2], end(3), 1e-9);
    EXPECT_NEAR(ray->GetPointData()->GetArray("t")->GetTuple1(ray->GetNumberOfPoints() - 1), end(0), 1e-9);

    // A pick at a projected point of fan ray 5, away from its neighbours, returns ray 5 and its direction.
    view->ClearHighlightedRay();
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(500, 500);
    window->AddRenderer(view->GetRenderer());
    view->Update();
    window->Render();
    double p[3];
    ASSERT_TRUE(lc::test::isolatedPointOfRay(view->GetGeodesics(), 5, p));
    vtkRenderer* renderer = view->GetRenderer();
    renderer->SetWorldPoint(p[0], p[1], p[2], 1);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    const View::PickResult pick = view->Pick(d[0], d[1]);
    ASSERT_EQ(pick.Kind, View::PickResult::RAY);
    EXPECT_EQ(pick.Ray, 5);
    const double phi = 2 * lc::kPi * 5 / view->GetNumberOfRays();  // the fan in the horizontal plane
    EXPECT_NEAR((pick.Direction - lc::Vec3(std::cos(phi), std::sin(phi), 0)).norm(), 0, 1e-9);

    // The selected object (the faller) is drawn thick, the others faint.
    view->SetSelectedObject(1);
    EXPECT_DOUBLE_EQ(view->GetLayerActors(View::WORLD_LINES)[1]->GetProperty()->GetLineWidth(), 5);
    EXPECT_LT(view->GetLayerActors(View::PHOTO_OBJECTS)[0]->GetProperty()->GetOpacity(), 1);
}

// A Kerr hole's horizon layer (data/kerr.json, a = 0.9): every point lies on the event horizon,
// Boyer-Lindquist r+ = M + sqrt(M^2 - a^2), or on the ergosurface r_E = M + sqrt(M^2 - a^2 cos^2
// theta) (Misner, Thorne & Wheeler 1973, eq. 33.41), with r the Kerr-Schild radius of the point and
// cos theta = z / r; both are drawn. Another metric refits the camera; an edit of the same one
// keeps it where the user turned it.
TEST(SpacetimeView, KerrHorizonLayerDrawsTheEventHorizonAndTheErgosurface) {
    const lc::Scene godel = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/default.json");
    lc::Scene kerr = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/kerr.json");
    vtkNew<View> view;
    view->SetScene(godel);
    view->Update();
    const std::vector<double> godelCamera = view->GetCameraState();
    view->SetScene(kerr);
    ASSERT_TRUE(view->IsLayerAvailable(View::HORIZON)) << view->GetLayerUnavailableReason(View::HORIZON);
    view->Update();
    EXPECT_NE(view->GetCameraState(), godelCamera) << "another metric: refitted";
    vtkActor* surfaces = view->GetLayerActors(View::HORIZON)[1];
    ASSERT_TRUE(surfaces->GetVisibility());
    EXPECT_FALSE(view->GetLayerActors(View::HORIZON)[0]->GetVisibility());
    vtkPolyData* drawn = vtkPolyData::SafeDownCast(surfaces->GetMapper()->GetInput());
    ASSERT_NE(drawn, nullptr);
    const double a = 0.9, rPlus = 1 + std::sqrt(1 - a * a);
    int onHorizon = 0, onErgosurface = 0;
    for (vtkIdType id = 0; id < drawn->GetNumberOfPoints(); ++id) {
        double p[3];
        drawn->GetPoint(id, p);
        const double r = lc::kerrSchildRadius(p[0], p[1], p[2], a), c = p[2] / r;
        const double rE = 1 + std::sqrt(1 - a * a * c * c);
        const bool horizon = std::abs(r - rPlus) < 1e-9, ergo = std::abs(r - rE) < 1e-9;
        EXPECT_TRUE(horizon || ergo) << "r = " << r << ", r+ = " << rPlus << ", r_E = " << rE;
        onHorizon += horizon && !ergo;
        onErgosurface += ergo && !horizon;
    }
    EXPECT_GT(onHorizon, 1000);
    EXPECT_GT(onErgosurface, 1000);
    // The same metric, the observer moved: the camera stays as it was.
    vtkCamera* camera = view->GetRenderer()->GetActiveCamera();
    camera->Azimuth(25);
    const std::vector<double> turned = view->GetCameraState();
    kerr.observer(2) += 1;
    view->SetScene(kerr);
    view->Update();
    EXPECT_EQ(view->GetCameraState(), turned);
    // Charts the source does not write: unavailable, and said.
    view->SetOutputChart(vtkLightconeOutputChart::RPHIT);
    EXPECT_NE(view->GetLayerUnavailableReason(View::HORIZON).find("embedding chart only"), std::string::npos);
}

// Kretschmann of Kerr (Henry 2000): 48 M^2 (r^2 - a^2 c^2)(r^4 - 14 a^2 r^2 c^2 + a^4 c^4) / (r^2 +
// a^2 c^2)^6, c = cos theta, at a Kerr-Schild point (M = 1).
double henryKretschmann(const double p[3], double a) {
    const double r = lc::kerrSchildRadius(p[0], p[1], p[2], a), c = p[2] / r, a2c2 = a * a * c * c;
    return 48 * (r * r - a2c2) * (r * r * r * r - 14 * a * a * r * r * c * c + a2c2 * a2c2) / std::pow(r * r + a2c2, 6);
}

// The curvature layer in 3D (data/kerr.json, a = 0.9): the source samples a 65^3 cube; the six
// isosurfaces lie where Henry's closed form takes their levels (log10 K), to the contouring's
// linear interpolation along a grid edge (h^2/8 |f''|, f = log10 K ~ -6 log10 r); the volume
// rendering draws the same field in the bar's colours, transparent at the bottom of the scale, and
// shows in a render. An unknown style is ignored.
TEST(SpacetimeView, CurvatureIsosurfacesLieOnKerrsKretschmannLevelsAndTheVolumeDrawsTheField) {
    const lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/kerr.json");
    const double a = 0.9;
    vtkNew<View> view;
    view->SetScene(scene);
    view->SetGeodesicsVisibility(false);  // the camera fits the cube alone: the hole at the centre
    view->SetCurvatureVisibility(true);
    view->SetCurvatureStyle(View::CURVATURE_ISOSURFACES);
    view->SetCurvatureStyle(7);
    view->SetCurvatureStyle(-1);
    ASSERT_EQ(view->GetCurvatureStyle(), View::CURVATURE_ISOSURFACES);
    view->Update();
    vtkImageData* cube = view->GetCurvatureField();
    ASSERT_NE(cube, nullptr);
    int dims[3];
    cube->GetDimensions(dims);
    EXPECT_EQ(dims[0], 65);
    EXPECT_EQ(dims[1], 65);
    EXPECT_EQ(dims[2], 65);
    const double h = cube->GetSpacing()[0];
    EXPECT_DOUBLE_EQ(cube->GetSpacing()[2], h);

    const std::vector<double> levels = view->GetCurvatureIsosurfaceLevels();
    ASSERT_EQ(levels.size(), 6u);
    vtkActor* shells = view->GetLayerActors(View::CURVATURE)[0];
    ASSERT_TRUE(shells->GetVisibility());
    vtkPolyData* surface = vtkPolyData::SafeDownCast(shells->GetMapper()->GetInput());
    ASSERT_NE(surface, nullptr);
    vtkDataArray* level = surface->GetPointData()->GetScalars();
    ASSERT_NE(level, nullptr);
    ASSERT_GT(surface->GetNumberOfPoints(), 1000);
    std::array<int, 6> onLevel{};
    double worst = 0;
    int checked = 0;
    for (vtkIdType id = 0; id < surface->GetNumberOfPoints(); ++id) {
        double p[3];
        surface->GetPoint(id, p);
        const double r = lc::kerrSchildRadius(p[0], p[1], p[2], a);
        const auto k = std::find(levels.begin(), levels.end(), level->GetTuple1(id)) - levels.begin();
        ASSERT_LT(k, 6) << "a point off every level: " << level->GetTuple1(id);
        ++onLevel[static_cast<std::size_t>(k)];
        if (r < 4) continue;  // the ring's neighbourhood: log10 K is not smooth on the grid's scale
        const double bound = 2 * h * h / 8 * 6 / (std::log(10.0) * (r - h) * (r - h));
        const double error = std::abs(std::log10(henryKretschmann(p, a)) - level->GetTuple1(id));
        EXPECT_LT(error, bound) << "r = " << r;
        worst = std::max(worst, error);
        ++checked;
    }
    EXPECT_GT(checked, 1000);
    int shellsSeen = 0;
    for (int n : onLevel) shellsSeen += n > 0;
    EXPECT_GE(shellsSeen, 4) << "the levels span eight decades: most of them cross the cube";
    RecordProperty("worst_log10_error", std::to_string(worst));

    // The volume: the same cube, opaque only towards the top of the scale; seen in a render.
    view->SetCurvatureStyle(View::CURVATURE_VOLUME);
    view->Update();
    EXPECT_TRUE(view->GetCurvatureIsosurfaceLevels().empty());
    EXPECT_FALSE(shells->GetVisibility());
    vtkVolume* volume = view->GetCurvatureVolume();
    ASSERT_TRUE(volume->GetVisibility());
    vtkImageData* drawn = vtkImageData::SafeDownCast(volume->GetMapper()->GetDataSetInput());
    ASSERT_NE(drawn, nullptr);
    EXPECT_EQ(drawn->GetNumberOfPoints(), 65 * 65 * 65);
    vtkPiecewiseFunction* opacity = volume->GetProperty()->GetScalarOpacity();
    const double lo = levels.front() - (levels[1] - levels[0]) / 2, hi = levels.back() + (levels[1] - levels[0]) / 2;
    EXPECT_NEAR(opacity->GetValue(lo), 0, 1e-12);
    EXPECT_NEAR(opacity->GetValue(hi), 0.6, 1e-12);
    // Each point holds log10 of Henry's K where it is finite and within the scale.
    for (vtkIdType id = 0; id < drawn->GetNumberOfPoints(); id += 997) {
        double p[3];
        drawn->GetPoint(id, p);
        if (lc::kerrSchildRadius(p[0], p[1], p[2], a) < 2) continue;
        const double v = std::log10(std::abs(henryKretschmann(p, a)));
        if (v > lo) {
            EXPECT_NEAR(drawn->GetPointData()->GetScalars()->GetTuple1(id), v, 1e-9);
        }
    }
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(300, 300);
    window->AddRenderer(view->GetRenderer());
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->Update();
    vtkUnsignedCharArray* pixels = vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
    ASSERT_NE(pixels, nullptr);
    // The hole's neighbourhood, at the window's centre, glows in the scale's top colours.
    double centre[3];
    pixels->GetTuple(150 * 300 + 150, centre);
    EXPECT_GT(centre[0] + centre[1] + centre[2], 60) << "the volume's centre is not drawn";
}

}  // namespace
