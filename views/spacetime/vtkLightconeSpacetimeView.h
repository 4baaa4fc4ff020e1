// SPDX-License-Identifier: BSD-3-Clause
#ifndef vtkLightconeSpacetimeView_h
#define vtkLightconeSpacetimeView_h
// The spacetime view (3D): the filters of filters/ for one scene and observer as a real VTK
// pipeline, filter -> mapper -> actor, in a renderer any render window can show. Each layer
// (the observer's null geodesics, the Goedel horizon and light cone, Killing-field glyphs
// coloured by the signed norm of a chosen combination, its orbits, world lines, photo-objects)
// has a visibility toggle; only visible layers are updated, and the filters re-execute only when
// their own parameters changed (vtkSet macros call Modified() on a change only), so a toggle runs
// at most the filter of that layer and an observer move runs the ones that depend on it once.
// The scene's parameters reach the filters through filters_from_scene (shared with
// `lightcone export`). A highlighted ray is traced by a second null geodesic source in list mode.
#include "core/scene/scene.hpp"

#include <vtkObject.h>

#include <memory>
#include <string>
#include <vector>

class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;
class vtkVolume;

class vtkLightconeSpacetimeView : public vtkObject {
public:
    static vtkLightconeSpacetimeView* New();
    vtkTypeMacro(vtkLightconeSpacetimeView, vtkObject)
    void PrintSelf(ostream& os, vtkIndent indent) override;

    enum Layers {
        GEODESICS,
        HORIZON,
        LIGHT_CONE,
        KILLING_FIELD,
        ORBITS,
        WORLD_LINES,
        PHOTO_OBJECTS,
        CURVATURE,
        NUMBER_OF_LAYERS
    };
    // The algorithms whose executions are counted (one counter for all objects' filters of a kind).
    enum Algorithms {
        GEODESIC_SOURCE,
        HIGHLIGHT_SOURCE,
        HORIZON_SOURCE,
        KILLING_FIELD_SOURCE,
        ORBIT_SOURCE,
        WORLD_LINE_SOURCES,
        PHOTO_OBJECT_FILTERS,
        CURVATURE_SOURCE,
        NUMBER_OF_ALGORITHMS
    };
    static const char* GetLayerName(int layer);

    // Takes the scene's observer, metric and objects; drops the highlighted ray. Sets only what
    // changed, so nothing re-executes for an edit that does not touch a filter's parameters.
    void SetScene(const lc::Scene& scene);
    void ClearScene();
    bool HasScene() const;

    // A layer is drawn when it is visible and available: the Goedel-only layers need the 'godel'
    // metric, world lines a moving object, photo-objects objects the filter images, and each
    // layer a chart its filter writes. GetLayerUnavailableReason says why not ("" when available).
    void SetLayerVisibility(int layer, bool visible);
    bool GetLayerVisibility(int layer) const;
    bool IsLayerAvailable(int layer) const { return this->GetLayerUnavailableReason(layer).empty(); }
    std::string GetLayerUnavailableReason(int layer) const;
    void SetGeodesicsVisibility(bool on) { this->SetLayerVisibility(GEODESICS, on); }
    void SetHorizonVisibility(bool on) { this->SetLayerVisibility(HORIZON, on); }
    void SetLightConeVisibility(bool on) { this->SetLayerVisibility(LIGHT_CONE, on); }
    void SetKillingFieldVisibility(bool on) { this->SetLayerVisibility(KILLING_FIELD, on); }
    void SetOrbitsVisibility(bool on) { this->SetLayerVisibility(ORBITS, on); }
    void SetWorldLinesVisibility(bool on) { this->SetLayerVisibility(WORLD_LINES, on); }
    void SetPhotoObjectsVisibility(bool on) { this->SetLayerVisibility(PHOTO_OBJECTS, on); }
    void SetCurvatureVisibility(bool on) { this->SetLayerVisibility(CURVATURE, on); }

    // The curvature layer: one quantity of vtkLightconeCurvatureSource (lc::curvatureQuantities(),
    // default "kretschmann") on the plane of the observer's z at its time, around the hole of an
    // asymptotically flat metric (three capture radii, or the observer's distance) or the observer
    // (Goedel: three Goedel radii); curvature invariants coloured by log10 of their magnitude,
    // matter and tides (static-else-normal observers) by value, with a colour bar.
    void SetCurvatureQuantity(const std::string& name);
    std::string GetCurvatureQuantity() const;
    // The sampled field of the layer (updated; empty when the layer is not drawn).
    vtkImageData* GetCurvatureField();
    // How the layer draws the quantity: on the slice (default), or sampled in a cube of the slice's
    // width centred on it (65^3 points) and drawn as six isosurfaces evenly spaced over the colour
    // bar's range (translucent shells in its colours), or by volume rendering (the colours, opaque
    // where the quantity is large: its magnitude's top decades, or both signs' extremes).
    enum CurvatureStyles { CURVATURE_SLICE, CURVATURE_ISOSURFACES, CURVATURE_VOLUME, NUMBER_OF_CURVATURE_STYLES };
    static const char* GetCurvatureStyleName(int style);
    void SetCurvatureStyle(int style);  // ignored outside CurvatureStyles
    vtkGetMacro(CurvatureStyle, int);
    // The isosurfaces' levels in the drawn scalar (log10 |value| for invariants), ascending; empty
    // unless they are drawn.
    std::vector<double> GetCurvatureIsosurfaceLevels() const;
    // The volume rendering's prop (drawn only in the CURVATURE_VOLUME style).
    vtkVolume* GetCurvatureVolume() const;

    // The chart of every layer (vtkLightconeOutputChart: EMBEDDING (default), RPHIT, XYT).
    void SetOutputChart(int chart);
    vtkGetMacro(OutputChart, int);
    // The Killing combination c1 d/dt + c2 d/dphi + c3 d/dz + c4 xi4 + c5 xi5 of the glyphs and the
    // orbits (default (0, 1, 0, 0, 0), the rotation).
    void SetKillingCombination(const double c[5]);
    void GetKillingCombination(double c[5]) const;
    // Rays of the fan in the observer's horizontal plane (default 24).
    void SetNumberOfRays(int rays);
    int GetNumberOfRays() const;

    // The highlighted ray: a unit direction in the observer's static frame (the camera's frame of a
    // static observer) traced for `affine` (<= 0: as long as the fan's rays).
    void SetHighlightedRay(const lc::Vec3& direction, double affine);
    void ClearHighlightedRay();
    bool HasHighlightedRay() const;
    vtkPolyData* GetHighlightedRay();  // the highlight source's output (updated)
    // While the curvature slice is drawn the highlighted ray is coloured by the slice's quantity at
    // each of its points, in the slice's colours: that ray with the quantity's array
    // (vtkLightconeCurvatureAlongPath's output, as of the last Update()); nullptr otherwise.
    vtkPolyData* GetHighlightedRayCurvature();
    // The object (spheres, then meshes, as lc::PixelRecord::object) whose photo-objects and world
    // line are drawn opaque and thick, the others faint; -1: none.
    void SetSelectedObject(int object);
    vtkGetMacro(SelectedObject, int);
    // Crowded scenes: photo-objects and world lines are drawn for the first MaxObjectsDrawn objects
    // and the selected one; the others are points at their centres, one actor in the photo-object
    // layer (3000 spheres, one pipeline each, took the workbench to 6 GB). Default 24; takes
    // effect at the next SetScene or SetSelectedObject.
    vtkSetClampMacro(MaxObjectsDrawn, int, 0, 1000000);
    vtkGetMacro(MaxObjectsDrawn, int);
    // How many objects the last SetScene or SetSelectedObject drew as points only.
    int GetNumberOfObjectsSummarised() const;

    // What a click at display point (x, y) (VTK: origin bottom left) hits: the ray of the fan or
    // the highlight nearest on the screen within 5 pixels (its id in the fan, -1 for the highlight,
    // and its initial direction), else an object's photo-object or world line (vtkCellPicker).
    // Picks only what is drawn; Update() and render first.
    struct PickResult {
        enum Kinds { NOTHING, RAY, OBJECT };
        int Kind = NOTHING;
        int Ray = -1;  // cell id in the fan (-1: the highlighted ray)
        lc::Vec3 Direction = lc::Vec3::Zero();
        int Object = -1;
    };
    PickResult Pick(double x, double y);

    // The 3D camera as ten numbers (position, focal point, view up, view angle in degrees), for
    // sessions; empty while a refit is pending (a new scene or chart not drawn yet). Set, it stays
    // through the next Update instead of the refit; ignored unless ten finite numbers with the
    // position off the focal point and a view up across the view.
    std::vector<double> GetCameraState() const;
    void SetCameraState(const std::vector<double>& state);

    // Brings every visible layer up to date (what a render does), fits the axes to them, shows the
    // colour legends of the scalars drawn and resets the camera after a new scene or chart.
    void Update();
    vtkRenderer* GetRenderer();
    // The actors of a layer (per object for world lines and photo-objects).
    std::vector<vtkActor*> GetLayerActors(int layer) const;
    vtkActor* GetHighlightActor() const;
    // How often each algorithm has executed (RequestData completed, vtkCommand::EndEvent).
    int GetExecutionCount(int algorithm) const;
    // The fan's source output, for pickers and tests.
    vtkPolyData* GetGeodesics();

protected:
    vtkLightconeSpacetimeView();
    ~vtkLightconeSpacetimeView() override;

private:
    struct Internals;
    std::unique_ptr<Internals> Internal;
    int OutputChart = 0;
    int SelectedObject = -1;
    int MaxObjectsDrawn = 24;
    int CurvatureStyle = CURVATURE_SLICE;

    void ConfigureObjects(const lc::Scene& scene);
    void ApplyVisibility();
    void FitAxes();

    vtkLightconeSpacetimeView(const vtkLightconeSpacetimeView&) = delete;
    void operator=(const vtkLightconeSpacetimeView&) = delete;
};

#endif
