// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/mesh_file.hpp"

#include "core/input/ranges.hpp"
#include "readers/io/file_extension.hpp"
#include "readers/io/input_file.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace lc::io {
namespace {

constexpr long kMaxPolygonVertices = 65536;

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw std::runtime_error(where + ": " + what);
}

// checkInputFile or readInputFile on a mesh file, their refusals saying which file it is.
template <class Result>
Result meshFile(const std::string& path, Result (*access)(const std::string&, const input::Range&)) {
    try {
        return access(path, input::kMeshFileBytes);
    } catch (const std::exception& e) {
        throw std::runtime_error(std::string("the mesh file ") + e.what());
    }
}

void requireCount(const input::Range& r, double n, const std::string& where) {
    if (n < 0) fail(where, "negative count");
    if (n > r.max)
        fail(where,
             std::string(r.key) + " " + input::formatBound(n) + " over the limit of " + input::formatBound(r.max));
}

// ---- OBJ -------------------------------------------------------------------------------------

bool parseIndex(const std::string& text, long& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtol(text.c_str(), &end, 10);
    return errno == 0 && end == text.c_str() + text.size();
}

void readObj(const std::string& path, PolygonMesh& mesh) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot be opened");
    long counts[3] = {0, 0, 0};  // v, vt, vn
    double triangles = 0;
    std::string line;
    for (long lineNo = 1; std::getline(in, line); ++lineNo) {
        const std::string where = path + ":" + std::to_string(lineNo);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (!std::all_of(line.begin(), line.end(), [](char c) { return (c >= 0x20 && c < 0x7f) || c == '\t'; }))
            fail(where, "a character that is not printable ASCII (OBJ is a text format)");
        std::istringstream ss(line);
        std::string key;
        if (!(ss >> key) || key[0] == '#') continue;
        if (key == "v" || key == "vt" || key == "vn") {
            const int kind = key == "v" ? 0 : key == "vt" ? 1 : 2;
            const int needed = kind == 1 ? 2 : 3;  // a vt has u and v
            std::string tok;
            int n = 0;
            std::array<double, 3> value{};
            while (n < needed && ss >> tok) {
                const auto v = input::parseNumber(tok);
                if (!v)
                    fail(where, "'" + key + "' needs " + std::to_string(needed) + " finite numbers, got '" + tok + "'");
                value[static_cast<std::size_t>(n++)] = *v;
            }
            if (n < needed) fail(where, "'" + key + "' needs " + std::to_string(needed) + " numbers");
            if (++counts[kind] > input::kMeshVertices.max)
                requireCount(input::kMeshVertices, double(counts[kind]), where);
            if (kind == 0) mesh.points.push_back(value);
        } else if (key == "f" || key == "l" || key == "p") {
            std::string tok;
            long corners = 0;
            while (ss >> tok) {
                // Exactly v, v/vt, v//vn or v/vt/vn.
                std::vector<std::string> parts;
                for (std::size_t start = 0;;) {
                    const std::size_t slash = tok.find('/', start);
                    parts.push_back(tok.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
                    if (slash == std::string::npos) break;
                    start = slash + 1;
                }
                const bool valid = parts.size() == 1 || (parts.size() == 2 && !parts[1].empty()) ||
                                   (parts.size() == 3 && !parts[2].empty());
                if (!valid || parts[0].empty())
                    fail(where, "'" + tok + "' is not a vertex reference (v, v/vt, v//vn or v/vt/vn)");
                for (std::size_t part = 0; part < parts.size(); ++part) {
                    if (parts[part].empty()) continue;  // the empty vt of v//vn
                    long idx = 0;
                    if (!parseIndex(parts[part], idx)) fail(where, "'" + tok + "' is not a vertex reference");
                    if (idx == 0) fail(where, "index 0 in '" + tok + "' (OBJ indices start at 1)");
                    if (idx < 0) idx += counts[part] + 1;  // relative: -1 is the latest defined
                    if (idx < 1)
                        fail(where, "'" + tok + "' refers back further than the " + std::to_string(counts[part]) +
                                        " defined before this line");
                    if (idx > counts[part])
                        fail(where, "'" + tok + "' refers to " +
                                        (part == 0   ? "vertex"
                                         : part == 1 ? "texture coordinate"
                                                     : "normal") +
                                        " " + std::to_string(idx) + ", but only " + std::to_string(counts[part]) +
                                        " are defined before this line");
                    if (part == 0 && key == "f") mesh.corners.push_back(idx - 1);
                }
                if (++corners > kMaxPolygonVertices) fail(where, "a face with more than 65536 corners");
            }
            if (key == "f") {
                if (corners < 3) fail(where, "a face needs at least 3 vertices, got " + std::to_string(corners));
                triangles += double(corners - 2);
                requireCount(input::kMeshTriangles, triangles, where);
                mesh.offsets.push_back(static_cast<std::int64_t>(mesh.corners.size()));
            }
        }
    }
}

// ---- PLY -------------------------------------------------------------------------------------

enum class PlyFormat { Ascii, BinaryLittle, BinaryBig };

struct PlyProperty {
    std::string name;
    int size = 0;       // bytes of the value (or of each list item)
    int countSize = 0;  // > 0: a list with a count of this many bytes
    bool countSigned = false;
    bool floating = false, isSigned = false;
};

struct PlyElement {
    std::string name;
    double count = 0;
    std::vector<PlyProperty> properties;
};

int plyTypeSize(const std::string& t, bool& floating, bool& isSigned) {
    floating = t == "float" || t == "float32" || t == "double" || t == "float64";
    isSigned = floating || t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" || t == "int32";
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

class PlyBody {
public:
    PlyBody(std::istream& in, PlyFormat f) : in_(in), format_(f) {}

    // Each ASCII element is exactly one line holding exactly its values (VTK's reader, used
    // before our own, crashed on a short line: fuzz_mesh_loader).
    void beginElement(const std::string& where) {
        if (format_ != PlyFormat::Ascii) return;
        std::string text;
        if (!std::getline(in_, text)) fail(where, "the file ends before the data its header announces");
        // VTK's reader double-freed a last line without its newline (fuzz_mesh_loader): still refused.
        if (in_.eof()) fail(where, "the line has no newline at its end");
        line_.clear();
        line_.str(text);
        std::string probe;
        if (!(std::istringstream(text) >> probe)) fail(where, "an empty line where an element's values belong");
    }
    void endElement(const std::string& where) {
        std::string extra;
        if (format_ == PlyFormat::Ascii && line_ >> extra)
            fail(where, "more values on the line than the element's properties ('" + extra + "')");
    }

    double read(const PlyProperty& p, int size, const std::string& where) {
        if (format_ == PlyFormat::Ascii) {
            std::string tok;
            if (!(line_ >> tok)) fail(where, "fewer values on the line than the element's properties");
            const auto v = input::parseNumber(tok);
            if (!v) fail(where, "'" + tok + "' is not a finite number");
            return *v;
        }
        unsigned char b[8];
        if (!in_.read(reinterpret_cast<char*>(b), size))
            fail(where, "the file ends before the data its header announces");
        const bool little = format_ == PlyFormat::BinaryLittle;
        std::uint64_t u = 0;
        for (int i = 0; i < size; ++i) u |= std::uint64_t(b[little ? i : size - 1 - i]) << (8 * i);
        if (p.floating && size == 4) {
            float f;
            const std::uint32_t u32 = static_cast<std::uint32_t>(u);
            std::memcpy(&f, &u32, 4);
            return f;
        }
        if (p.floating) {
            double d;
            std::memcpy(&d, &u, 8);
            return d;
        }
        if (p.isSigned && size < 8 && (u >> (8 * size - 1)) & 1)
            return double(std::int64_t(u) - (std::int64_t(1) << (8 * size)));
        return double(u);
    }

private:
    std::istream& in_;
    PlyFormat format_;
    std::istringstream line_;
};

bool isIdentifier(const std::string& s) {
    return !s.empty() && s.size() <= 64 && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_') &&
           std::all_of(s.begin(), s.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// The header: the format and each element with its properties, every line checked.
struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
};

// Nothing may follow a header line's fields.
void requireLineEnd(std::istringstream& ss, const std::string& where) {
    std::string rest;
    if (ss >> rest) fail(where, "unexpected '" + rest + "' at the end of the header line");
}

// "format ascii 1.0" (or binary_little_endian, binary_big_endian).
PlyFormat parsePlyFormatLine(std::istringstream& ss, const std::string& where) {
    std::string f, version;
    ss >> f >> version;
    if (version != "1.0") fail(where, "PLY version '" + version + "' (expected 1.0)");
    requireLineEnd(ss, where);
    if (f == "ascii") return PlyFormat::Ascii;
    if (f == "binary_little_endian") return PlyFormat::BinaryLittle;
    if (f == "binary_big_endian") return PlyFormat::BinaryBig;
    fail(where, "unknown PLY format '" + f + "'");
}

// "element NAME COUNT": a new name, a whole count within the mesh limits.
PlyElement parsePlyElementLine(std::istringstream& ss, const std::vector<PlyElement>& elements,
                               const std::string& where) {
    PlyElement e;
    std::string count;
    ss >> e.name >> count;
    requireLineEnd(ss, where);
    if (!isIdentifier(e.name)) fail(where, "element name '" + e.name + "' is not an identifier");
    for (const auto& other : elements)
        if (other.name == e.name) fail(where, "a second element '" + e.name + "'");
    const auto n = input::parseNumber(count);
    if (!n || *n < 0 || *n != std::floor(*n))
        fail(where, "element '" + e.name + "' has count '" + count + "', not a whole number >= 0");
    e.count = *n;
    if (e.name == "vertex") requireCount(input::kMeshVertices, e.count, where);
    if (e.name == "face") requireCount(input::kMeshTriangles, e.count, where);
    return e;
}

// "property TYPE NAME" or "property list COUNTTYPE ITEMTYPE NAME" of the last element.
PlyProperty parsePlyPropertyLine(std::istringstream& ss, const PlyElement& element, const std::string& where) {
    PlyProperty p;
    std::string type;
    ss >> type;
    if (type == "list") {
        std::string countType, itemType;
        ss >> countType >> itemType >> p.name;
        requireLineEnd(ss, where);
        bool f;
        p.countSize = plyTypeSize(countType, f, p.countSigned);
        if (!p.countSize || f) fail(where, "list count type '" + countType + "' must be an integer type");
        p.size = plyTypeSize(itemType, p.floating, p.isSigned);
        if (!p.size) fail(where, "unknown list item type '" + itemType + "'");
    } else {
        ss >> p.name;
        requireLineEnd(ss, where);
        p.size = plyTypeSize(type, p.floating, p.isSigned);
        if (!p.size) fail(where, "unknown property type '" + type + "'");
    }
    if (!isIdentifier(p.name)) fail(where, "property name '" + p.name + "' is not an identifier");
    for (const auto& other : element.properties)
        if (other.name == p.name) fail(where, "a second property '" + p.name + "'");
    return p;
}

PlyHeader readPlyHeader(std::istream& in, const std::string& path) {
    std::string line;
    long lineNo = 1;
    if (!std::getline(in, line) || line.substr(0, 3) != "ply") fail(path + ":1", "not a PLY file (no 'ply' magic)");
    PlyHeader header;
    bool sawFormat = false;
    for (;;) {
        if (!std::getline(in, line)) fail(path, "the header has no 'end_header'");
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string where = path + ":" + std::to_string(lineNo);
        if (!std::all_of(line.begin(), line.end(), [](char c) { return c >= 0x20 && c < 0x7f; }))
            fail(where, "the header has a character that is not printable ASCII");
        std::istringstream ss(line);
        std::string key;
        ss >> key;
        if (key == "end_header") break;
        if (key.empty()) fail(where, "an empty header line");
        if (key == "comment" || key == "obj_info") continue;
        if (lineNo > 10000) fail(where, "a header of over 10000 lines");
        if (key == "format") {
            if (sawFormat) fail(where, "a second 'format' line");
            header.format = parsePlyFormatLine(ss, where);
            sawFormat = true;
        } else if (key == "element") {
            header.elements.push_back(parsePlyElementLine(ss, header.elements, where));
        } else if (key == "property") {
            if (header.elements.empty()) fail(where, "a property before any element");
            header.elements.back().properties.push_back(parsePlyPropertyLine(ss, header.elements.back(), where));
        } else {
            fail(where, "unknown header line '" + key + "'");
        }
    }
    if (!sawFormat) fail(path, "the header has no 'format' line");
    return header;
}

void checkPlyLayout(const std::vector<PlyElement>& elements, const std::string& path) {
    // The layout a mesh needs, and that VTK's reader (used before our own) crashed without
    // (fuzz_mesh_loader): a vertex element of scalars with x, y, z, and a face element with a
    // vertex index list.
    bool sawVertex = false;
    for (const auto& e : elements) {
        // An element without properties made VTK's reader free an invalid pointer (ply_close).
        if (e.properties.empty()) fail(path, "element '" + e.name + "' has no properties");
        auto has = [&e](const std::string& name, bool list) {
            return std::any_of(e.properties.begin(), e.properties.end(),
                               [&](const PlyProperty& p) { return p.name == name && (p.countSize > 0) == list; });
        };
        if (e.name == "vertex") {
            sawVertex = true;
            if (!has("x", false) || !has("y", false) || !has("z", false))
                fail(path, "the vertex element needs scalar x, y and z");
            for (const auto& p : e.properties)
                if (p.countSize) fail(path, "the vertex element has a list property '" + p.name + "'");
        }
        if (e.name == "face") {
            int lists = 0;
            for (const auto& p : e.properties) lists += p.countSize > 0;
            if (lists != 1 || !(has("vertex_indices", true) || has("vertex_index", true)))
                fail(path, "the face element needs exactly one list property, named vertex_indices");
        }
    }
    if (!sawVertex) fail(path, "no vertex element");
    // A mesh needs faces (VTK's reader dereferenced find_element("face") unchecked: fuzz_mesh_loader).
    if (std::none_of(elements.begin(), elements.end(), [](const PlyElement& e) { return e.name == "face"; }))
        fail(path, "no face element (a mesh needs triangles)");
}

// The elements in the header's order; vertices and faces go into the mesh.
void readPlyBody(std::istream& in, const PlyHeader& header, const std::string& path, PolygonMesh& mesh) {
    const std::vector<PlyElement>& elements = header.elements;
    double vertices = 0;
    for (const auto& e : elements)
        if (e.name == "vertex") vertices = e.count;
    PlyBody body(in, header.format);
    for (const auto& e : elements) {
        const bool isVertex = e.name == "vertex";
        if (isVertex) mesh.points.reserve(static_cast<std::size_t>(e.count));
        for (double i = 0; i < e.count; ++i) {
            std::array<double, 3> point{};
            const std::string where = path + ": " + e.name + " " + input::formatBound(i);
            body.beginElement(where);
            for (const auto& p : e.properties) {
                if (p.countSize) {
                    PlyProperty countProp;
                    countProp.isSigned = p.countSigned;
                    const double n = body.read(countProp, p.countSize, where);
                    const bool indices = e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
                    if (n < 0 || n != std::floor(n) || n > kMaxPolygonVertices || (indices && n < 3))
                        fail(where, "list '" + p.name + "' has length " + input::formatBound(n) +
                                        (indices ? ", expected 3 to 65536 vertex indices" : ", expected 0 to 65536"));
                    for (double k = 0; k < n; ++k) {
                        const double v = body.read(p, p.size, where);
                        if (indices && !(v >= 0 && v < vertices && v == std::floor(v)))
                            fail(where, "vertex index " + input::formatBound(v) + " is not in [0, " +
                                            input::formatBound(vertices) + ")");
                        if (indices) mesh.corners.push_back(static_cast<std::int64_t>(v));
                    }
                    if (indices) mesh.offsets.push_back(static_cast<std::int64_t>(mesh.corners.size()));
                } else {
                    const double v = body.read(p, p.size, where);
                    if (isVertex && !std::isfinite(v)) fail(where, "property '" + p.name + "' is not finite");
                    if (isVertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
                        point[static_cast<std::size_t>(p.name[0] - 'x')] = v;
                }
            }
            body.endElement(where);
            if (isVertex) mesh.points.push_back(point);
        }
    }
}

void readPly(const std::string& path, PolygonMesh& mesh) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot be opened");
    const PlyHeader header = readPlyHeader(in, path);
    checkPlyLayout(header.elements, path);
    readPlyBody(in, header, path, mesh);
}

// ---- STL -------------------------------------------------------------------------------------

// STL repeats each vertex in every facet that uses it; merging equal coordinates gives the
// connected surface that smooth normals and their outward orientation need.
class MergedPoints {
public:
    explicit MergedPoints(PolygonMesh& mesh) : mesh_(mesh) {}
    std::int64_t index(const std::array<double, 3>& p) {
        const auto found = ids_.emplace(p, static_cast<std::int64_t>(mesh_.points.size()));
        if (found.second) mesh_.points.push_back(p);
        return found.first->second;
    }

private:
    struct Hash {
        std::size_t operator()(const std::array<double, 3>& p) const {
            std::size_t h = 0;
            for (double c : p) h = h * 1000003u ^ std::hash<double>()(c);
            return h;
        }
    };
    PolygonMesh& mesh_;
    std::unordered_map<std::array<double, 3>, std::int64_t, Hash> ids_;
};

void addTriangle(PolygonMesh& mesh, MergedPoints& merged, const std::array<std::array<double, 3>, 3>& corners) {
    for (const auto& c : corners) mesh.corners.push_back(merged.index(c));
    mesh.offsets.push_back(static_cast<std::int64_t>(mesh.corners.size()));
}

float littleEndianFloat(const unsigned char* b) {
    const std::uint32_t u =
        std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

// Binary STL: an 80-byte header, a 32-bit triangle count, then 50 bytes per triangle (normal,
// three corners, two attribute bytes). Only a file of exactly 84 + 50 n bytes is taken as binary.
void readBinaryStl(std::istream& in, std::uint32_t triangles, const std::string& path, PolygonMesh& mesh) {
    requireCount(input::kMeshTriangles, triangles, path);
    MergedPoints merged(mesh);
    in.seekg(84);
    unsigned char facet[50];
    for (std::uint32_t t = 0; t < triangles; ++t) {
        if (!in.read(reinterpret_cast<char*>(facet), 50)) fail(path, "the file ends inside facet " + std::to_string(t));
        std::array<std::array<double, 3>, 3> corners{};
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) {
                const double v = littleEndianFloat(facet + 12 + 12 * c + 4 * k);
                if (!std::isfinite(v)) fail(path + ": facet " + std::to_string(t), "a corner coordinate is not finite");
                corners[static_cast<std::size_t>(c)][static_cast<std::size_t>(k)] = v;
            }
        addTriangle(mesh, merged, corners);
    }
    requireCount(input::kMeshVertices, double(mesh.points.size()), path);
}

// ASCII STL: solid NAME, then per facet "facet normal nx ny nz", "outer loop", three
// "vertex x y z", "endloop", "endfacet"; "endsolid" closes a solid (another may follow).
void readAsciiStl(std::istream& in, const std::string& path, PolygonMesh& mesh) {
    MergedPoints merged(mesh);
    enum class Expect { Solid, FacetOrEnd, OuterLoop, Vertex, EndLoop, EndFacet } expect = Expect::Solid;
    std::array<std::array<double, 3>, 3> corners{};
    int vertices = 0;
    std::string line;
    long lineNo = 0;
    auto numbers = [](std::istringstream& ss, const std::string& where, const std::string& what) {
        std::array<double, 3> v{};
        std::string tok;
        for (auto& c : v) {
            if (!(ss >> tok)) fail(where, what + " needs 3 numbers");
            const auto n = input::parseNumber(tok);
            if (!n) fail(where, "'" + tok + "' is not a finite number");
            c = *n;
        }
        return v;
    };
    while (std::getline(in, line)) {
        const std::string where = path + ":" + std::to_string(++lineNo);
        if (!std::all_of(line.begin(), line.end(),
                         [](char c) { return (c >= 0x20 && c < 0x7f) || c == '\t' || c == '\r'; }))
            fail(where, "a character that is not printable ASCII (and the file's size is not that of a binary STL)");
        std::istringstream ss(line);
        std::string key, word;
        if (!(ss >> key)) continue;
        auto expected = [&](const char* what) { fail(where, "'" + key + "' where " + what + " belongs"); };
        switch (expect) {
            case Expect::Solid:
                if (key != "solid") expected("'solid'");
                expect = Expect::FacetOrEnd;
                continue;  // the rest of the line is the solid's name
            case Expect::FacetOrEnd:
                if (key == "endsolid") {
                    expect = Expect::Solid;
                    continue;
                }
                if (key != "facet" || !(ss >> word) || word != "normal") expected("'facet normal' or 'endsolid'");
                numbers(ss, where, "'facet normal'");
                expect = Expect::OuterLoop;
                break;
            case Expect::OuterLoop:
                if (key != "outer" || !(ss >> word) || word != "loop") expected("'outer loop'");
                vertices = 0;
                expect = Expect::Vertex;
                break;
            case Expect::Vertex:
                if (key != "vertex") expected("'vertex'");
                corners[static_cast<std::size_t>(vertices)] = numbers(ss, where, "'vertex'");
                if (++vertices == 3) expect = Expect::EndLoop;
                break;
            case Expect::EndLoop:
                if (key != "endloop") expected("'endloop' (a facet has exactly 3 vertices)");
                expect = Expect::EndFacet;
                break;
            case Expect::EndFacet:
                if (key != "endfacet") expected("'endfacet'");
                addTriangle(mesh, merged, corners);
                requireCount(input::kMeshTriangles, double(mesh.polygonCount()), where);
                requireCount(input::kMeshVertices, double(mesh.points.size()), where);
                expect = Expect::FacetOrEnd;
                continue;
        }
        if (ss >> word) fail(where, "unexpected '" + word + "' at the end of the line");
    }
    if (expect == Expect::Solid && lineNo == 0) fail(path, "an empty file");
    if (expect != Expect::Solid && expect != Expect::FacetOrEnd) fail(path, "the file ends inside a facet");
}

void readStl(const std::string& path, std::uintmax_t size, PolygonMesh& mesh) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot be opened");
    unsigned char head[84] = {};
    in.read(reinterpret_cast<char*>(head), 84);
    std::uint32_t n = 0;
    if (size >= 84)
        for (int i = 0; i < 4; ++i) n |= std::uint32_t(head[80 + i]) << (8 * i);
    if (size >= 84 && 84 + 50ull * n == size) return readBinaryStl(in, n, path, mesh);
    if (std::strncmp(reinterpret_cast<const char*>(head), "solid", 5) != 0) {
        if (size < 84)
            fail(path, "too short for a binary STL (84-byte header) and not an ASCII STL (which starts with 'solid')");
        fail(path, "binary STL announces " + std::to_string(n) + " triangles (" + std::to_string(84 + 50ull * n) +
                       " bytes) but the file has " + std::to_string(size) +
                       " bytes, and it is not an ASCII STL (which starts with 'solid')");
    }
    in.clear();
    in.seekg(0);
    readAsciiStl(in, path, mesh);
}

// ---- VTP -------------------------------------------------------------------------------------

// The value of attribute `name` in an XML start tag, or nothing.
std::optional<std::string> attribute(const std::string& tag, const std::string& name) {
    for (std::size_t at = tag.find(name + "=\""); at != std::string::npos; at = tag.find(name + "=\"", at + 1)) {
        if (at > 0 && !std::isspace(static_cast<unsigned char>(tag[at - 1])))
            continue;  // "NumberOfPoints" inside another name
        const std::size_t start = at + name.size() + 2, end = tag.find('"', start);
        if (end == std::string::npos) return std::nullopt;
        return tag.substr(start, end - start);
    }
    return std::nullopt;
}

}  // namespace

// VTK's XML reader sizes its arrays from the Piece and DataArray attributes and trusts them (a
// negative NumberOfPoints crashed it, found by fuzz_mesh_loader): every count a whole number in
// its range, every DataArray of a known type and format with 1 to 64 components.
void checkVtpFile(const std::string& path) {
    const std::string text = meshFile(path, readInputFile);
    const std::string xml = text.substr(0, text.find("<AppendedData"));  // raw appended bytes follow
    auto each = [&xml](const std::string& element, auto&& check) {
        for (std::size_t at = xml.find("<" + element); at != std::string::npos; at = xml.find("<" + element, at + 1)) {
            const std::size_t end = xml.find('>', at);
            if (end == std::string::npos) fail("VTP", "an unterminated <" + element + "> tag");
            check(xml.substr(at, end - at));
        }
    };
    auto count = [&path](const std::string& tag, const std::string& name, const input::Range& range) {
        const auto v = attribute(tag, name);
        if (!v) return;
        const auto n = input::parseNumber(*v);
        if (!n || *n < 0 || *n != std::floor(*n) || *n > range.max)
            fail(path, name + "=\"" + *v + "\": expected a whole number in [0, " + input::formatBound(range.max) + "]");
    };
    int pieces = 0;
    each("Piece", [&](const std::string& tag) {
        ++pieces;
        count(tag, "NumberOfPoints", input::kMeshVertices);
        for (const char* cells : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
            count(tag, cells, input::kMeshTriangles);
    });
    if (pieces == 0) fail(path, "no <Piece> element (not a VTK PolyData file?)");
    each("DataArray", [&](const std::string& tag) {
        static const input::Range components{"components", 1, 64, true, "", ""};
        if (const auto c = attribute(tag, "NumberOfComponents")) {
            const auto n = input::parseNumber(*c);
            if (!n || !components.contains(*n)) fail(path, "NumberOfComponents=\"" + *c + "\": expected 1 to 64");
        }
        count(tag, "NumberOfTuples", input::kMeshTriangles);
        const auto format = attribute(tag, "format");
        if (format && *format != "ascii" && *format != "binary" && *format != "appended")
            fail(path, "DataArray format \"" + *format + "\" (expected ascii, binary or appended)");
        static const char* types[] = {"Int8",   "UInt8", "Int16",  "UInt16",  "Int32",
                                      "UInt32", "Int64", "UInt64", "Float32", "Float64"};
        const auto type = attribute(tag, "type");
        if (!type || std::none_of(std::begin(types), std::end(types), [&](const char* t) { return *type == t; }))
            fail(path, "DataArray type \"" + type.value_or("") + "\" (expected Int8 ... Float64)");
    });
}

PolygonMesh readPolygonMesh(const std::string& path) {
    const std::uintmax_t size = meshFile(path, checkInputFile);
    const std::string ext = lowerCaseExtension(path);
    PolygonMesh mesh;
    if (ext == ".obj")
        readObj(path, mesh);
    else if (ext == ".ply")
        readPly(path, mesh);
    else if (ext == ".stl")
        readStl(path, size, mesh);
    else
        throw std::runtime_error("unknown mesh format '" + ext + "' (expected .obj, .ply, .stl or .vtp)");
    if (mesh.polygonCount() == 0) fail(path, "no triangles in the file");
    return mesh;
}

void checkMeshFile(const std::string& path) {
    if (lowerCaseExtension(path) == ".vtp")
        checkVtpFile(path);
    else
        readPolygonMesh(path);
}

}  // namespace lc::io
