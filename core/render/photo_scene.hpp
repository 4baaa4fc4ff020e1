#pragma once
// Every object of a Goedel scene as photo-object layers (seed 001 section 6): for each object a
// triangle mesh in its own frame, and for each (winding, branch) the image of every vertex in the
// observer's sky with its depth, emission time and frequency ratio. Objects at rest use the
// inverse problem of a static point (PhotoObjectBuilder, with stitching); freely falling objects
// solve for the emission event on each vertex's world line (imagesOfWorldLine). Both the CPU
// per-vertex raster and the shader renderer draw these layers.
#include "core/godel/images.hpp"
#include "core/godel/photo_object.hpp"
#include "core/scene/scene.hpp"

#include <functional>

namespace lc {

struct PhotoSceneLayer {
    int winding = 0;
    godel::Branch branch = godel::Branch::Outbound;
    std::vector<godel::VertexImage> vertices;   // one per mesh vertex (direction in the camera frame)
    std::vector<double> frequencyRatio;         // one per mesh vertex (1 for objects at rest)
    std::vector<std::array<int, 3>> triangles;  // those with all three vertices imaged
};

struct PhotoSceneObject {
    std::string name;
    int sceneIndex = 0;    // index over spheres then meshes (PixelRecord::object)
    godel::Mesh mesh;      // in the object's own frame
    std::vector<Vec2> uv;  // texture coordinates per vertex
    std::vector<PhotoSceneLayer> layers;
    int beyondHorizon = 0;  // vertices with no image at all
};

struct PhotoSceneOptions {
    int maxWinding = 2;
    int latitudes = 100, longitudes = 200;  // sphere tessellation
    int threads = 0;
    // Fraction of the objects done; may throw RenderCancelled (a GUI's Cancel), which stops the
    // moving objects' vertex loop within a few vertices and reaches the caller.
    std::function<void(double)> progress;
};

// The options a scene's settings ask for (windings, mesh resolution, threads): the CPU per-vertex
// renderer and the shader renderer build the same photo-objects from them.
PhotoSceneOptions photoSceneOptions(const Scene& scene);

// The images of a moving sphere's centre (free fall or world line), solved on the same world line
// and emission window as its vertices' photo-objects. Image::direction and the ray are in the
// observer's chart (observer at the origin, as godel::ObserverView); emissionTime in the world
// chart. Throws std::invalid_argument for a body at rest or a metric other than 'godel'.
std::vector<godel::MovingImage> imagesOfMovingCentre(const Scene& scene, const SphereObject& body, int maxWinding);

// The world line of a moving sphere's centre in the observer's chart (observer at the origin) and
// the window of its parameter that imagesOfMovingCentre searches for emissions (the part worth
// drawing); the same errors as imagesOfMovingCentre.
struct MovingCentre {
    godel::WorldLine line;
    godel::MovingImageOptions window;  // tauMin, tauMax, samples, maxWinding
};
MovingCentre movingCentre(const Scene& scene, const SphereObject& body, int maxWinding);

// Directions are given in the observer's camera frame (its local static frame e1, e2, e3);
// emission times in the world chart.
std::vector<PhotoSceneObject> buildPhotoScene(const Scene& scene, const PhotoSceneOptions& options);

}  // namespace lc
