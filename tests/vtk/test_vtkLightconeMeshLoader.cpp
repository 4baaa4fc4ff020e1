// SPDX-License-Identifier: BSD-3-Clause
// Mesh files through VTK's readers for scene files: a real OBJ loads with outward normals;
// a missing, unknown, corrupt or empty file gives an error that says what is wrong.
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeMeshLoader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace
{
namespace fs = std::filesystem;

fs::path writeFile(const std::string& name, const std::string& text)
{
  const fs::path p = fs::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p;
}

const char* kTetrahedron = "v 1 1 1\nv -1 -1 1\nv -1 1 -1\nv 1 -1 -1\n"
                           "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";

TEST(MeshLoader, ObjLoadsWithOutwardNormals)
{
  const fs::path p = writeFile("lightcone_tetra.obj", kTetrahedron);
  lc::MeshObject m;
  lc::io::loadMeshWithVtk(p.string(), m);
  ASSERT_EQ(m.triangles.size(), 4u);
  ASSERT_EQ(m.positions.size(), 4u);
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    EXPECT_GT(m.normals[i].dot(m.positions[i]), 0) << i;
  fs::remove(p);
}

TEST(MeshLoader, BadFilesSayWhatIsWrong)
{
  lc::MeshObject m;
  auto message = [&](const std::string& path) {
    try
    {
      lc::io::loadMeshWithVtk(path, m);
    }
    catch (const std::runtime_error& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("/nonexistent/x.obj").find("does not exist"), std::string::npos);
  const fs::path unknown = writeFile("lightcone_mesh.xyz", "1 2 3\n");
  EXPECT_NE(message(unknown.string()).find("unknown mesh format"), std::string::npos);
  const fs::path empty = writeFile("lightcone_empty.obj", "# nothing\n");
  EXPECT_NE(message(empty.string()).find("no triangles"), std::string::npos);
  const fs::path corrupt = writeFile("lightcone_corrupt.ply", "ply\nformat nonsense\n");
  EXPECT_FALSE(message(corrupt.string()).empty());
  for (const auto& p : { unknown, empty, corrupt })
    fs::remove(p);
}

TEST(MeshLoader, SceneWithMeshFileNamesFileLineAndField)
{
  const fs::path empty = writeFile("lightcone_empty2.obj", "# nothing\n");
  const std::string scene = "{\"metric\": {\"name\": \"godel\"},\n \"objects\": [{\"type\": "
                            "\"mesh\", \"centre\": [0,1,0,0],\n"
                            " \"file\": \"" +
    empty.string() + "\"}]}";
  lc::io::SceneReadOptions opt;
  opt.meshLoader = lc::io::loadMeshWithVtk;
  try
  {
    lc::io::parseScene(scene, "scene.json", ".", opt);
    FAIL();
  }
  catch (const lc::io::InputError& e)
  {
    const std::string w = e.what();
    EXPECT_NE(w.find("scene.json:3"), std::string::npos) << w;
    EXPECT_NE(w.find("objects[0].file"), std::string::npos) << w;
    EXPECT_NE(w.find("no triangles"), std::string::npos) << w;
  }
  fs::remove(empty);
  const fs::path tetra = writeFile("lightcone_tetra2.obj", kTetrahedron);
  const lc::Scene ok =
    lc::io::parseScene("{\"metric\": {\"name\": \"godel\"}, \"objects\": [{\"type\": \"mesh\", "
                       "\"centre\": [0,1,0,0], \"scale\": 0.1, \"file\": \"" +
        tetra.string() + "\"}]}",
      "scene.json", ".", opt);
  ASSERT_EQ(ok.meshes.size(), 1u);
  EXPECT_NEAR(ok.meshes[0].positions[0].norm(), 0.1 * std::sqrt(3.0), 1e-12);
  fs::remove(tetra);
}

} // namespace
