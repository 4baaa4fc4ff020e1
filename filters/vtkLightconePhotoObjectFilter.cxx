#include "vtkLightconePhotoObjectFilter.h"

#include "core/godel/photo_object.hpp"
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
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
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
      this->ApparentMesh(mesh, output);
    }
    else
    {
      this->GodelLayers(mesh, output);
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
  const lc::godel::Mesh& mesh, vtkMultiBlockDataSet* output)
{
  const lc::Vec4 obs(this->Observer[0], this->Observer[1], this->Observer[2], this->Observer[3]);
  const lc::Vec3 beta(this->Beta[0], this->Beta[1], this->Beta[2]);
  if (!(beta.squaredNorm() < 1.0))
  {
    throw std::invalid_argument("photo-object: |beta| must be < 1");
  }
  // The frame's origin passes ObjectOrigin: at t = 0 it is at x0 - beta t0.
  const lc::Vec3 x0(this->ObjectOrigin[1], this->ObjectOrigin[2], this->ObjectOrigin[3]);
  const lc::sr::MovingFrame frame(beta, x0 - beta * this->ObjectOrigin[0]);
  vtkNew<vtkPolyData> block;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> teArr, dArr;
  teArr->SetName("emission_time");
  dArr->SetName("doppler");
  vtkNew<vtkIdTypeArray> idArr;
  idArr->SetName("vertex_id");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
  {
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
  const lc::godel::Mesh& mesh, vtkMultiBlockDataSet* output)
{
  const double a = this->GodelA;
  const lc::Vec4 obs(this->Observer[0], this->Observer[1], this->Observer[2], this->Observer[3]);
  const lc::Vec4 centre(
    this->CentreEvent[0], this->CentreEvent[1], this->CentreEvent[2], this->CentreEvent[3]);
  const lc::godel::PhotoObjectBuilder builder(a, obs);
  lc::godel::PhotoObjectOptions opt;
  opt.maxWinding = this->MaxWinding;
  opt.stitch = this->Stitch;
  const lc::godel::PhotoObject po = builder.build(mesh, centre, opt);
  this->UpdateProgress(0.5);
  if (po.status != lc::godel::PhotoStatus::Ok)
  {
    throw std::runtime_error("photo-object: " + po.message);
  }

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
                    << " vertices are beyond the observer's Goedel horizon (no image).");
  }

  const unsigned int nLayers = static_cast<unsigned int>(po.layers.size());
  output->SetNumberOfBlocks(nLayers);
  for (unsigned int li = 0; li < nLayers; ++li)
  {
    const lc::godel::PhotoLayer& layer = po.layers[li];
    vtkSmartPointer<vtkPolyData> block = this->LayerBlock(mesh, po, layer);
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
vtkSmartPointer<vtkPolyData> vtkLightconePhotoObjectFilter::LayerBlock(const lc::godel::Mesh& mesh,
  const lc::godel::PhotoObject& po, const lc::godel::PhotoLayer& layer) const
{
  const lc::Vec4 obs(this->Observer[0], this->Observer[1], this->Observer[2], this->Observer[3]);
  const lc::godel::Isometry toWorld =
    lc::godel::Isometry::movingToOrigin(this->GodelA, obs).inverse();
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
  // Only the vertices used by the layer's triangles.
  std::vector<vtkIdType> newId(mesh.vertices.size(), -1);
  // The layer's triangles are an ordered subset of mesh.triangles.
  std::size_t searchFrom = 0;
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
        const lc::Vec4& xo = po.observerChart[v];
        teArr->InsertNextValue(toWorld.apply(lc::Vec4(vi.emissionTime, xo(1), xo(2), xo(3)))(0));
        frArr->InsertNextValue(1.0);
        weldArr->InsertNextValue(vi.welded ? 1 : 0);
        idArr->InsertNextValue(v);
      }
      q[k] = newId[v];
    }
    polys->InsertNextCell(3, q);
    windArr->InsertNextValue(layer.winding);
    branchArr->InsertNextValue(b);
    vtkIdType tid = -1;
    for (std::size_t m = searchFrom; m < mesh.triangles.size(); ++m)
    {
      if (mesh.triangles[m] == t)
      {
        tid = static_cast<vtkIdType>(m);
        searchFrom = m + 1;
        break;
      }
    }
    triArr->InsertNextValue(tid);
  }
  block->SetPoints(points);
  block->SetPolys(polys);
  for (vtkDataArray* array :
    std::initializer_list<vtkDataArray*>{ dirArr, depthArr, teArr, frArr, weldArr, idArr })
  {
    block->GetPointData()->AddArray(array);
  }
  block->GetPointData()->SetActiveScalars("depth");
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
  os << indent << "PointPlacement: " << (this->PointPlacement == DEPTH ? "Depth" : "Direction")
     << "\n";
  os << indent << "Beta: (" << this->Beta[0] << ", " << this->Beta[1] << ", " << this->Beta[2]
     << ")\n";
  os << indent << "ObjectOrigin: (" << this->ObjectOrigin[0] << ", " << this->ObjectOrigin[1]
     << ", " << this->ObjectOrigin[2] << ", " << this->ObjectOrigin[3] << ")\n";
}
