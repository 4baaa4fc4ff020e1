#pragma once
// What a render needs, independent of any file format: spacetime, observer, camera, objects.
#include "core/camera.hpp"
#include "core/integrator.hpp"
#include "core/texture.hpp"

#include <string>
#include <vector>

namespace lc {

// Maps an event to the coordinates of an object's own local frame (centre at the origin).
class Placement {
public:
    virtual ~Placement() = default;
    virtual Vec3 toLocal(const Vec4& x) const = 0;
};
using PlacementPtr = std::shared_ptr<const Placement>;

// Static object in a chart with Cartesian spatial coordinates: a plain translation.
class TranslationPlacement final : public Placement {
public:
    explicit TranslationPlacement(Vec3 centre) : c_(centre) {}
    Vec3 toLocal(const Vec4& x) const override { return x.tail<3>() - c_; }

private:
    Vec3 c_;
};

struct SphereObject {
    std::string name;
    Vec4 centre = Vec4::Zero();  // chart coordinates (t ignored: at rest)
    double radius = 1;
    PlacementPtr placement;      // event -> local coordinates
    TexturePtr texture;
};

struct RenderSettings {
    TraceOptions trace;
    int windings = 2;       // Goedel: how many windings of the light rays to follow
    int threads = 0;        // 0: all cores
    bool progress = true;
    // Auto: closed form where the metric has one (Goedel, static observer), numeric otherwise.
    enum class Method { Auto, Numeric, ClosedForm, PerVertex } method = Method::Auto;
    int meshLatitudes = 100, meshLongitudes = 200;  // PerVertex tessellation of spheres
};

struct Scene {
    std::string source;  // file it came from, for messages
    SpacetimePtr spacetime;
    Vec4 observer = Vec4::Zero();
    Vec4 observerVelocity = Vec4::Unit(0);  // contravariant; normalised by the frame builder
    Camera camera;
    std::vector<SphereObject> spheres;
    TexturePtr sky;                          // asymptotically flat metrics: celestial sphere
    Vec3 background{0.02, 0.02, 0.05};       // rays that hit nothing in the allowed windings
    RenderSettings settings;
};

}  // namespace lc
