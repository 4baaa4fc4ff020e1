// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightconePhotoObjectFilter.h"

#include "source_checks.hpp"

#include "core/godel/photo_object.hpp"
#include "core/render/photo_scene.hpp"
#include "core/scene/scene.hpp"
#include "core/sr/doppler.hpp"
#include "core/sr/photo_object.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <exception>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightconePhotoObjectFilter);

namespace
{
// The triangles of the input (polygons triangulated; lines and vertices dropped).
lc::godel::Mesh ToMesh(vtkPolyData* input, bool& hadOtherCells)
{
  lc::godel::Mesh mesh;
  hadOtherCells = input->GetNumberOfVerts() + input->GetNumberOfLines() > 0;
  const vtkIdType np = input->GetNumberOfPoints();
  mesh.vertices.reserve(static_cast<std::size_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    mesh.vertices.emplace_back(p[0], p[1], p[2]);
  }
  vtkSmartPointer<vtkPolyData> tri = input;
  bool needTriangulation = input->GetNumberOfStrips() > 0;
  if (!needTriangulation && input->GetPolys())
  {
    vtkCellArray* polys = input->GetPolys();
    vtkNew<vtkIdList> ids;
    for (polys->InitTraversal(); polys->GetNextCell(ids);)
    {
      if (ids->GetNumberOfIds() != 3)
      {
        needTriangulation = true;
        break;
      }
    }
  }
  if (needTriangulation)
  {
    vtkNew<vtkPolyData> shallow;
    shallow->SetPoints(input->GetPoints());
    shallow->SetPolys(input->GetPolys());
    shallow->SetStrips(input->GetStrips());
    vtkNew<vtkTriangleFilter> tf;
    tf->SetInputData(shallow);
    tf->PassVertsOff();
    tf->PassLinesOff();
    tf->Update();
    tri = tf->GetOutput();
  }
  if (vtkCellArray* polys = tri->GetPolys())
  {
    vtkNew<vtkIdList> ids;
    for (polys->InitTraversal(); polys->GetNextCell(ids);)
    {
      if (ids->GetNumberOfIds() == 3)
      {
        mesh.triangles.push_back({ static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
          static_cast<int>(ids->GetId(2)) });
      }
    }
  }
  return mesh;
}
} // namespace

//------------------------------------------------------------------------------
vtkLightconePhotoObjectFilter::vtkLightconePhotoObjectFilter()
  : BodyMotion(std::make_unique<lc::Motion>())
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkLightconePhotoObjectFilter::~vtkLightconePhotoObjectFilter() = default;

//------------------------------------------------------------------------------
void vtkLightconePhotoObjectFilter::SetMotion(const lc::Motion& motion)
{
  *this->BodyMotion = motion;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightconePhotoObjectFilter::SetPhotoObject(
  std::shared_ptr<const lc::PhotoSceneObject> solved)
{
  this->Solved = std::move(solved);
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkLightconePhotoObjectFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightconePhotoObjectFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro(<< "No output multiblock.");
    return 0;
  }
  output->Initialize();
  if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    vtkWarningMacro(<< "Empty input mesh: empty photo-object.");
    return 1;
  }
  bool hadOtherCells = false;
  const lc::godel::Mesh mesh = ToMesh(input, hadOtherCells);
  if (hadOtherCells)
  {
    vtkWarningMacro(<< "Vertices and lines of the input are ignored (triangles only).");
  }
  if (mesh.triangles.empty())
  {
    vtkWarningMacro(<< "The input mesh has no polygons: empty photo-object.");
    return 1;
  }
  try
  {
    if (this->Mode == SPECIAL_RELATIVITY)
    {
      this->ApparentMesh(mesh, input, output);
    }
    else
    {
      this->GodelLayers(mesh, input, output);
    }
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightconePhotoObjectFilter::ApparentMesh(
  const lc::godel::Mesh& mesh, vtkPolyData* input, vtkMultiBlockDataSet* output)
{
  const lc::Vec4 obs(this->Observer[0], this->Observer[1], this->Observer[2], this->Observer[3]);
  const lc::Vec3 beta(this->Beta[0], this->Beta[1], this->Beta[2]);
  for (const std::string& problem : { lc::filters::CheckMovingFrame(this->Beta, this->ObjectOrigin),
         lc::filters::CheckFinite("Observer", this->Observer, 4) })
  {
    if (!problem.empty())
    {
      throw std::invalid_argument("photo-object: " + problem);
    }
  }
  const lc::sr::MovingFrame frame = lc::sr::MovingFrame::throughEvent(beta,
    lc::Vec4(
      this->ObjectOrigin[0], this->ObjectOrigin[1], this->ObjectOrigin[2], this->ObjectOrigin[3]));
  vtkNew<vtkPolyData> block;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> teArr, dArr;
  teArr->SetName("emission_time");
  dArr->SetName("doppler");
  vtkNew<vtkIdTypeArray> idArr;
  idArr->SetName("vertex_id");
  // The input's point arrays travel with each vertex (rest normals, texture coordinates).
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = block->GetPointData();
  outPD->CopyAllocate(inPD, static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
  {
    outPD->CopyData(inPD, static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
    const lc::Vec4 e = lc::sr::emissionEvent(frame, mesh.vertices[i], obs);
    points->InsertNextPoint(e(1), e(2), e(3));
    teArr->InsertNextValue(e(0));
    const lc::Vec3 toObs = obs.tail<3>() - e.tail<3>();
    const double len = toObs.norm();
    dArr->InsertNextValue(len > 0 ? lc::sr::dopplerFactor(beta, toObs / len)
                                  : lc::sr::dopplerFactor(beta, lc::Vec3::Zero()));
    idArr->InsertNextValue(static_cast<vtkIdType>(i));
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : mesh.triangles)
  {
    const vtkIdType q[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, q);
  }
  block->SetPoints(points);
  block->SetPolys(polys);
  block->GetPointData()->AddArray(teArr);
  block->GetPointData()->AddArray(dArr);
  block->GetPointData()->AddArray(idArr);
  block->GetPointData()->SetActiveScalars("doppler");
  output->SetNumberOfBlocks(1);
  output->SetBlock(0, block);
  output->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "apparent");
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
void vtkLightconePhotoObjectFilter::GodelLayers(
  const lc::godel::Mesh& mesh, vtkPolyData* input, vtkMultiBlockDataSet* output)
{
  // Layers given (SetPhotoObject) are only turned into blocks; otherwise solved here.
  lc::PhotoSceneObject built;
  if (!this->Solved)
  {
    const lc::Vec4 obs(this->Observer[0], this->Observer[1], this->Observer[2], this->Observer[3]);
    lc::PhotoSource source;
    source.centre = lc::Vec4(
      this->CentreEvent[0], this->CentreEvent[1], this->CentreEvent[2], this->CentreEvent[3]);
    source.motion = *this->BodyMotion;
    source.mesh = mesh;
    lc::PhotoSceneOptions opt;
    opt.maxWinding = this->MaxWinding;
    opt.stitch = this->Stitch;
    opt.cameraFrame = this->CameraFrame;
    opt.progress = [this](double f) { this->UpdateProgress(0.5 * f); };
    built = lc::buildPhotoObject(this->GodelA, obs, source, opt);
  }
  const lc::PhotoSceneObject& po = this->Solved ? *this->Solved : built;
  if (po.mesh.vertices.size() != mesh.vertices.size())
  {
    throw std::invalid_argument("photo-object: the solved layers have " +
      std::to_string(po.mesh.vertices.size()) + " vertices, the input mesh " +
      std::to_string(mesh.vertices.size()));
  }
  this->UpdateProgress(0.5);

  vtkNew<vtkIdTypeArray> beyond;
  beyond->SetName("beyond_horizon");
  for (int v : po.beyondHorizon)
  {
    beyond->InsertNextValue(v);
  }
  vtkNew<vtkIntArray> weldedCount;
  weldedCount->SetName("welded_vertices");
  weldedCount->InsertNextValue(po.weldedVertices);
  output->GetFieldData()->AddArray(beyond);
  output->GetFieldData()->AddArray(weldedCount);
  if (!po.beyondHorizon.empty())
  {
    vtkWarningMacro(<< po.beyondHorizon.size() << " of " << mesh.vertices.size()
                    << " vertices have no image (beyond the observer's Goedel horizon).");
  }

  const unsigned int nLayers = static_cast<unsigned int>(po.layers.size());
  output->SetNumberOfBlocks(nLayers);
  for (unsigned int li = 0; li < nLayers; ++li)
  {
    const lc::PhotoSceneLayer& layer = po.layers[li];
    vtkSmartPointer<vtkPolyData> block = this->LayerBlock(mesh, layer, input);
    block->GetFieldData()->AddArray(beyond);
    block->GetFieldData()->AddArray(weldedCount);
    output->SetBlock(li, block);
    const std::string name = "winding " + std::to_string(layer.winding) +
      (layer.branch == lc::godel::Branch::Inbound ? " inbound" : " outbound");
    output->GetMetaData(li)->Set(vtkCompositeDataSet::NAME(), name.c_str());
    this->UpdateProgress(0.5 + 0.5 * (li + 1) / nLayers);
  }
}

//------------------------------------------------------------------------------
// The index in mesh.triangles of a layer's triangle t, searched from searchFrom on (a layer's
// triangles are an ordered subset of the mesh's), which then moves past it; -1 if absent.
static vtkIdType NextMeshTriangleIndex(
  const lc::godel::Mesh& mesh, const std::array<int, 3>& t, std::size_t& searchFrom)
{
  for (std::size_t m = searchFrom; m < mesh.triangles.size(); ++m)
  {
    if (mesh.triangles[m] == t)
    {
      searchFrom = m + 1;
      return static_cast<vtkIdType>(m);
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkLightconePhotoObjectFilter::LayerBlock(
  const lc::godel::Mesh& mesh, const lc::PhotoSceneLayer& layer, vtkPolyData* input) const
{
  const int b = layer.branch == lc::godel::Branch::Inbound ? 1 : 0;
  auto block = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> dirArr, depthArr, teArr, frArr;
  dirArr->SetName("direction");
  dirArr->SetNumberOfComponents(3);
  depthArr->SetName("depth");
  teArr->SetName("emission_time");
  frArr->SetName("frequency_ratio");
  vtkNew<vtkIntArray> weldArr;
  weldArr->SetName("welded");
  vtkNew<vtkIdTypeArray> idArr;
  idArr->SetName("vertex_id");
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> windArr, branchArr;
  windArr->SetName("winding");
  branchArr->SetName("branch");
  vtkNew<vtkIdTypeArray> triArr;
  triArr->SetName("triangle_id");
  // The input's point arrays travel with each vertex (texture coordinates, per-vertex light).
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = block->GetPointData();
  outPD->CopyAllocate(inPD);
  // Only the vertices used by the layer's triangles.
  std::vector<vtkIdType> newId(mesh.vertices.size(), -1);
  std::size_t searchFrom = 0; // in mesh.triangles
  for (const auto& t : layer.triangles)
  {
    vtkIdType q[3];
    for (int k = 0; k < 3; ++k)
    {
      const int v = t[k];
      if (newId[v] < 0)
      {
        const lc::godel::VertexImage& vi = layer.vertices[v];
        newId[v] = points->GetNumberOfPoints();
        const lc::Vec3 p =
          this->PointPlacement == DEPTH ? lc::Vec3(vi.lambda * vi.direction) : vi.direction;
        points->InsertNextPoint(p(0), p(1), p(2));
        dirArr->InsertNextTuple3(vi.direction(0), vi.direction(1), vi.direction(2));
        depthArr->InsertNextValue(vi.lambda);
        teArr->InsertNextValue(vi.emissionTime);
        frArr->InsertNextValue(layer.frequencyRatio[static_cast<std::size_t>(v)]);
        weldArr->InsertNextValue(vi.welded ? 1 : 0);
        idArr->InsertNextValue(v);
        outPD->CopyData(inPD, v, newId[v]);
      }
      q[k] = newId[v];
    }
    polys->InsertNextCell(3, q);
    windArr->InsertNextValue(layer.winding);
    branchArr->InsertNextValue(b);
    triArr->InsertNextValue(NextMeshTriangleIndex(mesh, t, searchFrom));
  }
  block->SetPoints(points);
  block->SetPolys(polys);
  for (vtkDataArray* array :
    std::initializer_list<vtkDataArray*>{ dirArr, depthArr, teArr, frArr, weldArr, idArr })
  {
    outPD->AddArray(array);
  }
  outPD->SetActiveScalars("depth");
  block->GetCellData()->AddArray(windArr);
  block->GetCellData()->AddArray(branchArr);
  block->GetCellData()->AddArray(triArr);
  return block;
}

//------------------------------------------------------------------------------
void vtkLightconePhotoObjectFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << (this->Mode == GODEL ? "Godel" : "SpecialRelativity") << "\n";
  os << indent << "GodelA: " << this->GodelA << "\n";
  os << indent << "Observer: (" << this->Observer[0] << ", " << this->Observer[1] << ", "
     << this->Observer[2] << ", " << this->Observer[3] << ")\n";
  os << indent << "CentreEvent: (" << this->CentreEvent[0] << ", " << this->CentreEvent[1] << ", "
     << this->CentreEvent[2] << ", " << this->CentreEvent[3] << ")\n";
  os << indent << "MaxWinding: " << this->MaxWinding << "\n";
  os << indent << "Stitch: " << (this->Stitch ? "On" : "Off") << "\n";
  os << indent << "PhotoObject: " << (this->Solved ? "given" : "solved here") << "\n";
  os << indent << "CameraFrame: " << (this->CameraFrame ? "On" : "Off") << "\n";
  os << indent << "PointPlacement: " << (this->PointPlacement == DEPTH ? "Depth" : "Direction")
     << "\n";
  os << indent << "Beta: (" << this->Beta[0] << ", " << this->Beta[1] << ", " << this->Beta[2]
     << ")\n";
  os << indent << "Motion: "
     << (this->BodyMotion->kind == lc::Motion::Kind::Rest          ? "rest"
            : this->BodyMotion->kind == lc::Motion::Kind::FreeFall ? "free fall"
                                                                   : "world line / velocity")
     << "\n";
  os << indent << "ObjectOrigin: (" << this->ObjectOrigin[0] << ", " << this->ObjectOrigin[1]
     << ", " << this->ObjectOrigin[2] << ", " << this->ObjectOrigin[3] << ")\n";
}
