// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightconePhotoObjectFilter
 * @brief   photo-object of a triangle mesh: where an observer sees each vertex
 *
 * vtkLightconePhotoObjectFilter takes a vtkPolyData triangle mesh given in the local flat
 * frame at its centre (other polygons are triangulated with vtkTriangleFilter; lines and
 * vertices are ignored) and produces a vtkMultiBlockDataSet of vtkPolyData blocks.
 *
 * Mode GODEL (default): lc::buildPhotoObject (core/render/photo_scene.hpp, the builder the CPU
 * renderers use) finds every image of every vertex seen by the static observer at Observer for
 * windings 0..MaxWinding on both branches, the mesh centred at the world event CentreEvent
 * (vertex v goes to Isometry::movingOriginTo(a, centre).apply((0, v))). At rest (default
 * motion): the inverse problem of each static vertex, with stitching of the two branches of a
 * winding when Stitch is on (default). In free fall or along a world line (SetMotion; the
 * centre event is then the body's tau = 0): the emission event on each vertex's own world line,
 * with its frequency ratio. Block 2n + b
 * (b = 0 outbound, 1 inbound) is the layer (winding n, branch b), named
 * "winding n outbound" / "winding n inbound"; it holds the triangles of the layer (all three
 * vertices imaged) and their vertices only. Points in the observer's frame (observer at the
 * origin): the unit sky direction (PointPlacement DIRECTION, default) or depth * direction
 * (DEPTH). Point data: "direction" (3), "depth" (affine length lambda, unit observed
 * frequency), "emission_time" (world chart), "frequency_ratio" (1: static emitter and
 * observer), "welded" (0/1, moved by stitching), "vertex_id" (input point id). Cell data:
 * "winding", "branch" (0 outbound, 1 inbound), "triangle_id" (index in the triangulated input).
 * Field data of every block and of the multiblock: "beyond_horizon" (ids of the input vertices at
 * r >= 2a from the observer, which have no image at all) and "welded_vertices" (count).
 *
 * Mode SPECIAL_RELATIVITY: the mesh is at rest in a frame moving with velocity Beta, whose
 * origin passes the event ObjectOrigin (t, x, y, z); observer at rest at Observer. One
 * block "apparent": the mesh with each vertex at its apparent position, where it was at the
 * emission of the light that reaches the observer (seed 003 eq. 5-8, lc::sr::emissionEvent).
 * Point data "emission_time", "doppler" (D = 1/(gamma (1 - beta . n)), n the unit direction
 * from the emission point to the observer), "vertex_id", and the input's point arrays (rest
 * normals, texture coordinates) passed through.
 *
 * An empty mesh gives an empty multiblock and a warning. Bad parameters (|beta| >= 1, a <= 0)
 * are errors (vtkErrorMacro) with an empty output.
 */
#ifndef vtkLightconePhotoObjectFilter_h
#define vtkLightconePhotoObjectFilter_h

#include "lightconeFiltersModule.h" // LIGHTCONEFILTERS_EXPORT
#include "vtkLightconeOutputChart.h" // vtkLightconeGodelAMacro

#include <vtkMultiBlockDataSetAlgorithm.h>
#include <vtkSmartPointer.h>

#include <memory>

class vtkPolyData;
namespace lc
{
struct Motion;
struct PhotoSceneLayer;
struct PhotoSceneObject;
namespace godel
{
struct Mesh;
}
}

class LIGHTCONEFILTERS_EXPORT vtkLightconePhotoObjectFilter : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkLightconePhotoObjectFilter* New();
  vtkTypeMacro(vtkLightconePhotoObjectFilter, vtkMultiBlockDataSetAlgorithm) // no ";"
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    GODEL = 0,
    SPECIAL_RELATIVITY = 1
  };
  enum PointPlacements
  {
    DIRECTION = 0,
    DEPTH = 1
  };

  ///@{
  /**
   * GODEL (default) or SPECIAL_RELATIVITY.
   */
  vtkSetClampMacro(Mode, int, GODEL, SPECIAL_RELATIVITY);
  vtkGetMacro(Mode, int);
  void SetModeToGodel() { this->SetMode(GODEL); }
  void SetModeToSpecialRelativity() { this->SetMode(SPECIAL_RELATIVITY); }
  ///@}

  ///@{
  /**
   * Goedel parameter a > 0 (default 1).
   */
  vtkLightconeGodelAMacro();
  ///@}

  ///@{
  /**
   * Observer event (both modes; default (0, 0, 0, 0)); Goedel: centre event of the mesh
   * (default (0, 1, 0, 0)).
   */
  vtkSetVector4Macro(Observer, double);
  vtkGetVector4Macro(Observer, double);
  vtkSetVector4Macro(CentreEvent, double);
  vtkGetVector4Macro(CentreEvent, double);
  ///@}

  ///@{
  /**
   * Goedel: highest winding (default 2), stitching (default on).
   */
  vtkSetClampMacro(MaxWinding, int, 0, 1000);
  vtkGetMacro(MaxWinding, int);
  vtkSetMacro(Stitch, bool);
  vtkGetMacro(Stitch, bool);
  vtkBooleanMacro(Stitch, bool);
  ///@}

  ///@{
  /**
   * Goedel: how the mesh moves (core/scene/scene.hpp): at rest (default), in free fall (energy
   * k0, dz/dtau k3, azimuth phi0 of the geodesic through CentreEvent) or along a world line of
   * its centre (events in the world chart). Constant velocity is for special relativity only
   * (an error here).
   */
  void SetMotion(const lc::Motion& motion);
  const lc::Motion& GetMotion() const { return *this->BodyMotion; }
  ///@}

  ///@{
  /**
   * Goedel: layers already solved by lc::buildPhotoObject for this input mesh (e.g. shared with the
   * CPU per-vertex renderer, or built on a worker thread); the filter then only turns them into
   * blocks and ignores Observer, CentreEvent, Motion, MaxWinding, Stitch and CameraFrame. Null
   * (default): the filter solves them. A vertex count other than the input's is an error.
   */
  void SetPhotoObject(std::shared_ptr<const lc::PhotoSceneObject> solved);
  ///@}

  ///@{
  /**
   * Goedel: directions in the observer's local static frame, the camera's (on), or in the
   * observer's chart (off, default).
   */
  vtkSetMacro(CameraFrame, bool);
  vtkGetMacro(CameraFrame, bool);
  vtkBooleanMacro(CameraFrame, bool);
  ///@}

  ///@{
  /**
   * Goedel: points on the unit sphere around the observer (DIRECTION, default) or at
   * distance depth (DEPTH).
   */
  vtkSetClampMacro(PointPlacement, int, DIRECTION, DEPTH);
  vtkGetMacro(PointPlacement, int);
  void SetPointPlacementToDirection() { this->SetPointPlacement(DIRECTION); }
  void SetPointPlacementToDepth() { this->SetPointPlacement(DEPTH); }
  ///@}

  ///@{
  /**
   * Special relativity: velocity of the object (default (0.5, 0, 0)) and an event on the
   * world line of its origin (default (0, 0, 0, -5)).
   */
  vtkSetVector3Macro(Beta, double);
  vtkGetVector3Macro(Beta, double);
  vtkSetVector4Macro(ObjectOrigin, double);
  vtkGetVector4Macro(ObjectOrigin, double);
  ///@}

protected:
  vtkLightconePhotoObjectFilter();
  ~vtkLightconePhotoObjectFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = GODEL;
  double GodelA = 1.0;
  double Observer[4] = { 0.0, 0.0, 0.0, 0.0 };
  double CentreEvent[4] = { 0.0, 1.0, 0.0, 0.0 };
  int MaxWinding = 2;
  bool Stitch = true;
  int PointPlacement = DIRECTION;
  bool CameraFrame = false;
  double Beta[3] = { 0.5, 0.0, 0.0 };
  double ObjectOrigin[4] = { 0.0, 0.0, 0.0, -5.0 };
  std::unique_ptr<lc::Motion> BodyMotion;
  std::shared_ptr<const lc::PhotoSceneObject> Solved;

private:
  // The steps of RequestData, one per mode: the apparent mesh of special relativity, and the
  // Goedel layers (every winding and branch), each layer's block built by LayerBlock.
  void ApparentMesh(const lc::godel::Mesh& mesh, vtkPolyData* input, vtkMultiBlockDataSet* output);
  void GodelLayers(const lc::godel::Mesh& mesh, vtkPolyData* input, vtkMultiBlockDataSet* output);
  vtkSmartPointer<vtkPolyData> LayerBlock(
    const lc::godel::Mesh& mesh, const lc::PhotoSceneLayer& layer, vtkPolyData* input) const;

  vtkLightconePhotoObjectFilter(const vtkLightconePhotoObjectFilter&) = delete;
  void operator=(const vtkLightconePhotoObjectFilter&) = delete;
};

#endif
