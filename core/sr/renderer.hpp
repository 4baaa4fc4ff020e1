#pragma once
// CPU reference renderer for SR scenes: observer and point light at rest in S, each object
// at rest in its own moving frame S'. Colour is the Doppler-shifted Planck colour of the
// object's emitter temperature, modulated by Phong shading computed in the rest frame.
#include <memory>
#include <vector>

#include "core/colour/blackbody.hpp"
#include "core/sr/camera.hpp"
#include "core/sr/lorentz.hpp"
#include "core/sr/mesh.hpp"

namespace lc::sr {

struct SrMaterial {
    double temperatureK = 6000.0;  // emitter temperature in the rest frame
    double ambient = 0.25, diffuse = 0.75, specular = 0.2, shininess = 32.0;
};

struct SrObject {
    TriMesh mesh;  // in S'
    MovingFrame frame;
    SrMaterial material;
};

struct SrScene {
    std::vector<SrObject> objects;
    Vec3 lightPosition = Vec3(0.0, 10.0, 10.0);  // point light at rest in S
    double lightTemperatureK = 6000.0;           // used with SrColourSource::ReflectedLight
    double observerTime = 0.0;                   // camera sits at (observerTime, camera.position)
};

enum class SrRenderMode {
    LocalRayTracing,    // footprint per triangle, exact hit per covered pixel, depth test (seed 003)
    BruteForce,         // every pixel against every triangle (reference for the above)
    PolygonDistortion,  // flat triangles through the apparent vertices
};

enum class SrColourSource {
    Emitter,         // the object glows at its material temperature, seen at D T
    ReflectedLight,  // the object reflects the Planck light of the lamp, seen at
                     // T_light (1 - beta.v_in) / (1 - beta.v_out) (seed 003 eq. 17)
};

struct SrRenderOptions {
    SrRenderMode mode = SrRenderMode::LocalRayTracing;
    colour::ToneMap toneMap = colour::ToneMap::ColourOnly;
    SrColourSource colourSource = SrColourSource::Emitter;
    bool doppler = true;  // false: emitter colour without shift
    bool shading = true;  // false: flat emitter colour (factor 1)
    Vec3 background = Vec3::Zero();
    int threads = 0;  // OpenMP threads; 0 = default
};

struct SrImage {
    int width = 0, height = 0;
    std::vector<float> rgb;      // row-major, 3 floats per pixel, row 0 at the top
    std::vector<float> depth;    // apparent distance |x_is - x_obs|, +inf where nothing is hit
    std::vector<int> object;     // -1 where nothing is hit
    std::vector<int> triangle;   // -1 where nothing is hit
    std::vector<float> doppler;  // nu_obs / nu_em at the hit, 0 where nothing is hit
};

class SrRenderer {
public:
    // The table is shared so several renderers (and a GPU upload) can use one.
    explicit SrRenderer(std::shared_ptr<const colour::BlackbodyTable> table = nullptr);

    SrImage render(const SrScene& scene, const PinholeCamera& camera, const SrRenderOptions& options) const;

    const colour::BlackbodyTable& table() const { return *table_; }

private:
    std::shared_ptr<const colour::BlackbodyTable> table_;
};

}  // namespace lc::sr
