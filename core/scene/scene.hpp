// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a render needs, independent of any file format: spacetime, observer, camera, objects.
#include "core/scene/animation.hpp"
#include "core/scene/camera.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/scene/texture.hpp"

#include <algorithm>

#include <string>
#include <vector>

namespace lc {
namespace godel {
class ProperTimeWorldLine;
}
class ThinDiskModel;

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

// How an object moves. Positions and velocities refer to its centre; the body keeps its shape
// in its own rest frame.
struct Motion {
    enum class Kind { Rest, ConstantVelocity, FreeFall, WorldLine, ProperTime } kind = Kind::Rest;
    Vec3 beta = Vec3::Zero();         // ConstantVelocity (flat spacetime): 3-velocity, |beta| < 1
    double k0 = 1, k3 = 0, phi0 = 0;  // FreeFall (Goedel): energy, dz/dtau, azimuth of the geodesic
                                      // through the centre event (docs/PHYSICS.md section 2)
    std::vector<Vec4> points;         // WorldLine: events in increasing time
    // ProperTime (Goedel): the centre's world line by proper time from the centre event, built
    // from segments; coordinate time may decrease along it (core/godel/proper_time_world_line.hpp).
    std::shared_ptr<const godel::ProperTimeWorldLine> properTimeLine;
    bool moving() const { return kind != Kind::Rest; }
};

struct SphereObject {
    std::string name;
    Vec4 centre = Vec4::Zero();  // chart coordinates (at rest: t ignored; moving: event at tau = 0)
    double radius = 1;
    PlacementPtr placement;  // event -> local coordinates (objects at rest)
    TexturePtr texture;
    TexturePtr nightTexture;  // optional: shown where the surface is unlit (earth at night)
    Motion motion;
    double temperature = 0;  // > 0: black-body emitter (K) instead of the texture colour
};

// The ambient light every lit surface gets, so that unlit sides stay visible.
constexpr double kAmbientLight = 0.08;

// Day/night multitexture: lit surfaces show the day texture times `lit` (the light plus the
// ambient kAmbientLight), and the night texture fades in as the light falls below 1/5 of full.
// For every scalar: the CPU shades with it, the shaders' lcDayNight is generated from it.
template <class S>
Eigen::Matrix<S, 3, 1> dayNightLit(const Eigen::Matrix<S, 3, 1>& day, const Eigen::Matrix<S, 3, 1>& night,
                                   const Eigen::Matrix<S, 3, 1>& lit) {
    using std::max;
    using std::min;
    const Eigen::Matrix<S, 3, 1> light = lit - Eigen::Matrix<S, 3, 1>::Constant(S(kAmbientLight));
    const S luminance = S(0.2126) * light(0) + S(0.7152) * light(1) + S(0.0722) * light(2);
    return day.cwiseProduct(lit) + min(max(S(1.0) - S(5.0) * luminance, S(0.0)), S(1.0)) * night;
}
// The same with the light without its ambient part, and an optional night texture.
inline Vec3 dayNightColour(const Vec3& day, const Vec3* night, const Vec3& light) {
    return dayNightLit<double>(day, night ? *night : Vec3::Zero(), Vec3::Constant(kAmbientLight) + light);
}

// A triangle mesh in the local frame of its centre (boxes are generated, files read by readers/).
struct MeshObject {
    std::string name;
    std::string source;  // file it came from, or "box"
    Vec4 centre = Vec4::Zero();
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // per position, unit
    std::vector<std::array<int, 3>> triangles;
    TexturePtr texture;
    Motion motion;
    double temperature = 0;
};

// A geometrically thin, optically thick disk in the equatorial plane z = 0 of a Kerr-Newman hole
// (core/accretion/thin_disk.hpp): matter on circular geodesics radiating the Page-Thorne flux.
struct DiskObject {
    std::string name;
    std::shared_ptr<const ThinDiskModel> model;  // orbits, edges and flux
    // How it looks: a black body at the Page-Thorne temperature (its hottest ring at `temperature`)
    // seen at g T with bolometric brightness g^4 F / F_max; the bolometric brightness alone (grey);
    // or `texture` in (u, v) = (phi / 2 pi, (r - r_in) / (r_out - r_in)), unlit, for orientation.
    enum class Emission { Blackbody, Flux, Texture } emission = Emission::Blackbody;
    double temperature = 1e4;  // K
    TexturePtr texture;
};

// A point light at rest (Goedel: static dust observer at its event), black-body coloured.
struct PointLight {
    std::string name;
    Vec4 position = Vec4::Zero();  // chart coordinates (t ignored: at rest)
    double temperature = 6500;     // K
    double intensity = 1;
};

struct RenderSettings {
    TraceOptions trace;
    // The scene's "stepper": "auto" (the default) models what each job needs: trace.stepper
    // (dopri5: dense output for the intersection tests) for images, dopri87 where only a ray's
    // fate counts (shadow edges; fastest at tight tolerances, docs/PERFORMANCE.md). False once a
    // stepper is named: then it serves every job.
    bool autoStepper = true;
    int windings = 2;  // Goedel: how many windings of the light rays to follow
    int threads = 0;   // 0: all cores
    bool progress = true;
    // Auto: closed form where the metric has one (Goedel, static observer), numeric otherwise.
    enum class Method { Auto, Numeric, ClosedForm, PerVertex } method = Method::Auto;
    int meshLatitudes = 100, meshLongitudes = 200;  // PerVertex tessellation of spheres
    // The rows [rowBegin, rowEnd) that the per-pixel methods (numeric, closed form) trace; the
    // others stay blank. A distributed render gives each task one band. rowEnd < 0: the last row.
    int rowBegin = 0, rowEnd = -1;
    // The numeric tracer carries a thin bundle with every ray (core/curvature/ray_bundle) and
    // records each pixel's magnification, shear and rotation (PixelRecord).
    bool magnification = false;
};

// A scene's stepper by name: "auto" or one of stepperNames(). Throws as parseStepper does.
inline void setSceneStepper(RenderSettings& settings, const std::string& name) {
    if (name == "auto") {
        settings.autoStepper = true;
        settings.trace.stepper = TraceOptions{}.stepper;
        return;
    }
    try {
        settings.trace.stepper = parseStepper(name);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string(e.what()) + "; or auto: dopri5 for images, dopri87 for shadow edges");
    }
    settings.autoStepper = false;
}
// "auto" or the named stepper, as a scene file writes it.
inline std::string sceneStepperName(const RenderSettings& settings) {
    return settings.autoStepper ? "auto" : stepperName(settings.trace.stepper);
}
// The stepper for rays of which only the fate counts (captured or escaped).
inline StepperKind fateStepper(const RenderSettings& settings) {
    return settings.autoStepper ? StepperKind::Dopri87 : settings.trace.stepper;
}
// What a scene's "stepper" and the commands' --stepper accept: "auto" and stepperNames().
inline std::vector<std::string> sceneStepperNames() {
    std::vector<std::string> names{"auto"};
    for (const auto& n : stepperNames()) names.push_back(n);
    return names;
}

struct Scene {
    std::string source;  // file it came from, for messages
    SpacetimePtr spacetime;
    Vec4 observer = Vec4::Zero();
    Vec4 observerVelocity = Vec4::Unit(0);  // contravariant; normalised by the frame builder
    Camera camera;
    std::vector<SphereObject> spheres;
    std::vector<MeshObject> meshes;
    std::vector<DiskObject> disks;   // at most one (the equatorial plane); kept apart from the objects
    std::vector<PointLight> lights;  // none: objects are self-luminous (unlit texture)
    TexturePtr sky;                  // asymptotically flat metrics: celestial sphere
    TexturePtr otherSky;             // two-ended metrics (Spacetime::hasOtherEnd): the far end's
    // A black-body sky (sky.temperature): light at this temperature from infinity, drawn at g T
    // with brightness g^4 times the sky texture's luminance, g the pixel's frequency ratio.
    std::optional<double> skyTemperature;
    Vec3 background{0.02, 0.02, 0.05};  // rays that hit nothing in the allowed windings
    RenderSettings settings;
    AnimationPath animation;  // the scene file's "animation" block (lightcone animate); empty when none
};

}  // namespace lc
