// SPDX-License-Identifier: BSD-3-Clause
// readers/io/mesh_file: OBJ and STL read into one polygon mesh, and the checks of mesh files
// that would crash VTK's readers (run before those readers): each names the file, line and
// problem.
#include "readers/io/mesh_file.hpp"
#include "tests/io/temp_file.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using namespace lc;
using lc::test::writeFile;

namespace {

std::string meshError(const std::string& name, const std::string& bytes) {
    try {
        io::checkMeshFile(writeFile(name, bytes).string());
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

std::string le32(std::uint32_t v) { return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; }
std::string f32(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return le32(u);
}

}  // namespace

TEST(MeshFile, ObjRelativeIndicesCountBackFromTheLatestVertex) {
    const fs::path p = writeFile("relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 1\nf 1 -1 2\n");
    const io::PolygonMesh m = io::readPolygonMesh(p.string());
    ASSERT_EQ(m.polygonCount(), 2u);
    EXPECT_EQ(m.corners, (std::vector<std::int64_t>{0, 1, 2, 0, 3, 1}));
    EXPECT_EQ(m.offsets, (std::vector<std::int64_t>{0, 3, 6}));
    EXPECT_EQ(m.points[3][2], 1.0);
}

TEST(MeshFile, StlAsciiAndBinaryGiveTheSameMergedSurface) {
    // A tetrahedron: 4 facets of 3 corners each, 4 distinct vertices after merging.
    const float p[4][3] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
    const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    std::string ascii = "solid tetra\n", binary = std::string(80, ' ') + le32(4);
    for (const auto& f : faces) {
        ascii += "  facet normal 0 0 0\n    outer loop\n";
        binary += f32(0) + f32(0) + f32(0);
        for (int c : f) {
            ascii += "      vertex " + std::to_string(p[c][0]) + " " + std::to_string(p[c][1]) + " " +
                     std::to_string(p[c][2]) + "\n";
            binary += f32(p[c][0]) + f32(p[c][1]) + f32(p[c][2]);
        }
        ascii += "    endloop\n  endfacet\n";
        binary += std::string(2, '\0');
    }
    ascii += "endsolid tetra\n";
    for (const auto& [name, bytes] : {std::pair{"tetra_ascii.stl", ascii}, std::pair{"tetra_binary.stl", binary}}) {
        const io::PolygonMesh m = io::readPolygonMesh(writeFile(name, bytes).string());
        ASSERT_EQ(m.points.size(), 4u) << name;
        ASSERT_EQ(m.polygonCount(), 4u) << name;
        for (std::size_t k = 0; k < m.corners.size(); ++k) {
            const int expected = faces[k / 3][k % 3];
            for (int i = 0; i < 3; ++i)
                EXPECT_EQ(m.points[std::size_t(m.corners[k])][std::size_t(i)], p[expected][i]) << name << " " << k;
        }
    }
    EXPECT_NE(
        meshError("five.stl",
                  "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n")
            .find("five.stl:7: 'vertex' where 'endloop'"),
        std::string::npos);
    EXPECT_NE(meshError("open.stl", "solid x\nfacet normal 0 0 1\nouter loop\n").find("ends inside a facet"),
              std::string::npos);
}

TEST(MeshCheck, ObjIndicesOutOfRangeZeroOrRelativeNameTheLine) {
    const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(meshError("ok.obj", v + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n"), "");
    EXPECT_EQ(meshError("okn.obj", v + "vn 0 0 1\nf 1//1 2//1 3//1\n"), "");
    // Found by fuzz_mesh_loader (VTK's reader crashed): "1/", mixed forms, a one-number vt.
    EXPECT_NE(meshError("slash.obj", "v 1 1 1\nf\t1/ 1 1\n").find("not a vertex reference"), std::string::npos);
    EXPECT_EQ(meshError("mixed.obj", v + "vt 0 0\nvn 0 0 1\nf 1/1 2/1 3\nf 1//1 2 3/1/1\n"),
              "");  // our walker takes any mix
    EXPECT_NE(meshError("vt1.obj", v + "vt 0\nf 1/1 2/1 3/1\n").find("'vt' needs 2"), std::string::npos);
    EXPECT_NE(meshError("bin.obj", v + "usemtl \xff\xfe\nf 1 2 3\n").find("not printable ASCII"), std::string::npos);
    EXPECT_NE(meshError("far.obj", v + "f 1 2 99999\n").find("far.obj:4: '99999' refers to vertex 99999, but only 3"),
              std::string::npos);
    EXPECT_NE(meshError("zero.obj", v + "f 0 1 2\n").find("index 0"), std::string::npos);
    EXPECT_NE(meshError("neg.obj", v + "f -1 -2 -4\n").find("'-4' refers back further than the 3 defined"),
              std::string::npos);
    EXPECT_NE(meshError("vt.obj", v + "f 1/5 2/5 3/5\n").find("texture coordinate 5"), std::string::npos);
    EXPECT_NE(meshError("two.obj", v + "f 1 2\n").find("at least 3 vertices"), std::string::npos);
    EXPECT_NE(meshError("nan.obj", "v 0 nan 0\n").find("finite numbers"), std::string::npos);
    EXPECT_NE(meshError("word.obj", v + "f 1 2 x\n").find("not a vertex reference"), std::string::npos);
}

TEST(MeshCheck, PlyListLengthsIndicesAndTruncationAscii) {
    const std::string head =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_EQ(meshError("ok.ply", head + "3 0 1 2\n"), "");
    EXPECT_NE(meshError("idx.ply", head + "3 0 1 7\n").find("vertex index 7 is not in [0, 3)"), std::string::npos);
    EXPECT_NE(meshError("short.ply", head + "3 0 1\n").find("fewer values on the line"), std::string::npos);
    EXPECT_NE(meshError("none.ply", head).find("ends before"), std::string::npos);
    // Found by fuzz_mesh_loader: enough values in the file, too few on one line (VTK crashed).
    const std::string shortLine =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0\n1 0 0 0\n0 1 0\n3 0 1 2\n";
    EXPECT_NE(meshError("line.ply", shortLine).find("vertex 0: fewer values"), std::string::npos);
    EXPECT_NE(meshError("eol.ply", head + "3 0 1 2").find("no newline at its end"),
              std::string::npos);  // VTK double-freed
    EXPECT_NE(meshError("dup.ply", "ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\nend_header\n")
                  .find("a second element"),
              std::string::npos);
    EXPECT_NE(
        meshError("count.ply", "ply\nformat ascii 1.0\nelement vertex -5\nend_header\n").find("not a whole number"),
        std::string::npos);
    EXPECT_NE(meshError("huge.ply", "ply\nformat ascii 1.0\nelement vertex 1e12\nproperty float x\nend_header\n")
                  .find("over the limit"),
              std::string::npos);
    EXPECT_NE(meshError("nohead.ply", "ply\nformat ascii 1.0\n").find("end_header"), std::string::npos);
}

TEST(MeshCheck, PlyNegativeListLengthBinary) {
    std::string head =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
    for (int i = 0; i < 9; ++i) head += f32(float(i % 2));
    EXPECT_EQ(meshError("okb.ply", head + le32(3) + le32(0) + le32(1) + le32(2)), "");
    EXPECT_NE(meshError("negb.ply", head + le32(std::uint32_t(-7)) + le32(0)).find("length -7"), std::string::npos);
    EXPECT_NE(meshError("idxb.ply", head + le32(3) + le32(0) + le32(1) + le32(3)).find("vertex index 3"),
              std::string::npos);
}

TEST(MeshCheck, BinaryStlSizeMustMatchItsTriangleCount) {
    const std::string header(80, ' ');
    EXPECT_EQ(meshError("ok.stl", header + le32(1) + std::string(50, '\0')), "");
    EXPECT_NE(meshError("bad.stl", header + le32(1000000) + std::string(50, '\0')).find("announces 1000000 triangles"),
              std::string::npos);
}
