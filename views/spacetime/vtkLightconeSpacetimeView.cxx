// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconeSpacetimeView.h"

#include "filters_from_scene.hpp"
#include "core/curvature/curvature_field.hpp"
#include "curvature_slice_image.hpp"
#include "vtkLightconeCurvatureAlongPath.h"
#include "vtkLightconeCurvatureSource.h"
#include "vtkLightconeGodelHorizonSource.h"
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeKerrHorizonSource.h"
#include "vtkLightconeKillingFieldSource.h"
#include "vtkLightconeMeshLoader.h"
#include "vtkLightconeNullGeodesicSource.h"
#include "vtkLightconeOutputChart.h"
#include "vtkLightconePhotoObjectFilter.h"
#include "vtkLightconeWorldLineSource.h"

#include <vtkActor.h>
#include <vtkArrayCalculator.h>
#include <vtkArrowSource.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellPicker.h>
#include <vtkColorTransferFunction.h>
#include <vtkCompositeDataDisplayAttributes.h>
#include <vtkCompositePolyDataMapper2.h>
#include <vtkCubeAxesActor.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkFlyingEdges3D.h>
#include <vtkGlyph3DMapper.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkSphereSource.h>
#include <vtkTextProperty.h>
#include <vtkVariant.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include <algorithm>
#include <array>
#include <cmath>

vtkStandardNewMacro(vtkLightconeSpacetimeView);

namespace {

using Chart = vtkLightconeOutputChart;

// The charts each layer's filter writes (bit 1 << chart).
constexpr int kEmbedding = 1 << Chart::EMBEDDING, kRPhiT = 1 << Chart::RPHIT, kXYT = 1 << Chart::XYT;
constexpr int kLayerCharts[vtkLightconeSpacetimeView::NUMBER_OF_LAYERS] = {
    kEmbedding | kRPhiT | kXYT, kEmbedding | kRPhiT, kEmbedding | kRPhiT, kEmbedding,
    kEmbedding | kXYT,          kEmbedding | kXYT,   kEmbedding,          kEmbedding};
constexpr const char* kLayerNames[vtkLightconeSpacetimeView::NUMBER_OF_LAYERS] = {
    "null geodesics",  "horizon",     "light cone",    "Killing field",
    "isometry orbits", "world lines", "photo-objects", "curvature"};

// Okabe-Ito: one colour per photo-object layer (winding, branch), colour-blind safe.
const double kLayerColours[][3] = {{0.90, 0.62, 0.0}, {0.34, 0.71, 0.91}, {0.0, 0.62, 0.45},  {0.80, 0.47, 0.65},
                                   {0.84, 0.37, 0.0}, {0.0, 0.45, 0.70},  {0.94, 0.89, 0.26}, {0.5, 0.5, 0.5}};
constexpr int kNumberOfLayerColours = 8;

void countExecution(vtkObject*, unsigned long, void* clientData, void*) { ++*static_cast<int*>(clientData); }

void watchExecutions(vtkAlgorithm* algorithm, int* counter) {
    vtkNew<vtkCallbackCommand> cb;
    cb->SetCallback(&countExecution);
    cb->SetClientData(counter);
    algorithm->AddObserver(vtkCommand::EndEvent, cb);
}

vtkSmartPointer<vtkScalarBarActor> makeScalarBar(vtkScalarsToColors* lut, const char* title, double x, double y) {
    auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
    bar->SetLookupTable(lut);
    bar->SetTitle(title);
    bar->SetNumberOfLabels(4);
    bar->SetPosition(x, y);
    bar->SetWidth(0.1);
    bar->SetHeight(0.38);
    bar->SetMaximumWidthInPixels(90);
    bar->GetTitleTextProperty()->SetFontSize(12);
    bar->GetLabelTextProperty()->SetFontSize(10);
    bar->UnconstrainedFontSizeOn();
    bar->VisibilityOff();
    return bar;
}

// Blue (spacelike, < 0) through white to red (timelike, > 0).
void makeDiverging(vtkLookupTable* lut) {
    const int n = 256;
    lut->SetNumberOfTableValues(n);
    for (int k = 0; k < n; ++k) {
        const double s = 2.0 * k / (n - 1) - 1.0, w = 1 - std::abs(s);
        const double* end = s < 0 ? kLayerColours[5] : kLayerColours[4];
        lut->SetTableValue(k, w + (1 - w) * end[0], w + (1 - w) * end[1], w + (1 - w) * end[2]);
    }
    lut->Build();
}

// The polyline of `lines` nearest to display point (x, y) closer than `distance` pixels (then
// lowered to its distance), -1 if none.
vtkIdType nearestPolyline(vtkRenderer* renderer, vtkPolyData* lines, double x, double y, double& distance) {
    std::vector<std::array<double, 2>> screen(static_cast<std::size_t>(lines->GetNumberOfPoints()));
    for (vtkIdType k = 0; k < lines->GetNumberOfPoints(); ++k) {
        const double* p = lines->GetPoint(k);
        renderer->SetWorldPoint(p[0], p[1], p[2], 1);
        renderer->WorldToDisplay();
        screen[static_cast<std::size_t>(k)] = {renderer->GetDisplayPoint()[0], renderer->GetDisplayPoint()[1]};
    }
    vtkIdType found = -1;
    for (vtkIdType cell = 0; cell < lines->GetNumberOfCells(); ++cell) {
        vtkIdType n = 0;
        const vtkIdType* ids = nullptr;
        lines->GetCellPoints(cell, n, ids);
        for (vtkIdType k = 0; k + 1 < n; ++k) {
            const auto& a = screen[static_cast<std::size_t>(ids[k])];
            const auto& b = screen[static_cast<std::size_t>(ids[k + 1])];
            const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
            const double s = len2 > 0 ? std::clamp(((x - a[0]) * dx + (y - a[1]) * dy) / len2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(a[0] + s * dx - x, a[1] + s * dy - y);
            if (d < distance) distance = d, found = cell;
        }
    }
    return found;
}

std::array<const char*, 6> axisTitles(int chart) {
    if (chart == Chart::RPHIT) return {"r", "chart units", "phi", "rad", "t", "chart units, c = 1"};
    return {"X",
            "chart units",
            "Y",
            "chart units",
            chart == Chart::XYT ? "t" : "z",
            chart == Chart::XYT ? "chart units, c = 1" : "chart units"};
}

}  // namespace

// Named, not anonymous: a member of Internals (the unity build includes this file in another).
namespace lc::views {

// One object's pipelines: its mesh, photo-object filter and world line source with their actors.
struct SpacetimeObjectPipeline {
    vtkNew<vtkSphereSource> Sphere;
    vtkNew<vtkPolyData> Mesh;
    std::vector<lc::Vec3> Positions;  // the mesh last converted (an unchanged mesh is not set again)
    std::vector<std::array<int, 3>> Triangles;
    int Input = -1;  // 0: Sphere, 1: Mesh
    vtkNew<vtkLightconePhotoObjectFilter> Photo;
    vtkNew<vtkCompositeDataDisplayAttributes> BlockColours;
    vtkNew<vtkCompositePolyDataMapper2> PhotoMapper;
    vtkNew<vtkActor> PhotoActor;
    vtkNew<vtkLightconeWorldLineSource> Line;
    vtkNew<vtkPolyDataMapper> LineMapper;
    vtkNew<vtkActor> LineActor;
    bool HasPhoto = false, HasLine = false;
    int SceneIndex = -1;  // spheres, then meshes (as lc::PixelRecord::object)

    SpacetimeObjectPipeline(int* photoCount, int* lineCount) {
        Photo->SetPointPlacementToDepth();
        PhotoMapper->SetInputConnection(Photo->GetOutputPort());
        PhotoMapper->SetCompositeDataDisplayAttributes(BlockColours);
        PhotoMapper->ScalarVisibilityOff();
        PhotoActor->SetMapper(PhotoMapper);
        LineMapper->SetInputConnection(Line->GetOutputPort());
        LineMapper->ScalarVisibilityOff();
        LineActor->SetMapper(LineMapper);
        LineActor->GetProperty()->SetColor(0.95, 0.85, 0.3);
        watchExecutions(Photo, photoCount);
        watchExecutions(Line, lineCount);
    }
    void SetSphere(double radius) {
        lc::views::configureSphereMesh(Sphere, radius);
        if (Input != 0) Photo->SetInputConnection(Sphere->GetOutputPort());
        Input = 0;
    }
    void SetMesh(const lc::MeshObject& m) {
        if (Input != 1 || m.positions != Positions || m.triangles != Triangles) {
            vtkNew<vtkPolyData> pd;
            lc::io::meshToPolyData(m, pd);
            Mesh->ShallowCopy(pd);
            Positions = m.positions;
            Triangles = m.triangles;
            Photo->SetInputData(Mesh);
            Photo->Modified();
        }
        Input = 1;
    }
};

}  // namespace lc::views
using lc::views::SpacetimeObjectPipeline;

struct vtkLightconeSpacetimeView::Internals {
    lc::Scene Scene;
    bool HasScene = false;
    bool ResetCamera = true;
    bool Visible[NUMBER_OF_LAYERS] = {true, true, false, false, false, true, true, false};
    int Executions[NUMBER_OF_ALGORITHMS] = {};
    double Combination[5] = {0, 1, 0, 0, 0};

    vtkNew<vtkRenderer> Renderer;
    vtkNew<vtkLightconeNullGeodesicSource> Geodesics;
    vtkNew<vtkPolyDataMapper> GeodesicMapper;
    vtkNew<vtkActor> GeodesicActor;
    vtkNew<vtkLightconeNullGeodesicSource> Highlight;
    vtkNew<vtkPoints> HighlightDirection;
    vtkNew<vtkPolyDataMapper> HighlightMapper;
    vtkNew<vtkActor> HighlightActor;
    bool HasHighlight = false;
    lc::Vec3 HighlightVector = lc::Vec3::Zero();
    vtkNew<vtkLightconeGodelHorizonSource> Horizon;
    vtkNew<vtkPolyDataMapper> HorizonMapper, LightConeMapper;
    vtkNew<vtkActor> HorizonActor, LightConeActor;
    // A Kerr-Newman hole's horizon layer: its event horizon and ergosurface.
    vtkNew<vtkLightconeKerrHorizonSource> KerrHorizon;
    vtkNew<vtkPolyDataMapper> KerrHorizonMapper;
    vtkNew<vtkActor> KerrHorizonActor;
    vtkNew<vtkLookupTable> SurfaceColours;
    bool HasKerrHorizon = false;
    vtkNew<vtkLightconeKillingFieldSource> Killing;
    vtkNew<vtkArrayCalculator> SignedNorm;  // norm times causal character: one scalar for both
    vtkNew<vtkArrowSource> Arrow;
    vtkNew<vtkGlyph3DMapper> GlyphMapper;
    vtkNew<vtkActor> KillingActor;
    vtkNew<vtkLightconeIsometryOrbitSource> Orbits;
    vtkNew<vtkPolyDataMapper> OrbitMapper;
    vtkNew<vtkActor> OrbitActor;
    std::vector<std::unique_ptr<SpacetimeObjectPipeline>> Objects;
    // The objects beyond MaxObjectsDrawn: a point at each centre.
    vtkNew<vtkPolyData> Crowd;
    vtkNew<vtkPolyDataMapper> CrowdMapper;
    vtkNew<vtkActor> CrowdActor;
    int Summarised = 0;
    vtkNew<vtkLightconeCurvatureSource> Curvature;
    std::string CurvatureQuantity = "kretschmann";
    vtkNew<vtkDataSetMapper> CurvatureMapper;
    vtkNew<vtkActor> CurvatureActor;
    vtkSmartPointer<vtkScalarBarActor> CurvatureBar;
    std::string CurvatureProblem;          // why the scene's metric has no curvature layer ("" when it has)
    vtkMTimeType CurvatureColouredAt = 0;  // the source output the slice's colours were made from
    int CurvatureColouredStyle = -1;       // and the style they were made for
    bool CurvatureDrawable = false;        // that output had a finite value to colour
    // The cube's styles: shells (drawn by CurvatureActor) and the volume.
    vtkNew<vtkFlyingEdges3D> CurvatureContour;
    std::vector<double> CurvatureLevels;
    vtkNew<vtkSmartVolumeMapper> CurvatureVolumeMapper;
    vtkNew<vtkVolume> CurvatureVolume;
    // The picked ray coloured by the same quantity, in the slice's colours, while the slice is drawn.
    vtkNew<vtkLightconeCurvatureAlongPath> HighlightCurvature;
    bool HighlightColoured = false;
    vtkMTimeType HighlightColouredAt = 0;  // the ray (with its quantity) those colours were made from

    vtkNew<vtkLookupTable> TimeColours, NormColours, BranchColours;
    vtkSmartPointer<vtkScalarBarActor> TimeBar, NormBar, BranchBar;
    vtkNew<vtkCubeAxesActor> Axes;
    vtkNew<vtkCellPicker> Picker;

    // The constructor's steps, one per layer or decoration.
    void SetUpRays();
    void SetUpHorizon();
    void SetUpKillingGlyphs();
    void SetUpOrbits();
    void SetUpCurvature();
    void ConfigureCurvature(int style);
    void ColourCurvature(int style);
    void DrawCurvatureCube(vtkImageData* shown, vtkLookupTable* colours, int style);
    void ColourHighlight(bool byCurvature);
    void SetUpLegends();
    void SetUpAxes();

    void Add(vtkActor* actor, vtkMapper* mapper, vtkAlgorithm* source, int port, const double rgb[3]) {
        mapper->SetInputConnection(source->GetOutputPort(port));
        actor->SetMapper(mapper);
        actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
        this->Renderer->AddActor(actor);
    }
};

namespace {
const double kWhite[3] = {1, 1, 1}, kMagenta[3] = {1, 0, 1}, kBlue[3] = {0.35, 0.55, 0.95},
             kOrange[3] = {0.95, 0.6, 0.2}, kGreen[3] = {0.3, 0.85, 0.45};
}  // namespace

void vtkLightconeSpacetimeView::Internals::SetUpRays() {
    // The fan, coloured by coordinate time along the rays.
    Geodesics->SetDirectionModeToFan();
    Geodesics->SetNumberOfRays(24);
    Add(GeodesicActor, GeodesicMapper, Geodesics, 0, kWhite);
    TimeColours->SetHueRange(0.667, 0.0);
    TimeColours->Build();
    GeodesicMapper->SetLookupTable(TimeColours);
    GeodesicMapper->SetScalarModeToUsePointFieldData();
    GeodesicMapper->SelectColorArray("t");
    GeodesicMapper->ScalarVisibilityOn();
    TimeBar = makeScalarBar(TimeColours, "t (rays)", 0.89, 0.08);

    HighlightDirection->SetDataTypeToDouble();
    HighlightDirection->InsertNextPoint(1, 0, 0);
    Highlight->SetDirectionModeToList();
    Highlight->SetDirections(HighlightDirection);
    Add(HighlightActor, HighlightMapper, Highlight, 0, kMagenta);
    HighlightMapper->ScalarVisibilityOff();
    HighlightMapper->UseLookupTableScalarRangeOn();
    HighlightActor->GetProperty()->SetLineWidth(5);
    HighlightCurvature->SetInputConnection(Highlight->GetOutputPort());
}

void vtkLightconeSpacetimeView::Internals::SetUpHorizon() {
    Add(HorizonActor, HorizonMapper, Horizon, 0, kBlue);
    Add(LightConeActor, LightConeMapper, Horizon, 1, kOrange);
    HorizonMapper->ScalarVisibilityOff();
    LightConeMapper->ScalarVisibilityOff();
    HorizonActor->GetProperty()->SetOpacity(0.25);
    LightConeActor->GetProperty()->SetOpacity(0.45);
    // Kerr-Newman: the event horizon blue as Goedel's, the ergosurface (static limit) orange,
    // both translucent (the ergosurface encloses the horizon), by the source's "surface" cells.
    KerrHorizon->SetPolarResolution(48);
    KerrHorizon->SetAzimuthResolution(96);
    Add(KerrHorizonActor, KerrHorizonMapper, KerrHorizon, 0, kBlue);
    SurfaceColours->SetNumberOfTableValues(4);
    SurfaceColours->SetTableRange(0, 3);
    SurfaceColours->SetTableValue(0, kBlue[0], kBlue[1], kBlue[2]);
    SurfaceColours->SetTableValue(1, kBlue[0], kBlue[1], kBlue[2]);
    SurfaceColours->SetTableValue(2, kOrange[0], kOrange[1], kOrange[2]);
    SurfaceColours->SetTableValue(3, kOrange[0], kOrange[1], kOrange[2]);
    SurfaceColours->Build();
    KerrHorizonMapper->SetLookupTable(SurfaceColours);
    KerrHorizonMapper->UseLookupTableScalarRangeOn();
    KerrHorizonMapper->SetScalarModeToUseCellFieldData();
    KerrHorizonMapper->SelectColorArray("surface");
    KerrHorizonMapper->ScalarVisibilityOn();
    KerrHorizonActor->GetProperty()->SetOpacity(0.35);
}

void vtkLightconeSpacetimeView::Internals::SetUpKillingGlyphs() {
    // Killing glyphs: arrows along the combination, coloured by sqrt|g(xi, xi)| signed by its
    // causal character.
    SignedNorm->SetInputConnection(Killing->GetOutputPort());
    SignedNorm->SetAttributeTypeToPointData();
    SignedNorm->AddScalarArrayName("combination_norm");
    SignedNorm->AddScalarArrayName("combination_causal");
    SignedNorm->SetFunction("combination_norm*combination_causal");
    SignedNorm->SetResultArrayName("signed_norm");
    SignedNorm->SetResultArrayType(VTK_DOUBLE);
    GlyphMapper->SetSourceConnection(Arrow->GetOutputPort());
    GlyphMapper->SetOrientationArray("combination");
    GlyphMapper->SetOrientationModeToDirection();
    GlyphMapper->SetScaling(false);
    GlyphMapper->SetScalarModeToUsePointFieldData();
    GlyphMapper->SelectColorArray("signed_norm");
    GlyphMapper->ScalarVisibilityOn();
    makeDiverging(NormColours);
    GlyphMapper->SetLookupTable(NormColours);
    GlyphMapper->UseLookupTableScalarRangeOn();
    Add(KillingActor, GlyphMapper, SignedNorm, 0, kWhite);
    NormBar = makeScalarBar(NormColours, "|xi| (+ timelike, - spacelike)", 0.89, 0.55);
}

void vtkLightconeSpacetimeView::Internals::SetUpOrbits() {
    Add(OrbitActor, OrbitMapper, Orbits, 0, kGreen);
    OrbitMapper->ScalarVisibilityOff();
    OrbitActor->GetProperty()->SetLineWidth(2);
}

void vtkLightconeSpacetimeView::Internals::SetUpCurvature() {
    vtkNew<vtkImageData> empty;  // until the layer is first drawn
    CurvatureMapper->SetInputData(empty);
    CurvatureMapper->UseLookupTableScalarRangeOn();
    CurvatureMapper->InterpolateScalarsBeforeMappingOn();
    CurvatureActor->SetMapper(CurvatureMapper);
    CurvatureActor->GetProperty()->SetOpacity(0.85);
    Renderer->AddActor(CurvatureActor);
    CurvatureBar = makeScalarBar(nullptr, "curvature", 0.08, 0.08);  // room for a long title on the left
    CurvatureContour->ComputeScalarsOn();  // each shell carries its level: coloured as the bar says
    CurvatureContour->ComputeNormalsOn();
    CurvatureVolume->SetMapper(CurvatureVolumeMapper);
    CurvatureVolume->SetVisibility(false);
    vtkNew<vtkImageData> none;
    CurvatureVolumeMapper->SetInputData(none);
    Renderer->AddVolume(CurvatureVolume);
}

void vtkLightconeSpacetimeView::Internals::ConfigureCurvature(int style) {
    CurvatureProblem = lc::views::configureCurvature(Curvature, Scene, CurvatureQuantity, style != CURVATURE_SLICE)
                           ? ""
                           : "the metric '" + Scene.spacetime->name() + "' is not written as expressions";
}

namespace {

// Whether a curvature quantity is drawn as log10 of its magnitude: the invariants span decades;
// matter and tides (measured by an observer) are drawn by value.
bool drawnOnLogScale(const std::string& name) {
    const auto quantity = lc::curvatureQuantityNamed(name);
    return quantity && !lc::curvatureQuantityInfo(*quantity).needsObserver;
}

// The drawn scalar with its non-finite points made finite for contouring and volume rendering:
// +inf (a singularity on a log scale) at the top of the range, -inf and NaN (log10 of a zero, an
// unsampled point) at the transparent end: the bottom, or 0 for a scale of both signs.
vtkSmartPointer<vtkImageData> finiteCopy(vtkImageData* shown, double lo, double hi, bool diverging) {
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->CopyStructure(shown);
    vtkDataArray* in = shown->GetPointData()->GetScalars();
    vtkNew<vtkDoubleArray> out;
    out->SetName(in->GetName());
    out->SetNumberOfTuples(in->GetNumberOfTuples());
    for (vtkIdType i = 0; i < in->GetNumberOfTuples(); ++i) {
        const double v = in->GetComponent(i, 0);
        out->SetValue(i, std::isfinite(v) ? v : v > 0 ? hi : (diverging && !(v < 0)) ? 0.0 : lo);
    }
    copy->GetPointData()->SetScalars(out);
    return copy;
}

}  // namespace

// Isosurfaces at six levels evenly spaced over the bar's range (never its ends), or the volume in
// the bar's colours with opacity growing as the square of the distance from the scale's quiet end
// (the bottom of a one-signed scale, 0 of a two-signed one) to 0.6 per sample spacing.
void vtkLightconeSpacetimeView::Internals::DrawCurvatureCube(vtkImageData* shown, vtkLookupTable* colours, int style) {
    const double lo = colours->GetTableRange()[0], hi = colours->GetTableRange()[1];
    const bool diverging = lo < 0 && hi > 0 && lo == -hi;
    vtkSmartPointer<vtkImageData> finite = finiteCopy(shown, lo, hi, diverging);
    if (style == CURVATURE_ISOSURFACES) {
        const int levels = 6;
        CurvatureContour->SetInputData(finite);
        CurvatureContour->SetNumberOfContours(levels);
        for (int k = 0; k < levels; ++k) {
            CurvatureLevels.push_back(lo + (k + 0.5) * (hi - lo) / levels);
            CurvatureContour->SetValue(k, CurvatureLevels.back());
        }
        CurvatureContour->Update();
        CurvatureMapper->SetInputData(CurvatureContour->GetOutput());
        return;
    }
    vtkNew<vtkColorTransferFunction> rgb;
    vtkNew<vtkPiecewiseFunction> opacity;
    const int samples = 32;
    for (int k = 0; k < samples; ++k) {
        const double v = lo + k * (hi - lo) / (samples - 1);
        double c[3];
        colours->GetColor(v, c);
        rgb->AddRGBPoint(v, c[0], c[1], c[2]);
        const double s = diverging ? v / hi : (v - lo) / (hi - lo);
        opacity->AddPoint(v, 0.6 * s * s);
    }
    CurvatureVolume->GetProperty()->SetColor(rgb);
    CurvatureVolume->GetProperty()->SetScalarOpacity(opacity);
    CurvatureVolume->GetProperty()->SetInterpolationTypeToLinear();
    CurvatureVolume->GetProperty()->SetScalarOpacityUnitDistance(shown->GetSpacing()[0]);
    CurvatureVolumeMapper->SetInputData(finite);
}

void vtkLightconeSpacetimeView::Internals::ColourCurvature(int style) {
    Curvature->Update();
    // Coloured again only when the source produced a new output or the style changed (a toggle or
    // a pick does neither).
    if (Curvature->GetOutput()->GetMTime() != CurvatureColouredAt || style != CurvatureColouredStyle) {
        CurvatureColouredAt = Curvature->GetOutput()->GetMTime();
        CurvatureColouredStyle = style;
        CurvatureLevels.clear();
        const lc::views::CurvatureColouring c =
            lc::views::colourCurvature(Curvature->GetOutput(), CurvatureQuantity, drawnOnLogScale(CurvatureQuantity));
        CurvatureDrawable = c.valid;
        if (c.valid) {
            CurvatureMapper->SetLookupTable(c.colours);
            CurvatureBar->SetLookupTable(c.colours);
            CurvatureBar->SetTitle(c.title.c_str());
            if (style == CURVATURE_SLICE)
                CurvatureMapper->SetInputData(c.shown);
            else
                DrawCurvatureCube(vtkImageData::SafeDownCast(c.shown), c.colours, style);
        }
    }
    CurvatureActor->SetVisibility(CurvatureDrawable && style != CURVATURE_VOLUME);
    // Shells half transparent, so that the inner ones show, and lit from all sides a little, so
    // that the dark bottom of the scale stands out from the background.
    CurvatureActor->GetProperty()->SetOpacity(style == CURVATURE_SLICE ? 0.85 : 0.5);
    CurvatureActor->GetProperty()->SetAmbient(style == CURVATURE_SLICE ? 0.0 : 0.3);
    CurvatureVolume->SetVisibility(CurvatureDrawable && style == CURVATURE_VOLUME);
    CurvatureBar->SetVisibility(CurvatureDrawable);
}

// The picked ray in magenta, or, while the curvature slice is drawn, coloured by the slice's
// quantity at each of its points in the slice's colours (what the light met on its way).
void vtkLightconeSpacetimeView::Internals::ColourHighlight(bool byCurvature) {
    if (byCurvature) {
        HighlightCurvature->SetSpacetime(Scene.spacetime);
        HighlightCurvature->SetQuantity(CurvatureQuantity.c_str());
        HighlightCurvature->Update();
        // Coloured again only for a new ray, quantity or colour scale.
        const vtkMTimeType traced = HighlightCurvature->GetOutput()->GetMTime();
        if (HighlightColoured && traced == HighlightColouredAt &&
            HighlightMapper->GetLookupTable() == CurvatureMapper->GetLookupTable())
            return;
        const lc::views::CurvatureColouring c = lc::views::colourCurvature(
            HighlightCurvature->GetOutput(), CurvatureQuantity, drawnOnLogScale(CurvatureQuantity));
        if (c.valid) {
            HighlightMapper->SetInputData(vtkPolyData::SafeDownCast(c.shown));
            HighlightMapper->SetLookupTable(CurvatureMapper->GetLookupTable());
            HighlightMapper->ScalarVisibilityOn();
            HighlightColoured = true;
            HighlightColouredAt = traced;
            return;
        }
    }
    if (HighlightColoured) HighlightMapper->SetInputConnection(Highlight->GetOutputPort());
    HighlightMapper->ScalarVisibilityOff();
    HighlightColoured = false;
}

void vtkLightconeSpacetimeView::Internals::SetUpLegends() {
    BranchColours->IndexedLookupOn();
    BranchBar = makeScalarBar(BranchColours, "photo-object layer", 0.01, 0.08);
    BranchBar->SetDrawAnnotations(true);
    // Tick labels before the bar, so that the annotations (the layer names) come after it.
    BranchBar->SetTextPosition(vtkScalarBarActor::PrecedeScalarBar);
    BranchBar->SetDrawTickLabels(false);
    BranchBar->SetPosition(0.01, 0.55);
    BranchBar->SetWidth(0.35);
    BranchBar->SetHeight(0.4);
    BranchBar->SetMaximumWidthInPixels(200);
    BranchBar->AnnotationTextScalingOff();
    BranchBar->SetBarRatio(0.15);
    BranchBar->GetAnnotationTextProperty()->SetFontSize(11);
    BranchBar->GetAnnotationTextProperty()->SetColor(0.9, 0.9, 0.9);
    for (vtkScalarBarActor* bar : {TimeBar.Get(), NormBar.Get(), BranchBar.Get(), CurvatureBar.Get()})
        Renderer->AddActor2D(bar);
}

void vtkLightconeSpacetimeView::Internals::SetUpAxes() {
    Axes->SetCamera(Renderer->GetActiveCamera());
    Axes->SetFlyModeToOuterEdges();
    Axes->UseBoundsOff();  // the camera fits the data, not the axes
    // Three significant digits without trailing zeros: VTK's "%-#6.3g" wrote "-2.00" and "0.00"
    // that ran together where two axes meet ("-2.0000.0").
    Axes->SetXLabelFormat("%.3g");
    Axes->SetYLabelFormat("%.3g");
    Axes->SetZLabelFormat("%.3g");
    for (int k = 0; k < 3; ++k) {
        Axes->GetTitleTextProperty(k)->SetColor(0.9, 0.9, 0.9);
        Axes->GetLabelTextProperty(k)->SetColor(0.8, 0.8, 0.8);
    }
    Axes->VisibilityOff();
    Renderer->AddActor(Axes);
}

vtkLightconeSpacetimeView::vtkLightconeSpacetimeView() : Internal(std::make_unique<Internals>()) {
    Internals& in = *this->Internal;
    in.Renderer->SetBackground(0.1, 0.1, 0.12);
    in.CrowdMapper->SetInputData(in.Crowd);
    in.CrowdMapper->ScalarVisibilityOff();
    in.CrowdActor->SetMapper(in.CrowdMapper);
    in.CrowdActor->GetProperty()->SetColor(0.75, 0.75, 0.75);
    in.CrowdActor->GetProperty()->SetPointSize(4);
    in.Renderer->AddActor(in.CrowdActor);
    int* count = in.Executions;
    watchExecutions(in.Geodesics, &count[GEODESIC_SOURCE]);
    watchExecutions(in.Highlight, &count[HIGHLIGHT_SOURCE]);
    watchExecutions(in.Horizon, &count[HORIZON_SOURCE]);
    watchExecutions(in.KerrHorizon, &count[HORIZON_SOURCE]);
    watchExecutions(in.Killing, &count[KILLING_FIELD_SOURCE]);
    watchExecutions(in.Orbits, &count[ORBIT_SOURCE]);
    watchExecutions(in.Curvature, &count[CURVATURE_SOURCE]);
    in.SetUpRays();
    in.SetUpHorizon();
    in.SetUpKillingGlyphs();
    in.SetUpOrbits();
    in.SetUpCurvature();
    in.SetUpLegends();
    in.SetUpAxes();
    in.Picker->SetTolerance(0.005);
    in.Picker->PickFromListOn();
    this->SetKillingCombination(in.Combination);
    this->ApplyVisibility();
}

vtkLightconeSpacetimeView::~vtkLightconeSpacetimeView() = default;

const char* vtkLightconeSpacetimeView::GetLayerName(int layer) {
    return layer >= 0 && layer < NUMBER_OF_LAYERS ? kLayerNames[layer] : "?";
}

void vtkLightconeSpacetimeView::SetScene(const lc::Scene& scene) {
    Internals& in = *this->Internal;
    // Refitted for a new scene or another metric (Goedel's rays to Kerr's hole); kept through an
    // edit of the same metric, as the user turned it.
    const bool sameMetric = in.HasScene && in.Scene.spacetime->name() == scene.spacetime->name() &&
                            in.Scene.spacetime->parameters() == scene.spacetime->parameters();
    in.ResetCamera = in.ResetCamera || !sameMetric;
    in.Scene = scene;
    in.HasScene = true;
    in.HasHighlight = false;
    lc::views::configureNullGeodesics(in.Geodesics, scene);
    lc::views::configureNullGeodesics(in.Highlight, scene);
    const double a = lc::views::sceneGodelA(scene);
    if (a > 0) {
        lc::views::configureHorizon(in.Horizon, scene);
        lc::views::configureKillingFields(in.Killing, scene);
        lc::views::configureOrbits(in.Orbits, scene);
        in.GlyphMapper->SetScaleFactor(0.2 * a);
    }
    const auto kn = scene.spacetime->kerrNewmanParameters();
    in.HasKerrHorizon = kn.has_value();
    if (kn) {
        in.KerrHorizon->SetMass(kn->mass);
        in.KerrHorizon->SetSpin(kn->spin);
        in.KerrHorizon->SetCharge(kn->charge);
    }
    this->ConfigureObjects(scene);
    in.ConfigureCurvature(this->CurvatureStyle);
    this->ApplyVisibility();
    this->Modified();
}

void vtkLightconeSpacetimeView::ClearScene() {
    this->Internal->HasScene = false;
    this->Internal->HasHighlight = false;
    this->ApplyVisibility();
    this->Modified();
}

bool vtkLightconeSpacetimeView::HasScene() const { return this->Internal->HasScene; }

void vtkLightconeSpacetimeView::ConfigureObjects(const lc::Scene& scene) {
    Internals& in = *this->Internal;
    const std::size_t count = scene.spheres.size() + scene.meshes.size();
    // The objects drawn in full: the first MaxObjectsDrawn and the selected one.
    std::vector<std::size_t> drawn;
    for (std::size_t k = 0; k < count && k < static_cast<std::size_t>(this->MaxObjectsDrawn); ++k) drawn.push_back(k);
    if (this->SelectedObject >= this->MaxObjectsDrawn && static_cast<std::size_t>(this->SelectedObject) < count)
        drawn.push_back(static_cast<std::size_t>(this->SelectedObject));
    while (in.Objects.size() > drawn.size()) {
        in.Renderer->RemoveActor(in.Objects.back()->PhotoActor);
        in.Renderer->RemoveActor(in.Objects.back()->LineActor);
        in.Objects.pop_back();
    }
    while (in.Objects.size() < drawn.size()) {
        in.Objects.push_back(std::make_unique<SpacetimeObjectPipeline>(&in.Executions[PHOTO_OBJECT_FILTERS],
                                                                       &in.Executions[WORLD_LINE_SOURCES]));
        // A new pipeline writes the chart shown (a selected crowd object gets one at any time).
        if (this->OutputChart != Chart::RPHIT) in.Objects.back()->Line->SetOutputChart(this->OutputChart);
        in.Renderer->AddActor(in.Objects.back()->PhotoActor);
        in.Renderer->AddActor(in.Objects.back()->LineActor);
    }
    vtkNew<vtkPoints> crowd;
    vtkNew<vtkCellArray> crowdCells;
    for (std::size_t k = 0, next = 0; k < count; ++k) {
        if (next < drawn.size() && drawn[next] == k) {
            ++next;
            continue;
        }
        const lc::Vec4& c =
            k < scene.spheres.size() ? scene.spheres[k].centre : scene.meshes[k - scene.spheres.size()].centre;
        crowdCells->InsertNextCell(1);
        crowdCells->InsertCellPoint(crowd->InsertNextPoint(c(1), c(2), c(3)));
    }
    in.Crowd->SetPoints(crowd);
    in.Crowd->SetVerts(crowdCells);
    in.Summarised = static_cast<int>(crowd->GetNumberOfPoints());
    const bool godel = lc::views::sceneGodelA(scene) > 0;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
        const std::size_t k = drawn[i];
        SpacetimeObjectPipeline& p = *in.Objects[i];
        p.SceneIndex = static_cast<int>(k);
        const bool sphere = k < scene.spheres.size();
        const lc::Vec4& centre = sphere ? scene.spheres[k].centre : scene.meshes[k - scene.spheres.size()].centre;
        const lc::Motion& motion = sphere ? scene.spheres[k].motion : scene.meshes[k - scene.spheres.size()].motion;
        if (sphere)
            p.SetSphere(scene.spheres[k].radius);
        else
            p.SetMesh(scene.meshes[k - scene.spheres.size()]);
        p.HasPhoto = lc::views::configurePhotoObject(p.Photo, scene, centre, motion);
        p.HasLine = lc::views::configureWorldLine(p.Line, scene, centre, motion);
        // Goedel photo-objects are written in the observer's frame (observer at the origin).
        const lc::Vec4& obs = scene.observer;
        if (godel)
            p.PhotoActor->SetPosition(obs(1), obs(2), obs(3));
        else
            p.PhotoActor->SetPosition(0, 0, 0);
    }
}

void vtkLightconeSpacetimeView::SetLayerVisibility(int layer, bool visible) {
    if (layer < 0 || layer >= NUMBER_OF_LAYERS || this->Internal->Visible[layer] == visible) return;
    this->Internal->Visible[layer] = visible;
    this->ApplyVisibility();
    this->Modified();
}

bool vtkLightconeSpacetimeView::GetLayerVisibility(int layer) const {
    return layer >= 0 && layer < NUMBER_OF_LAYERS && this->Internal->Visible[layer];
}

std::string vtkLightconeSpacetimeView::GetLayerUnavailableReason(int layer) const {
    const Internals& in = *this->Internal;
    if (layer < 0 || layer >= NUMBER_OF_LAYERS) return "no such layer";
    if (!in.HasScene) return "no scene";
    if (layer == HORIZON && in.HasKerrHorizon)
        return this->OutputChart == Chart::EMBEDDING ? ""
                                                     : "the Kerr-Newman horizon source writes the embedding chart only";
    const bool godelOnly = layer == HORIZON || layer == LIGHT_CONE || layer == KILLING_FIELD || layer == ORBITS;
    if (godelOnly && lc::views::sceneGodelA(in.Scene) <= 0)
        return std::string("the ") + kLayerNames[layer] + " of the Goedel universe: this scene's metric is '" +
               in.Scene.spacetime->name() + "'";
    if (!(kLayerCharts[layer] & (1 << this->OutputChart))) {
        std::string charts;
        for (int c : {Chart::EMBEDDING, Chart::RPHIT, Chart::XYT})
            if (kLayerCharts[layer] & (1 << c)) charts += std::string(charts.empty() ? "" : ", ") + Chart::GetName(c);
        return std::string("its filter writes the ") + charts + " chart(s) only";
    }
    const auto any = [&](bool SpacetimeObjectPipeline::*has) {
        return std::any_of(in.Objects.begin(), in.Objects.end(), [&](const auto& p) { return (*p).*has; });
    };
    if (layer == WORLD_LINES && !any(&SpacetimeObjectPipeline::HasLine))
        return "no object of this scene moves (world lines: Goedel free fall, constant velocity in Minkowski space)";
    if (layer == CURVATURE && !in.CurvatureProblem.empty()) return in.CurvatureProblem;
    if (layer == PHOTO_OBJECTS && !any(&SpacetimeObjectPipeline::HasPhoto) && in.Summarised == 0)
        return "no object the photo-object filter images (Goedel objects at rest, any object in Minkowski space)";
    return "";
}

void vtkLightconeSpacetimeView::SetOutputChart(int chart) {
    chart = std::clamp(chart, static_cast<int>(Chart::EMBEDDING), static_cast<int>(Chart::XYT));
    if (chart == this->OutputChart) return;
    Internals& in = *this->Internal;
    this->OutputChart = chart;
    // Each filter takes the charts it writes; a layer whose filter has no such chart is unavailable.
    in.Geodesics->SetOutputChart(chart);
    in.Highlight->SetOutputChart(chart);
    if (chart != Chart::XYT) in.Horizon->SetOutputChart(chart);
    if (chart != Chart::RPHIT) {
        in.Orbits->SetOutputChart(chart);
        for (auto& p : in.Objects) p->Line->SetOutputChart(chart);
    }
    in.ResetCamera = true;
    this->ApplyVisibility();
    this->Modified();
}

void vtkLightconeSpacetimeView::SetKillingCombination(const double c[5]) {
    Internals& in = *this->Internal;
    std::copy(c, c + 5, in.Combination);
    in.Killing->SetCoefficients(in.Combination);
    in.Orbits->SetCoefficients(in.Combination);
    this->Modified();
}

void vtkLightconeSpacetimeView::GetKillingCombination(double c[5]) const {
    std::copy(this->Internal->Combination, this->Internal->Combination + 5, c);
}

void vtkLightconeSpacetimeView::SetNumberOfRays(int rays) { this->Internal->Geodesics->SetNumberOfRays(rays); }

int vtkLightconeSpacetimeView::GetNumberOfRays() const { return this->Internal->Geodesics->GetNumberOfRays(); }

void vtkLightconeSpacetimeView::SetHighlightedRay(const lc::Vec3& direction, double affine) {
    Internals& in = *this->Internal;
    if (!in.HasScene || !(direction.norm() > 0)) return;
    const lc::Vec3 n = direction.normalized();
    in.HighlightVector = n;
    in.HighlightDirection->SetPoint(0, n(0), n(1), n(2));
    in.HighlightDirection->Modified();
    in.Highlight->SetMaxAffine(affine > 0 ? affine : lc::views::rayAffineLength(in.Scene));
    in.HasHighlight = true;
    this->ApplyVisibility();
    this->Modified();
}

void vtkLightconeSpacetimeView::ClearHighlightedRay() {
    this->Internal->HasHighlight = false;
    this->ApplyVisibility();
    this->Modified();
}

bool vtkLightconeSpacetimeView::HasHighlightedRay() const {
    return this->Internal->HasScene && this->Internal->HasHighlight;
}

vtkPolyData* vtkLightconeSpacetimeView::GetHighlightedRayCurvature() {
    Internals& in = *this->Internal;
    return in.HighlightColoured ? in.HighlightCurvature->GetOutput() : nullptr;
}

vtkPolyData* vtkLightconeSpacetimeView::GetHighlightedRay() {
    this->Internal->Highlight->Update();
    return this->Internal->Highlight->GetOutput();
}

int vtkLightconeSpacetimeView::GetNumberOfObjectsSummarised() const { return this->Internal->Summarised; }

void vtkLightconeSpacetimeView::SetSelectedObject(int object) {
    if (object == this->SelectedObject) return;
    // An object beyond MaxObjectsDrawn gets its pipelines while selected.
    const bool crowdChanges = object >= this->MaxObjectsDrawn || this->SelectedObject >= this->MaxObjectsDrawn;
    this->SelectedObject = object;
    if (crowdChanges && this->Internal->HasScene) this->ConfigureObjects(this->Internal->Scene);
    this->ApplyVisibility();
    this->Modified();
}

void vtkLightconeSpacetimeView::ApplyVisibility() {
    Internals& in = *this->Internal;
    auto drawn = [&](int layer) { return in.Visible[layer] && this->IsLayerAvailable(layer); };
    in.GeodesicActor->SetVisibility(drawn(GEODESICS));
    const bool godel = in.HasScene && lc::views::sceneGodelA(in.Scene) > 0;
    in.HorizonActor->SetVisibility(drawn(HORIZON) && godel);
    in.KerrHorizonActor->SetVisibility(drawn(HORIZON) && in.HasKerrHorizon);
    in.LightConeActor->SetVisibility(drawn(LIGHT_CONE));
    in.KillingActor->SetVisibility(drawn(KILLING_FIELD));
    in.OrbitActor->SetVisibility(drawn(ORBITS));
    in.HighlightActor->SetVisibility(this->HasHighlightedRay());
    for (std::size_t k = 0; k < in.Objects.size(); ++k) {
        SpacetimeObjectPipeline& p = *in.Objects[k];
        const bool selected = p.SceneIndex == this->SelectedObject;
        p.PhotoActor->SetVisibility(drawn(PHOTO_OBJECTS) && p.HasPhoto);
        p.PhotoActor->GetProperty()->SetOpacity(selected || this->SelectedObject < 0 ? 1.0 : 0.25);
        p.LineActor->SetVisibility(drawn(WORLD_LINES) && p.HasLine);
        p.LineActor->GetProperty()->SetLineWidth(selected ? 5 : 2);
    }
    in.CrowdActor->SetVisibility(drawn(PHOTO_OBJECTS) && in.Summarised > 0);
    in.TimeBar->SetVisibility(drawn(GEODESICS));
    in.NormBar->SetVisibility(drawn(KILLING_FIELD));
    in.BranchBar->SetVisibility(drawn(PHOTO_OBJECTS));
    in.CurvatureActor->SetVisibility(drawn(CURVATURE));
    in.CurvatureBar->SetVisibility(drawn(CURVATURE));
    in.CurvatureVolume->SetVisibility(drawn(CURVATURE) && this->CurvatureStyle == CURVATURE_VOLUME);
}

void vtkLightconeSpacetimeView::Update() {
    Internals& in = *this->Internal;
    this->ApplyVisibility();
    std::vector<vtkActor*> shown;
    for (int layer = 0; layer < NUMBER_OF_LAYERS; ++layer)
        for (vtkActor* actor : this->GetLayerActors(layer))
            if (actor->GetVisibility()) shown.push_back(actor);
    if (in.HighlightActor->GetVisibility()) shown.push_back(in.HighlightActor);
    // The curvature layer is coloured from its source's output first (its mapper takes a copy),
    // then the picked ray in its colours.
    const bool curvatureDrawn = in.CurvatureActor->GetVisibility();
    if (curvatureDrawn) in.ColourCurvature(this->CurvatureStyle);
    if (in.HighlightActor->GetVisibility()) in.ColourHighlight(curvatureDrawn && in.CurvatureDrawable);
    for (vtkActor* actor : shown)
        if (actor->GetVisibility()) actor->GetMapper()->Update();

    // The legends follow the data drawn.
    if (in.GeodesicActor->GetVisibility())
        if (vtkDataArray* t = in.Geodesics->GetOutput()->GetPointData()->GetArray("t"))
            in.GeodesicMapper->SetScalarRange(t->GetRange());
    if (in.KillingActor->GetVisibility())
        if (vtkDataArray* s =
                vtkDataSet::SafeDownCast(in.SignedNorm->GetOutput())->GetPointData()->GetArray("signed_norm")) {
            const double* r = s->GetRange();
            const double m = std::max({std::abs(r[0]), std::abs(r[1]), 1e-12});
            in.NormColours->SetTableRange(-m, m);
        }
    in.BranchColours->ResetAnnotations();
    int layers = 0;
    for (auto& p : in.Objects) {
        if (!p->PhotoActor->GetVisibility()) continue;
        vtkMultiBlockDataSet* blocks = p->Photo->GetOutput();
        for (unsigned b = 0; b < blocks->GetNumberOfBlocks(); ++b) {
            const double* rgb = kLayerColours[b % kNumberOfLayerColours];
            p->PhotoMapper->SetBlockColor(b + 1, rgb);  // flat index: the root is 0
            const char* name = blocks->HasMetaData(b) ? blocks->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()) : "";
            if (static_cast<int>(b) >= layers) in.BranchColours->SetAnnotation(vtkVariant(b), name ? name : "");
        }
        layers = std::max(layers, static_cast<int>(blocks->GetNumberOfBlocks()));
    }
    in.BranchColours->SetNumberOfTableValues(std::max(layers, 1));
    for (int b = 0; b < layers; ++b) {
        const double* rgb = kLayerColours[b % kNumberOfLayerColours];
        in.BranchColours->SetTableValue(b, rgb[0], rgb[1], rgb[2]);
    }
    in.BranchBar->SetVisibility(layers > 0);
    this->FitAxes();
}

void vtkLightconeSpacetimeView::FitAxes() {
    Internals& in = *this->Internal;
    // The axes span every visible layer; the camera fits the rays and the horizon when they are
    // shown (far images of high windings would make the observer's surroundings a dot).
    auto boundsOf = [&](std::initializer_list<int> layers, double bounds[6]) {
        vtkMath::UninitializeBounds(bounds);
        bool any = false;
        for (int layer : layers)
            for (vtkActor* actor : this->GetLayerActors(layer)) {
                const double* b = actor->GetVisibility() ? actor->GetBounds() : nullptr;
                if (!b || !vtkMath::AreBoundsInitialized(b)) continue;
                for (int k = 0; k < 3; ++k) {
                    bounds[2 * k] = any ? std::min(bounds[2 * k], b[2 * k]) : b[2 * k];
                    bounds[2 * k + 1] = any ? std::max(bounds[2 * k + 1], b[2 * k + 1]) : b[2 * k + 1];
                }
                any = true;
            }
        // The volume rendering is a prop of its own, not an actor.
        const double* v = in.CurvatureVolume->GetVisibility() ? in.CurvatureVolume->GetBounds() : nullptr;
        if (std::count(layers.begin(), layers.end(), CURVATURE) && v && vtkMath::AreBoundsInitialized(v)) {
            for (int k = 0; k < 3; ++k) {
                bounds[2 * k] = any ? std::min(bounds[2 * k], v[2 * k]) : v[2 * k];
                bounds[2 * k + 1] = any ? std::max(bounds[2 * k + 1], v[2 * k + 1]) : v[2 * k + 1];
            }
            any = true;
        }
        return any;
    };
    double all[6], core[6];
    const bool any =
        boundsOf({GEODESICS, HORIZON, LIGHT_CONE, KILLING_FIELD, ORBITS, WORLD_LINES, PHOTO_OBJECTS, CURVATURE}, all);
    in.Axes->SetVisibility(any);
    if (!any) return;
    in.Axes->SetBounds(all);
    const auto titles = axisTitles(this->OutputChart);
    in.Axes->SetXTitle(titles[0]);
    in.Axes->SetXUnits(titles[1]);
    in.Axes->SetYTitle(titles[2]);
    in.Axes->SetYUnits(titles[3]);
    in.Axes->SetZTitle(titles[4]);
    in.Axes->SetZUnits(titles[5]);
    if (in.ResetCamera) {
        // Oblique, from above the first quadrant: the rays' plane and the time or z axis both show.
        vtkCamera* camera = in.Renderer->GetActiveCamera();
        camera->SetFocalPoint(0, 0, 0);
        camera->SetPosition(0.6, -1.0, 0.9);
        camera->SetViewUp(0, 0, 1);
        // Goedel: the rays and the horizon; other metrics: everything drawn (the rays alone are
        // a star around the observer, and the objects may lie far from it).
        const bool godel = lc::views::sceneGodelA(in.Scene) > 0;
        in.Renderer->ResetCamera(godel && boundsOf({GEODESICS, HORIZON, LIGHT_CONE}, core) ? core : all);
        camera->Zoom(1.2);  // ResetCamera fits the bounds' sphere: its margins waste a third of the dock
        in.ResetCamera = false;
    }
}

std::vector<double> vtkLightconeSpacetimeView::GetCameraState() const {
    const Internals& in = *this->Internal;
    if (in.ResetCamera || !in.HasScene) return {};
    vtkCamera* camera = in.Renderer->GetActiveCamera();
    std::vector<double> state(10);
    camera->GetPosition(&state[0]);
    camera->GetFocalPoint(&state[3]);
    camera->GetViewUp(&state[6]);
    state[9] = camera->GetViewAngle();
    return state;
}

void vtkLightconeSpacetimeView::SetCameraState(const std::vector<double>& state) {
    if (state.size() != 10 || !std::all_of(state.begin(), state.end(), [](double v) { return std::isfinite(v); }))
        return;
    const lc::Vec3 position(state[0], state[1], state[2]), focal(state[3], state[4], state[5]),
        up(state[6], state[7], state[8]);
    const lc::Vec3 view = focal - position;
    if (!(view.norm() > 0) || !(up.cross(view).norm() > 1e-9 * up.norm() * view.norm()) || !(state[9] > 0) ||
        !(state[9] < 180))
        return;
    Internals& in = *this->Internal;
    vtkCamera* camera = in.Renderer->GetActiveCamera();
    camera->SetPosition(state[0], state[1], state[2]);
    camera->SetFocalPoint(state[3], state[4], state[5]);
    camera->SetViewUp(state[6], state[7], state[8]);
    camera->SetViewAngle(state[9]);
    in.Renderer->ResetCameraClippingRange();
    in.ResetCamera = false;
    this->Modified();
}

vtkLightconeSpacetimeView::PickResult vtkLightconeSpacetimeView::Pick(double x, double y) {
    Internals& in = *this->Internal;
    PickResult result;
    // Rays first: the polyline nearest to the click on the screen, within 5 pixels (a cell picker
    // takes the first line along the view direction, and the loops of the Goedel rays cross).
    double best = 5.0;
    auto nearestRay = [&](vtkActor* actor, vtkPolyData* lines) {
        if (!actor->GetVisibility()) return -1;
        const vtkIdType cell = nearestPolyline(in.Renderer, lines, x, y, best);
        return static_cast<int>(cell);
    };
    const int fanRay = nearestRay(in.GeodesicActor, in.Geodesics->GetOutput());
    const int highlight = nearestRay(in.HighlightActor, in.Highlight->GetOutput());
    if (highlight >= 0) {
        result.Kind = PickResult::RAY;
        result.Direction = in.HighlightVector;
        return result;
    }
    if (fanRay >= 0) {
        vtkCellData* cd = in.Geodesics->GetOutput()->GetCellData();
        vtkDataArray* psi = cd->GetArray("psi");
        vtkDataArray* phi0 = cd->GetArray("phi0");
        if (!psi || !phi0 || fanRay >= psi->GetNumberOfTuples()) return result;
        const double p = psi->GetTuple1(fanRay), f = phi0->GetTuple1(fanRay);
        result.Kind = PickResult::RAY;
        result.Ray = fanRay;
        result.Direction = lc::Vec3(std::sin(p) * std::cos(f), std::sin(p) * std::sin(f), std::cos(p));
        return result;
    }
    // Objects: the photo-object surface or world line under the mouse.
    in.Picker->InitializePickList();
    for (int layer : {WORLD_LINES, PHOTO_OBJECTS})
        for (vtkActor* actor : this->GetLayerActors(layer))
            if (actor->GetVisibility()) in.Picker->AddPickList(actor);
    if (!in.Picker->Pick(x, y, 0, in.Renderer)) return result;
    vtkActor* hit = in.Picker->GetActor();
    for (std::size_t k = 0; k < in.Objects.size(); ++k)
        if (hit == in.Objects[k]->PhotoActor.Get() || hit == in.Objects[k]->LineActor.Get()) {
            result.Kind = PickResult::OBJECT;
            result.Object = in.Objects[k]->SceneIndex;
        }
    return result;
}

vtkRenderer* vtkLightconeSpacetimeView::GetRenderer() { return this->Internal->Renderer; }

std::vector<vtkActor*> vtkLightconeSpacetimeView::GetLayerActors(int layer) const {
    const Internals& in = *this->Internal;
    std::vector<vtkActor*> actors;
    switch (layer) {
        case GEODESICS: actors.push_back(in.GeodesicActor); break;
        case HORIZON:
            actors.push_back(in.HorizonActor);
            actors.push_back(in.KerrHorizonActor);
            break;
        case LIGHT_CONE: actors.push_back(in.LightConeActor); break;
        case KILLING_FIELD: actors.push_back(in.KillingActor); break;
        case ORBITS: actors.push_back(in.OrbitActor); break;
        case WORLD_LINES:
            for (const auto& p : in.Objects) actors.push_back(p->LineActor);
            break;
        case PHOTO_OBJECTS:
            for (const auto& p : in.Objects) actors.push_back(p->PhotoActor);
            actors.push_back(in.CrowdActor);  // the axes and the camera fit the crowd's points too
            break;
        case CURVATURE: actors.push_back(in.CurvatureActor); break;
        default: break;
    }
    return actors;
}

vtkActor* vtkLightconeSpacetimeView::GetHighlightActor() const { return this->Internal->HighlightActor; }

int vtkLightconeSpacetimeView::GetExecutionCount(int algorithm) const {
    return algorithm >= 0 && algorithm < NUMBER_OF_ALGORITHMS ? this->Internal->Executions[algorithm] : 0;
}

vtkPolyData* vtkLightconeSpacetimeView::GetGeodesics() { return this->Internal->Geodesics->GetOutput(); }

void vtkLightconeSpacetimeView::SetCurvatureQuantity(const std::string& name) {
    Internals& in = *this->Internal;
    if (name == in.CurvatureQuantity || !lc::curvatureQuantityNamed(name)) return;
    in.CurvatureQuantity = name;
    if (in.HasScene) in.ConfigureCurvature(this->CurvatureStyle);
    this->Modified();
}

const char* vtkLightconeSpacetimeView::GetCurvatureStyleName(int style) {
    static const char* const names[NUMBER_OF_CURVATURE_STYLES] = {"slice", "isosurfaces", "volume"};
    return style >= 0 && style < NUMBER_OF_CURVATURE_STYLES ? names[style] : "?";
}

void vtkLightconeSpacetimeView::SetCurvatureStyle(int style) {
    if (style < 0 || style >= NUMBER_OF_CURVATURE_STYLES || style == this->CurvatureStyle) return;
    Internals& in = *this->Internal;
    this->CurvatureStyle = style;
    if (in.HasScene) in.ConfigureCurvature(style);
    in.ResetCamera = true;  // a cube has a height the slice has not
    this->ApplyVisibility();
    this->Modified();
}

std::vector<double> vtkLightconeSpacetimeView::GetCurvatureIsosurfaceLevels() const {
    const Internals& in = *this->Internal;
    return in.CurvatureActor->GetVisibility() && this->CurvatureStyle == CURVATURE_ISOSURFACES ? in.CurvatureLevels
                                                                                               : std::vector<double>{};
}

vtkVolume* vtkLightconeSpacetimeView::GetCurvatureVolume() const { return this->Internal->CurvatureVolume; }

std::string vtkLightconeSpacetimeView::GetCurvatureQuantity() const { return this->Internal->CurvatureQuantity; }

vtkImageData* vtkLightconeSpacetimeView::GetCurvatureField() {
    Internals& in = *this->Internal;
    if (!in.Visible[CURVATURE] || !this->IsLayerAvailable(CURVATURE)) return nullptr;
    in.Curvature->Update();
    return in.Curvature->GetOutput();
}

void vtkLightconeSpacetimeView::PrintSelf(ostream& os, vtkIndent indent) {
    this->Superclass::PrintSelf(os, indent);
    const Internals& in = *this->Internal;
    os << indent << "HasScene: " << in.HasScene << "\n"
       << indent << "OutputChart: " << Chart::GetName(this->OutputChart) << "\n"
       << indent << "SelectedObject: " << this->SelectedObject << "\n"
       << indent << "CurvatureStyle: " << GetCurvatureStyleName(this->CurvatureStyle) << "\n"
       << indent << "HighlightedRay: " << this->HasHighlightedRay() << "\n";
    for (int layer = 0; layer < NUMBER_OF_LAYERS; ++layer)
        os << indent << "Layer '" << kLayerNames[layer] << "': visible " << in.Visible[layer] << ", "
           << (this->IsLayerAvailable(layer) ? "available" : this->GetLayerUnavailableReason(layer)) << "\n";
    for (int a = 0; a < NUMBER_OF_ALGORITHMS; ++a)
        os << indent << "Executions[" << a << "]: " << in.Executions[a] << "\n";
}
