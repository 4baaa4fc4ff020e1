// The validation layer: strict numbers, the documented ranges (docs/SCENES.md shows exactly the
// table the code enforces), files that are not regular, and mesh files that would crash VTK's
// readers (checked before those readers run).
#include "core/input/ranges.hpp"
#include "core/metrics/factory.hpp"
#include "readers/io/input_file.hpp"
#include "readers/io/mesh_file.hpp"
#include "readers/io/scene_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace fs = std::filesystem;
using namespace lc;

namespace {

std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

fs::path writeFile(const std::string& name, const std::string& bytes) {
    const fs::path p = fs::temp_directory_path() / ("lightcone_check_" + std::to_string(::getpid()) + "_" + name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
}

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

TEST(Ranges, NumbersAreParsedStrictly) {
    EXPECT_EQ(input::parseNumber("0.5"), 0.5);
    EXPECT_EQ(input::parseNumber("-1e3"), -1000.0);
    for (const char* bad : {"0.5xyz", "", " 1", "1 ", "nan", "NaN", "inf", "-inf", "1e999", "0x", "--1", "1,2"})
        EXPECT_FALSE(input::parseNumber(bad).has_value()) << bad;
}

TEST(Ranges, IntegersFinitenessAndBounds) {
    EXPECT_TRUE(input::kImageSide.contains(16384));
    EXPECT_FALSE(input::kImageSide.contains(2.5));
    EXPECT_FALSE(input::kImageSide.contains(0));
    EXPECT_FALSE(input::kTolerance.contains(std::nan("")));
    EXPECT_FALSE(input::kCoordinate.contains(1e308));
    EXPECT_EQ(input::kImageSide.problem(2.5), "expected an integer in [1, 16384] px, got 2.5");
    EXPECT_EQ(input::kTolerance.problem(-INFINITY), "expected a number in [1e-15, 0.1], got -inf");
}

TEST(Ranges, DocsListExactlyTheEnforcedTable) {
    const std::string doc = readText(fs::path(LIGHTCONE_SOURCE_DIR) / "docs" / "SCENES.md");
    EXPECT_NE(doc.find(input::rangesMarkdown()), std::string::npos)
        << "docs/SCENES.md must contain the output of `lightcone ranges`:\n" << input::rangesMarkdown();
    EXPECT_NE(doc.find(metricParametersMarkdown()), std::string::npos)
        << "docs/SCENES.md must contain:\n" << metricParametersMarkdown();
}

TEST(InputFiles, DevicesFifosFoldersAndHugeFilesAreRefused) {
    auto error = [](const std::string& path, const input::Range& r) {
        try {
            io::checkInputFile(path, r);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error("/dev/zero", input::kTextureFileBytes).find("not a regular file"), std::string::npos);
    EXPECT_NE(error(fs::temp_directory_path().string(), input::kSceneFileBytes).find("is a directory"), std::string::npos);
    const fs::path fifo = fs::temp_directory_path() / ("lightcone_fifo_" + std::to_string(::getpid()));
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(error(fifo.string(), input::kSceneFileBytes).find("not a regular file"), std::string::npos);
    fs::remove(fifo);
    const input::Range tiny{"test file size", 1, 4, true, "bytes", ""};
    EXPECT_NE(error(writeFile("five.txt", "12345").string(), tiny).find("over the limit of 4 bytes"), std::string::npos);
    EXPECT_NE(error(writeFile("empty.txt", "").string(), tiny).find("is empty"), std::string::npos);
    EXPECT_NE(error("/nonexistent/file", tiny).find("does not exist"), std::string::npos);
}

TEST(InputFiles, TextureFromADeviceIsAnErrorNotAHang) {
    const std::string scene = R"({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0],
        "radius": 0.2, "texture": "/dev/zero"}]})";
    try {
        io::parseScene(scene, "scene.json", ".");
        FAIL();
    } catch (const io::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("objects[0].texture"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
    }
}

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
            ascii += "      vertex " + std::to_string(p[c][0]) + " " + std::to_string(p[c][1]) + " " + std::to_string(p[c][2]) + "\n";
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
            for (int i = 0; i < 3; ++i) EXPECT_EQ(m.points[std::size_t(m.corners[k])][std::size_t(i)], p[expected][i]) << name << " " << k;
        }
    }
    EXPECT_NE(meshError("five.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n")
                  .find("five.stl:7: 'vertex' where 'endloop'"), std::string::npos);
    EXPECT_NE(meshError("open.stl", "solid x\nfacet normal 0 0 1\nouter loop\n").find("ends inside a facet"), std::string::npos);
}

TEST(MeshCheck, ObjIndicesOutOfRangeZeroOrRelativeNameTheLine) {
    const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(meshError("ok.obj", v + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n"), "");
    EXPECT_EQ(meshError("okn.obj", v + "vn 0 0 1\nf 1//1 2//1 3//1\n"), "");
    // Found by fuzz_mesh_loader (VTK's reader crashed): "1/", mixed forms, a one-number vt.
    EXPECT_NE(meshError("slash.obj", "v 1 1 1\nf\t1/ 1 1\n").find("not a vertex reference"), std::string::npos);
    EXPECT_EQ(meshError("mixed.obj", v + "vt 0 0\nvn 0 0 1\nf 1/1 2/1 3\nf 1//1 2 3/1/1\n"), "");  // our walker takes any mix
    EXPECT_NE(meshError("vt1.obj", v + "vt 0\nf 1/1 2/1 3/1\n").find("'vt' needs 2"), std::string::npos);
    EXPECT_NE(meshError("bin.obj", v + "usemtl \xff\xfe\nf 1 2 3\n").find("not printable ASCII"), std::string::npos);
    EXPECT_NE(meshError("far.obj", v + "f 1 2 99999\n").find("far.obj:4: '99999' refers to vertex 99999, but only 3"), std::string::npos);
    EXPECT_NE(meshError("zero.obj", v + "f 0 1 2\n").find("index 0"), std::string::npos);
    EXPECT_NE(meshError("neg.obj", v + "f -1 -2 -4\n").find("'-4' refers back further than the 3 defined"), std::string::npos);
    EXPECT_NE(meshError("vt.obj", v + "f 1/5 2/5 3/5\n").find("texture coordinate 5"), std::string::npos);
    EXPECT_NE(meshError("two.obj", v + "f 1 2\n").find("at least 3 vertices"), std::string::npos);
    EXPECT_NE(meshError("nan.obj", "v 0 nan 0\n").find("finite numbers"), std::string::npos);
    EXPECT_NE(meshError("word.obj", v + "f 1 2 x\n").find("not a vertex reference"), std::string::npos);
}

TEST(MeshCheck, PlyListLengthsIndicesAndTruncationAscii) {
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_EQ(meshError("ok.ply", head + "3 0 1 2\n"), "");
    EXPECT_NE(meshError("idx.ply", head + "3 0 1 7\n").find("vertex index 7 is not in [0, 3)"), std::string::npos);
    EXPECT_NE(meshError("short.ply", head + "3 0 1\n").find("fewer values on the line"), std::string::npos);
    EXPECT_NE(meshError("none.ply", head).find("ends before"), std::string::npos);
    // Found by fuzz_mesh_loader: enough values in the file, too few on one line (VTK crashed).
    const std::string shortLine = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0\n1 0 0 0\n0 1 0\n3 0 1 2\n";
    EXPECT_NE(meshError("line.ply", shortLine).find("vertex 0: fewer values"), std::string::npos);
    EXPECT_NE(meshError("eol.ply", head + "3 0 1 2").find("no newline at its end"), std::string::npos);  // VTK double-freed
    EXPECT_NE(meshError("dup.ply", "ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\nend_header\n").find("a second element"),
              std::string::npos);
    EXPECT_NE(meshError("count.ply", "ply\nformat ascii 1.0\nelement vertex -5\nend_header\n").find("not a whole number"),
              std::string::npos);
    EXPECT_NE(meshError("huge.ply", "ply\nformat ascii 1.0\nelement vertex 1e12\nproperty float x\nend_header\n").find("over the limit"),
              std::string::npos);
    EXPECT_NE(meshError("nohead.ply", "ply\nformat ascii 1.0\n").find("end_header"), std::string::npos);
}

TEST(MeshCheck, PlyNegativeListLengthBinary) {
    std::string head = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
    for (int i = 0; i < 9; ++i) head += f32(float(i % 2));
    EXPECT_EQ(meshError("okb.ply", head + le32(3) + le32(0) + le32(1) + le32(2)), "");
    EXPECT_NE(meshError("negb.ply", head + le32(std::uint32_t(-7)) + le32(0)).find("length -7"), std::string::npos);
    EXPECT_NE(meshError("idxb.ply", head + le32(3) + le32(0) + le32(1) + le32(3)).find("vertex index 3"), std::string::npos);
}

TEST(MeshCheck, BinaryStlSizeMustMatchItsTriangleCount) {
    const std::string header(80, ' ');
    EXPECT_EQ(meshError("ok.stl", header + le32(1) + std::string(50, '\0')), "");
    EXPECT_NE(meshError("bad.stl", header + le32(1000000) + std::string(50, '\0')).find("announces 1000000 triangles"),
              std::string::npos);
}
