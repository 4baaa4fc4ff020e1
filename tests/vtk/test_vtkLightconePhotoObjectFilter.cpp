// SPDX-License-Identifier: BSD-3-Clause
// vtkLightconePhotoObjectFilter: Goedel photo-objects against the inverse solution per vertex
// (lc::godel::ObserverView), the special-relativistic photo-object against a hand-derived
// quadratic, pipeline re-execution, empty input, .vtm round trip. Two tests reach past this
// class: the re-execution test also checks the Killing-field and orbit sources, PrintSelf all
// four newer classes.
#include "tests/common/vtk_event_counter.hpp"
#include "tests/vtk/filter_helpers.hpp"
#include "vtkLightconeIsometryOrbitSource.h"
#include "vtkLightconeKillingFieldSource.h"
#include "vtkLightconePhotoObjectFilter.h"
#include "vtkLightconeWorldLineSource.h"

#include "core/godel/images.hpp"
#include "core/godel/isometry.hpp"
#include "core/scene/scene.hpp"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkCubeSource.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <string>

namespace
{
using lc::test::EventCounter;
using lc::test::PointArray;

vtkSmartPointer<vtkPolyData> SmallSphere(double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(10);
  sphere->SetPhiResolution(8);
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  sphere->Update();
  vtkSmartPointer<vtkPolyData> pd = sphere->GetOutput();
  return pd;
}

std::string BlockName(vtkMultiBlockDataSet* mb, unsigned int i)
{
  if (!mb->HasMetaData(i) || !mb->GetMetaData(i)->Has(vtkCompositeDataSet::NAME()))
    return "";
  return mb->GetMetaData(i)->Get(vtkCompositeDataSet::NAME());
}
} // namespace

TEST(PhotoObjectFilter, GodelDirectionsMatchInverseSolution)
{
  const double a = 1.0;
  const lc::Vec4 obs(0.2, 0.1, -0.2, 0.1), centre(0.0, 0.9, 0.3, 0.2);
  auto mesh = SmallSphere(0.3);
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(mesh);
  f->SetGodelA(a);
  f->SetObserver(obs(0), obs(1), obs(2), obs(3));
  f->SetCentreEvent(centre(0), centre(1), centre(2), centre(3));
  f->SetMaxWinding(1);
  f->StitchOff();
  f->Update();
  vtkMultiBlockDataSet* out = f->GetOutput();
  ASSERT_EQ(out->GetNumberOfBlocks(), 4u);
  const lc::godel::Isometry place = lc::godel::Isometry::movingOriginTo(a, centre);
  const lc::godel::ObserverView view(a, obs);
  int checked = 0;
  for (unsigned int bi = 0; bi < 4; ++bi)
  {
    const int n = static_cast<int>(bi / 2), b = static_cast<int>(bi % 2);
    EXPECT_EQ(BlockName(out, bi), "winding " + std::to_string(n) + (b ? " inbound" : " outbound"));
    auto* pd = vtkPolyData::SafeDownCast(out->GetBlock(bi));
    ASSERT_NE(pd, nullptr);
    ASSERT_GT(pd->GetNumberOfPolys(), 0) << "block " << bi;
    vtkDataArray* dir = PointArray(pd, "direction");
    vtkDataArray* depth = PointArray(pd, "depth");
    vtkDataArray* te = PointArray(pd, "emission_time");
    vtkDataArray* vid = PointArray(pd, "vertex_id");
    vtkDataArray* welded = PointArray(pd, "welded");
    ASSERT_TRUE(dir && depth && te && vid && welded);
    vtkDataArray* wind = pd->GetCellData()->GetArray("winding");
    vtkDataArray* br = pd->GetCellData()->GetArray("branch");
    ASSERT_TRUE(wind && br);
    for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
    {
      EXPECT_EQ(wind->GetComponent(c, 0), n);
      EXPECT_EQ(br->GetComponent(c, 0), b);
    }
    for (vtkIdType id = 0; id < pd->GetNumberOfPoints(); ++id)
    {
      double v[3];
      mesh->GetPoint(static_cast<vtkIdType>(vid->GetComponent(id, 0)), v);
      const lc::Vec4 world = place.apply(lc::Vec4(0, v[0], v[1], v[2]));
      const lc::godel::ImageSet set = view.images(world.segment<3>(1), 1);
      ASSERT_EQ(set.status, lc::godel::ImageStatus::Ok);
      const lc::godel::Image* match = nullptr;
      for (const auto& im : set.images)
        if (im.winding == n && static_cast<int>(im.branch == lc::godel::Branch::Inbound) == b)
          match = &im;
      ASSERT_NE(match, nullptr) << "vertex " << vid->GetComponent(id, 0) << " block " << bi;
      double p[3];
      pd->GetPoint(id, p);
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_NEAR(dir->GetComponent(id, k), match->direction(k), 1e-10);
        EXPECT_NEAR(p[k], match->direction(k), 1e-10); // unit-sphere placement
      }
      EXPECT_NEAR(depth->GetComponent(id, 0), match->lambda, 1e-10);
      EXPECT_NEAR(te->GetComponent(id, 0), match->emissionTime, 1e-9);
      EXPECT_EQ(welded->GetComponent(id, 0), 0.0);
      ++checked;
    }
  }
  EXPECT_GT(checked, 4 * 50);
  vtkDataArray* beyond = out->GetFieldData()->GetArray("beyond_horizon");
  ASSERT_NE(beyond, nullptr);
  EXPECT_EQ(beyond->GetNumberOfTuples(), 0);

  // Depth placement: points at depth * direction.
  f->SetPointPlacementToDepth();
  f->Update();
  auto* pd = vtkPolyData::SafeDownCast(f->GetOutput()->GetBlock(1));
  ASSERT_NE(pd, nullptr);
  for (vtkIdType id = 0; id < pd->GetNumberOfPoints(); ++id)
  {
    double p[3];
    pd->GetPoint(id, p);
    const double l = PointArray(pd, "depth")->GetComponent(id, 0);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(p[k], l * PointArray(pd, "direction")->GetComponent(id, k), 1e-12);
  }

  // Stitching on: still one block per layer, welded flags present.
  f->StitchOn();
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 4u);

  // A mesh beyond the horizon (r = 5 > 2a from the observer): no image at all, reported.
  f->SetObserver(0, 0, 0, 0);
  f->SetCentreEvent(0, 5, 0, 0);
  f->Update();
  beyond = f->GetOutput()->GetFieldData()->GetArray("beyond_horizon");
  ASSERT_NE(beyond, nullptr);
  EXPECT_EQ(beyond->GetNumberOfTuples(), mesh->GetNumberOfPoints());
  for (unsigned int bi = 0; bi < f->GetOutput()->GetNumberOfBlocks(); ++bi)
  {
    auto* blk = vtkPolyData::SafeDownCast(f->GetOutput()->GetBlock(bi));
    ASSERT_NE(blk, nullptr);
    EXPECT_EQ(blk->GetNumberOfCells(), 0);
  }
}

// The dust of the Goedel universe is geodesic: a body "falling freely" with unit energy and no
// velocity stays at rest, so the free-fall path (emission events on each vertex's world line) must
// give what the inverse problem of static points gives, frequency ratio 1. Input point arrays
// (texture coordinates) travel with each vertex; the camera frame is the observer's static frame.
TEST(PhotoObjectFilter, GodelDustInFreeFallMatchesRestAndPassesPointData)
{
  const double a = 1.0;
  const lc::Vec4 obs(0.0, 0.4, -0.3, 0.0), centre(0.0, 1.0, 0.3, 0.1);
  auto mesh = SmallSphere(0.3);
  vtkNew<vtkFloatArray> uv;
  uv->SetName("uv");
  uv->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    uv->InsertNextTuple2(0.01 * i, 1 - 0.01 * i);
  mesh->GetPointData()->SetTCoords(uv);
  auto configure = [&](vtkLightconePhotoObjectFilter* f) {
    f->SetInputData(mesh);
    f->SetGodelA(a);
    f->SetObserver(obs(0), obs(1), obs(2), obs(3));
    f->SetCentreEvent(centre(0), centre(1), centre(2), centre(3));
    f->SetMaxWinding(0);
    f->StitchOff();
    f->CameraFrameOn();
  };
  vtkNew<vtkLightconePhotoObjectFilter> rest, fall;
  configure(rest);
  configure(fall);
  lc::Motion dust;
  dust.kind = lc::Motion::Kind::FreeFall;
  dust.k0 = 1.0;
  fall->SetMotion(dust);
  rest->Update();
  fall->Update();
  int compared = 0;
  for (unsigned int bi = 0; bi < 2; ++bi)
  {
    auto* r = vtkPolyData::SafeDownCast(rest->GetOutput()->GetBlock(bi));
    auto* f = vtkPolyData::SafeDownCast(fall->GetOutput()->GetBlock(bi));
    ASSERT_TRUE(r && f);
    vtkDataArray *rid = PointArray(r, "vertex_id"), *fid = PointArray(f, "vertex_id");
    vtkDataArray *rdir = PointArray(r, "direction"), *fdir = PointArray(f, "direction");
    vtkDataArray *rdepth = PointArray(r, "depth"), *fdepth = PointArray(f, "depth");
    vtkDataArray *rte = PointArray(r, "emission_time"), *fte = PointArray(f, "emission_time");
    vtkDataArray* ratio = PointArray(f, "frequency_ratio");
    vtkDataArray* tc = f->GetPointData()->GetTCoords();
    ASSERT_TRUE(rid && fid && rdir && fdir && rdepth && fdepth && rte && fte && ratio && tc);
    std::map<vtkIdType, vtkIdType> restPoint;
    for (vtkIdType p = 0; p < r->GetNumberOfPoints(); ++p)
      restPoint[static_cast<vtkIdType>(rid->GetComponent(p, 0))] = p;
    for (vtkIdType p = 0; p < f->GetNumberOfPoints(); ++p)
    {
      const vtkIdType v = static_cast<vtkIdType>(fid->GetComponent(p, 0));
      EXPECT_NEAR(tc->GetComponent(p, 0), 0.01 * v, 1e-6);
      EXPECT_NEAR(ratio->GetComponent(p, 0), 1.0, 1e-6);
      const auto it = restPoint.find(v);
      if (it == restPoint.end())
        continue;
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(fdir->GetComponent(p, k), rdir->GetComponent(it->second, k), 1e-6);
      EXPECT_NEAR(fdepth->GetComponent(p, 0), rdepth->GetComponent(it->second, 0), 1e-6);
      EXPECT_NEAR(fte->GetComponent(p, 0), rte->GetComponent(it->second, 0), 1e-6);
      ++compared;
    }
  }
  EXPECT_GT(compared, 50);

  // Constant velocity is special relativity's: an error, an empty output, no crash.
  lc::Motion drift;
  drift.kind = lc::Motion::Kind::ConstantVelocity;
  drift.beta = lc::Vec3(0.5, 0, 0);
  fall->SetMotion(drift);
  const bool previous = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  fall->Update();
  vtkObject::SetGlobalWarningDisplay(previous);
  EXPECT_EQ(fall->GetOutput()->GetNumberOfBlocks(), 0u);
}

TEST(PhotoObjectFilter, SpecialRelativityCubeOnLightCone)
{
  const double beta = 0.95;
  vtkNew<vtkCubeSource> cube; // quads: the filter triangulates them
  cube->SetXLength(1.0);
  cube->SetYLength(0.6);
  cube->SetZLength(0.8);
  cube->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  cube->Update();
  vtkPolyData* mesh = cube->GetOutput();
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(mesh);
  f->SetModeToSpecialRelativity();
  f->SetBeta(beta, 0, 0);
  const double t0 = 0.5, x0[3] = { -1.0, 2.0, 0.5 }; // the cube's centre passes x0 at t0
  f->SetObjectOrigin(t0, x0[0], x0[1], x0[2]);
  f->SetObserver(0, 0, 0, 0);
  f->Update();
  vtkMultiBlockDataSet* out = f->GetOutput();
  ASSERT_EQ(out->GetNumberOfBlocks(), 1u);
  auto* pd = vtkPolyData::SafeDownCast(out->GetBlock(0));
  ASSERT_NE(pd, nullptr);
  ASSERT_EQ(pd->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_EQ(pd->GetNumberOfPolys(), 12); // 6 quads -> 12 triangles
  vtkDataArray* te = PointArray(pd, "emission_time");
  vtkDataArray* D = PointArray(pd, "doppler");
  ASSERT_TRUE(te && D);
  const double gamma = 1 / std::sqrt(1 - beta * beta);
  for (vtkIdType id = 0; id < pd->GetNumberOfPoints(); ++id)
  {
    double v[3], p[3];
    mesh->GetPoint(id, v);
    pd->GetPoint(id, p);
    // Position at t = 0 in S: the centre at x0 - beta t0, the rest shape contracted along x.
    const double q[3] = { x0[0] - beta * t0 + v[0] / gamma, x0[1] + v[1], x0[2] + v[2] };
    // |q + beta t| = -t, t < 0:  (1 - beta^2) t^2 - 2 (q.beta) t - |q|^2 = 0.
    const double B = q[0] * beta, q2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    const double disc = std::sqrt(B * B + (1 - beta * beta) * q2);
    const double te0 = B > 0 ? -q2 / (B + disc) : (B - disc) / (1 - beta * beta);
    const double xa[3] = { q[0] + beta * te0, q[1], q[2] };
    const double scale = 1 + std::abs(te0);
    EXPECT_NEAR(te->GetComponent(id, 0), te0, 1e-12 * scale);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(p[k], xa[k], 1e-12 * scale) << "vertex " << id;
    // The light-cone equation itself.
    EXPECT_NEAR(
      std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), -te->GetComponent(id, 0), 1e-12 * scale);
    // Doppler factor towards the observer at the origin: n = -x_app / |x_app|.
    const double len = std::sqrt(xa[0] * xa[0] + xa[1] * xa[1] + xa[2] * xa[2]);
    EXPECT_NEAR(D->GetComponent(id, 0), 1 / (gamma * (1 + beta * xa[0] / len)), 1e-12);
  }
  // The input's point arrays travel with each vertex: the rest normals and texture coordinates.
  vtkDataArray* normals = pd->GetPointData()->GetNormals();
  vtkDataArray* tcoords = pd->GetPointData()->GetTCoords();
  ASSERT_TRUE(normals && tcoords);
  for (vtkIdType id = 0; id < pd->GetNumberOfPoints(); ++id)
  {
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(
        normals->GetComponent(id, k), mesh->GetPointData()->GetNormals()->GetComponent(id, k));
    EXPECT_EQ(
      tcoords->GetComponent(id, 1), mesh->GetPointData()->GetTCoords()->GetComponent(id, 1));
  }
}

TEST(PhotoObjectFilter, SpecialRelativityRefusesFasterThanLightAndNonFiniteEvents)
{
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(SmallSphere(0.2));
  f->SetModeToSpecialRelativity();
  EventCounter errors;
  errors.watch(f);
  f->SetBeta(0.8, 0.7, 0);
  f->Update();
  EXPECT_EQ(errors.count, 1);
  EXPECT_NE(errors.text.find("|beta| must be < 1"), std::string::npos) << errors.text;
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 0u);
  f->SetBeta(0.5, 0, 0);
  f->SetObjectOrigin(0, std::nan(""), 0, -5);
  f->Update();
  EXPECT_EQ(errors.count, 2);
  EXPECT_NE(errors.text.find("ObjectOrigin has a non-finite component"), std::string::npos)
    << errors.text;
  f->SetObjectOrigin(0, 0, 0, -5);
  f->SetObserver(std::numeric_limits<double>::infinity(), 0, 0, 0);
  f->Update();
  EXPECT_EQ(errors.count, 3);
  EXPECT_NE(errors.text.find("Observer has a non-finite component"), std::string::npos)
    << errors.text;
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 0u);
  f->SetObserver(0, 0, 0, 0);
  f->Update();
  EXPECT_EQ(errors.count, 3);
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 1u);
}

TEST(PhotoObjectFilter, ReexecutesOnlyOnChangeAndEmptyInput)
{
  auto mesh = SmallSphere(0.2);
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(mesh);
  f->SetMaxWinding(0);
  EventCounter ends;
  ends.watch(f, vtkCommand::EndEvent);
  f->Update();
  EXPECT_EQ(ends.count, 1);
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 2u);
  f->Update();
  EXPECT_EQ(ends.count, 1);
  f->SetMaxWinding(0); // same value: no re-execution
  f->Update();
  EXPECT_EQ(ends.count, 1);
  f->SetMaxWinding(2);
  f->Update();
  EXPECT_EQ(ends.count, 2);
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 6u);
  f->SetCentreEvent(0, 0.5, 0.5, 0);
  f->Update();
  EXPECT_EQ(ends.count, 3);

  // Empty mesh: empty output, a warning, no crash.
  EventCounter warnings;
  warnings.watch(f, vtkCommand::WarningEvent);
  vtkNew<vtkPolyData> empty;
  f->SetInputData(empty);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 0u);
  EXPECT_EQ(warnings.count, 1);
  f->SetModeToSpecialRelativity();
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetNumberOfBlocks(), 0u);
  EXPECT_EQ(warnings.count, 2);

  // Sources re-execute on a change too.
  vtkNew<vtkLightconeKillingFieldSource> k;
  EventCounter kends;
  kends.watch(k, vtkCommand::EndEvent);
  k->Update();
  k->Update();
  EXPECT_EQ(kends.count, 1);
  k->SetCoefficients(1, 0, 0, 0, 0);
  k->Update();
  EXPECT_EQ(kends.count, 2);
  vtkNew<vtkLightconeIsometryOrbitSource> o;
  vtkNew<vtkPoints> seeds;
  seeds->InsertNextPoint(1, 0, 0);
  o->SetSeeds(seeds);
  o->Update();
  const vtkMTimeType m0 = o->GetOutput()->GetMTime();
  seeds->SetPoint(0, 0.5, 0, 0);
  seeds->Modified();
  o->Update();
  EXPECT_GT(o->GetOutput()->GetMTime(), m0);
  EXPECT_NEAR(o->GetOutput()->GetPoint(0)[0], 0.5, 1e-15);
}

TEST(PhotoObjectFilter, VtmRoundTripKeepsPoints)
{
  auto mesh = SmallSphere(0.25);
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->SetInputData(mesh);
  f->SetObserver(0, 0, 0, 0);
  f->SetCentreEvent(0, 0.8, -0.2, 0.1);
  f->SetMaxWinding(1);
  f->SetPointPlacementToDepth();
  f->Update();
  vtkMultiBlockDataSet* out = f->GetOutput();
  ASSERT_EQ(out->GetNumberOfBlocks(), 4u);
  const auto dir = std::filesystem::temp_directory_path() / "lightcone_photo_object_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "photo.vtm").string();
  vtkNew<vtkXMLMultiBlockDataWriter> w;
  w->SetInputData(out);
  w->SetFileName(file.c_str());
  w->SetDataModeToBinary();
  ASSERT_EQ(w->Write(), 1);
  vtkNew<vtkXMLMultiBlockDataReader> r;
  r->SetFileName(file.c_str());
  r->Update();
  auto* back = vtkMultiBlockDataSet::SafeDownCast(r->GetOutput());
  ASSERT_NE(back, nullptr);
  ASSERT_EQ(back->GetNumberOfBlocks(), 4u);
  for (unsigned int bi = 0; bi < 4; ++bi)
  {
    auto* a = vtkPolyData::SafeDownCast(out->GetBlock(bi));
    auto* b = vtkPolyData::SafeDownCast(back->GetBlock(bi));
    ASSERT_TRUE(a && b);
    ASSERT_GT(a->GetNumberOfPoints(), 0);
    EXPECT_EQ(BlockName(back, bi), BlockName(out, bi));
    ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
    ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
    for (vtkIdType id = 0; id < a->GetNumberOfPoints(); ++id)
    {
      double p[3], q[3];
      a->GetPoint(id, p);
      b->GetPoint(id, q);
      EXPECT_EQ(p[0], q[0]);
      EXPECT_EQ(p[1], q[1]);
      EXPECT_EQ(p[2], q[2]);
    }
    for (const char* name : { "direction", "depth", "emission_time", "welded" })
    {
      vtkDataArray* x = a->GetPointData()->GetArray(name);
      vtkDataArray* y = b->GetPointData()->GetArray(name);
      ASSERT_TRUE(x && y) << name;
      for (vtkIdType id = 0; id < x->GetNumberOfTuples(); ++id)
        for (int k = 0; k < x->GetNumberOfComponents(); ++k)
          EXPECT_EQ(x->GetComponent(id, k), y->GetComponent(id, k));
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(PhotoObjectFilter, PrintSelfOfAllNewClasses)
{
  std::ostringstream os;
  vtkNew<vtkLightconeKillingFieldSource> k;
  k->Print(os);
  vtkNew<vtkLightconeIsometryOrbitSource> o;
  o->Print(os);
  vtkNew<vtkLightconeWorldLineSource> w;
  w->Print(os);
  vtkNew<vtkLightconePhotoObjectFilter> f;
  f->Print(os);
  const std::string text = os.str();
  for (const char* key : { "Coefficients: (0, 1, 0, 0, 0)", "FlowRange:", "Mode: GodelFreeFall",
         "MaxWinding: 2", "PointPlacement: Direction" })
    EXPECT_NE(text.find(key), std::string::npos) << key;
}
