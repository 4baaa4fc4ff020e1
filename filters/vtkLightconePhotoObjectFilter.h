/**
 * @class   vtkLightconePhotoObjectFilter
 * @brief   photo-object of a triangle mesh: where an observer sees each vertex
 *
 * vtkLightconePhotoObjectFilter takes a vtkPolyData triangle mesh given in the local flat
 * frame at its centre (other polygons are triangulated with vtkTriangleFilter; lines and
 * vertices are ignored) and produces a vtkMultiBlockDataSet of vtkPolyData blocks.
 *
 * Mode GODEL (default): lc::godel::PhotoObjectBuilder(a, Observer) builds every image
 * of every vertex for windings 0..MaxWinding on both branches, the mesh centred at the world
 * event CentreEvent (vertex v goes to Isometry::movingOriginTo(a, centre).apply((0, v))),
 * with stitching of the two branches of a winding when Stitch is on (default). Block 2n + b
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
 * from the emission point to the observer), "vertex_id".
 *
 * An empty mesh gives an empty multiblock and a warning. Bad parameters (|beta| >= 1, a <= 0)
 * are errors (vtkErrorMacro) with an empty output.
 */
#ifndef vtkLightconePhotoObjectFilter_h
#define vtkLightconePhotoObjectFilter_h

#include "vtkLightconeOutputChart.h" // vtkLightconeGodelAMacro

#include <vtkMultiBlockDataSetAlgorithm.h>
#include <vtkSmartPointer.h>

class vtkPolyData;
namespace lc
{
namespace godel
{
struct Mesh;
struct PhotoLayer;
struct PhotoObject;
}
}

class vtkLightconePhotoObjectFilter : public vtkMultiBlockDataSetAlgorithm
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
  ~vtkLightconePhotoObjectFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = GODEL;
  double GodelA = 1.0;
  double Observer[4] = { 0.0, 0.0, 0.0, 0.0 };
  double CentreEvent[4] = { 0.0, 1.0, 0.0, 0.0 };
  int MaxWinding = 2;
  bool Stitch = true;
  int PointPlacement = DIRECTION;
  double Beta[3] = { 0.5, 0.0, 0.0 };
  double ObjectOrigin[4] = { 0.0, 0.0, 0.0, -5.0 };

private:
  // The steps of RequestData, one per mode: the apparent mesh of special relativity, and the
  // Goedel layers (every winding and branch), each layer's block built by LayerBlock.
  void ApparentMesh(const lc::godel::Mesh& mesh, vtkMultiBlockDataSet* output);
  void GodelLayers(const lc::godel::Mesh& mesh, vtkMultiBlockDataSet* output);
  vtkSmartPointer<vtkPolyData> LayerBlock(const lc::godel::Mesh& mesh,
    const lc::godel::PhotoObject& po, const lc::godel::PhotoLayer& layer) const;

  vtkLightconePhotoObjectFilter(const vtkLightconePhotoObjectFilter&) = delete;
  void operator=(const vtkLightconePhotoObjectFilter&) = delete;
};

#endif
