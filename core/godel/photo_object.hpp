// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Photo-objects per vertex (seed 001 sections 5-6): for every vertex of a mesh, every image
// (direction in the observer's sky and depth lambda) for windings 0..N on both branches. A
// renderer draws each (winding, branch) layer as an ordinary mesh with those directions and
// depths; stitching joins the two branches of one winding where part of the object has no image.
//
// Placement: the mesh is given in the local flat frame at its centre; the vertex v goes to
// placement.apply((0, v)), with placement = Isometry::movingOriginTo(centre) by default, so the
// same mesh has the same shape anywhere (homogeneity). The observer sits at any event.
#include "core/godel/images.hpp"

#include <array>
#include <string>
#include <vector>

namespace lc::godel {

struct Mesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
};

struct VertexImage {
    bool valid = false;             // this vertex has an image in this layer
    bool welded = false;            // moved by stitching (position shared by both branches of the winding)
    Vec3 direction = Vec3::Zero();  // unit sky direction, observer's frame
    double lambda = 0;              // depth
    double emissionTime = 0;        // observer chart (observer at t = 0)
};

struct PhotoLayer {
    int winding = 0;
    Branch branch = Branch::Outbound;
    std::vector<VertexImage> vertices;          // one per mesh vertex
    std::vector<std::array<int, 3>> triangles;  // those with all three vertices imaged
};

enum class PhotoStatus { Ok, InvalidMesh };

struct PhotoObject {
    PhotoStatus status = PhotoStatus::Ok;
    std::string message;
    std::vector<PhotoLayer> layers;   // index 2n + b: winding n, branch b (0 Outbound, 1 Inbound)
    std::vector<int> beyondHorizon;   // vertices at r >= 2a from the observer: no image at all
    std::vector<Vec4> observerChart;  // the vertices in the observer's chart (t = 0)
    int weldedVertices = 0;           // over all windings
    const PhotoLayer& layer(int n, Branch b) const { return layers[2 * n + (b == Branch::Inbound)]; }
};

struct PhotoObjectOptions {
    int maxWinding = 2;
    int threads = 0;  // OpenMP threads; 0: OpenMP's default
    bool stitch = true;
};

class PhotoObjectBuilder {
public:
    // The observer's chart: Isometry::observerToOrigin(observerEvent), so directions are the camera's.
    PhotoObjectBuilder(double a, const Vec4& observerEvent);
    // Mesh centred at the world event `centre` (its frame: Isometry::movingOriginTo(centre)).
    PhotoObject build(const Mesh& mesh, const Vec4& centre, const PhotoObjectOptions& opt = {}) const;
    // Mesh placed by any isometry from its centre-at-origin chart to the world.
    PhotoObject build(const Mesh& mesh, const Isometry& placement, const PhotoObjectOptions& opt = {}) const;

private:
    double a_;
    Isometry toObserver_;
    ImageSolver solver_;
};

// Seed 001 section 5.2 / 6: per winding, triangles need all three vertices imaged. Vertices with
// an image on one branch only take it from the other branch; vertices on the rim between kept and
// dropped triangles get the average of their two branch images, so the two photo-objects of the
// winding fuse there. Returns the number of welded vertices.
int stitchWinding(const Mesh& mesh, PhotoLayer& outbound, PhotoLayer& inbound);

// A UV sphere of radius R (for tests and benchmarks): (nLat - 1) * nLon + 2 vertices.
Mesh uvSphere(double radius, int nLat, int nLon);

}  // namespace lc::godel
