// SPDX-License-Identifier: BSD-3-Clause
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

class GodelLighting;

struct PhotoSceneLayer {
    int winding = 0;
    godel::Branch branch = godel::Branch::Outbound;
    std::vector<godel::VertexImage> vertices;   // one per mesh vertex (direction in the camera frame)
    std::vector<double> frequencyRatio;         // one per mesh vertex (1 for objects at rest)
    std::vector<std::array<int, 3>> triangles;  // those with all three vertices imaged
    // Moving bodies: the body's proper time at each vertex's emission event (its world line's
    // parameter: coordinate time for a world line of events), and which crossing of the observer's
    // past light cone this layer shows in its (winding, branch), counted along the world line.
    std::vector<double> properTime;
    int crossing = 0;
};

// The most one object's photo-object layers may hold (a quarter of the 24 GB machines is for all
// of them and the image): buildPhotoObject refuses more, saying how much and why.
constexpr double kMaxPhotoObjectBytes = 2e9;
// The most a whole scene's photo-objects may hold (3000 spheres at the default 100 x 200
// tessellation once asked for 21 GB): buildPhotoScene refuses more before building any.
constexpr double kMaxPhotoSceneBytes = 6e9;

struct PhotoSceneObject {
    std::string name;
    int sceneIndex = 0;    // index over spheres then meshes (PixelRecord::object)
    godel::Mesh mesh;      // in the object's own frame
    std::vector<Vec2> uv;  // texture coordinates per vertex
    std::vector<PhotoSceneLayer> layers;
    std::vector<int> beyondHorizon;  // the vertices with no image at all
    int weldedVertices = 0;          // moved by stitching, over all windings (objects at rest)
    // Lit spheres at rest: linear RGB light per vertex, ambient included (vertexLight); empty
    // when unlit. Built with the photo-objects, off the GUI thread: it traces shadow rays.
    std::vector<Vec3> light;
};

struct PhotoSceneOptions {
    int maxWinding = 2;
    int latitudes = 100, longitudes = 200;  // sphere tessellation
    int threads = 0;
    // Directions in the observer's local static frame (e1, e2, e3: lc::Camera's frame) or, false,
    // in the observer's chart (observer moved to the origin: godel::ObserverView's directions).
    bool cameraFrame = true;
    bool stitch = true;  // join the two branches of a winding where part of a resting object has no image
    // Also each lit sphere's light per vertex (PhotoSceneObject::light, shadow rays) for the shader
    // renderer; the CPU renderers light per pixel and leave it off.
    bool vertexLight = false;
    // Fraction of the objects done; may throw RenderCancelled (a GUI's Cancel), which stops the
    // moving objects' vertex loop within a few vertices and reaches the caller.
    std::function<void(double)> progress;
};

// The options a scene's settings ask for (windings, mesh resolution, threads): the CPU per-vertex
// renderer and the shader renderer build the same photo-objects from them.
PhotoSceneOptions photoSceneOptions(const Scene& scene);

// What photo-objects will hold, in bytes, before any is built: per object from its mesh's size
// (its layers' vertex images, frequency ratios, proper times and triangles; the mesh, its texture
// coordinates and light), and for a whole scene from the tessellation `options` asks for.
double photoObjectBytes(std::size_t vertices, std::size_t triangles, bool moving, int maxWinding);
double photoSceneBytes(const Scene& scene, const PhotoSceneOptions& options);

// Each image of the centre of every sphere whose world line is given by proper time (segments):
// where the camera sees it (frame components, as Camera::project takes them after
// lc::frameCamera) and the body's proper time at emission, i.e. its age in that image.
struct AgeImage {
    int object = 0;
    std::string name;
    double properTime = 0, emissionTime = 0;
    Vec3 direction = Vec3::UnitX();
    double angularRadius = 0;  // rad, about radius / affine distance (for placing a label beside it)
};
std::vector<AgeImage> ageImages(const Scene& scene);

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

// One object to image: its mesh in its own frame, its centre event (at rest) or the event of its
// tau = 0 (moving), its motion (at rest, free fall or a given world line).
struct PhotoSource {
    std::string name;
    Vec4 centre = Vec4::Zero();
    Motion motion;
    godel::Mesh mesh;
};
// Texture coordinates of each vertex, spherical about the mesh's centre (u: azimuth, v: polar angle).
std::vector<Vec2> sphericalUvs(const godel::Mesh& mesh);

// The objects of a scene: spheres (tessellated as options asks) then meshes.
std::vector<PhotoSource> photoSources(const Scene& scene, const PhotoSceneOptions& options);

// The photo-object layers of one object seen by a static observer at `observer` in the Goedel
// universe of parameter a: directions in the camera frame (or the observer's chart, see
// PhotoSceneOptions::cameraFrame), emission times in the world chart, texture coordinates spherical about the centre.
// options.progress gets this object's fraction done. Throws std::invalid_argument for a constant
// velocity (flat spacetime only) or an invalid mesh. The one builder of photo-objects: the scene's
// (buildPhotoScene) and vtkLightconePhotoObjectFilter's.
PhotoSceneObject buildPhotoObject(double a, const Vec4& observer, const PhotoSource& source,
                                  const PhotoSceneOptions& options);

// Every object of the scene (buildPhotoObject of each photoSources entry; sceneIndex numbered),
// with its light per vertex where the scene has lights (vertexLight).
std::vector<PhotoSceneObject> buildPhotoScene(const Scene& scene, const PhotoSceneOptions& options);

// Object `object` (a sphere at rest, lit by the scene's lights): ambient plus the light arriving
// along the lights' null rays at each vertex of its mesh (`lighting`, the scene's, shadows
// included), as the shader renderer colours it; empty for moving objects, meshes and scenes
// without lights.
std::vector<Vec3> vertexLight(double a, const Scene& scene, const GodelLighting& lighting, const PhotoSource& source,
                              std::size_t object);

}  // namespace lc
