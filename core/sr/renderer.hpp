// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// CPU reference renderer for SR scenes: observer and point light at rest in S, each object
// at rest in its own moving frame S'. Colour is the Doppler-shifted Planck colour of the
// object's emitter temperature, modulated by Phong shading computed in the rest frame.
#include <cmath>
#include <memory>
#include <vector>

#include "core/colour/blackbody.hpp"
#include "core/numerics/select.hpp"
#include "core/sr/doppler.hpp"
#include "core/sr/lorentz.hpp"
#include "core/sr/mesh.hpp"
#include "core/sr/observer_camera.hpp"

namespace lc::sr {

struct SrMaterial {
    double temperatureK = 6000.0;  // emitter temperature in the rest frame
    double ambient = 0.25, diffuse = 0.75, specular = 0.2, shininess = 32.0;
    // Throws std::invalid_argument("material values must be finite and >= 0") otherwise.
    void validate() const;
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

// The shading of a pixel's sample seen along the unit view direction d at apparent distance depth
// (seed 003 Fig. 9): the Phong factor in the emitter's rest frame, with the light and view
// directions aberrated there (u, v: barycentric weights of n1, n2; material: ambient, diffuse,
// specular, shininess; lightRelative: the light's position minus the eye's), and the observed
// black-body temperature: D T, or the lamp's T_light (1 - beta.v_in) / (1 - beta.v_out) for
// reflected light. Returns (factor, temperature); the colour is clamp(factor Planck(temperature)).
// The switches are scalars (> 0: on) so that the shaders take them as uniforms. For every scalar:
// double for SrRenderer, codegen::Expr for the shaders' lcSrShading.
template <class S>
Eigen::Matrix<S, 2, 1> srShading(const Eigen::Matrix<S, 3, 1>& d, const S& depth, const S& D, const S& u, const S& v,
                                 const Eigen::Matrix<S, 3, 1>& n0, const Eigen::Matrix<S, 3, 1>& n1,
                                 const Eigen::Matrix<S, 3, 1>& n2, const Eigen::Matrix<S, 3, 1>& beta,
                                 const S& temperature, const Eigen::Matrix<S, 4, 1>& material,
                                 const Eigen::Matrix<S, 3, 1>& lightRelative, const S& lightTemperature,
                                 const S& shading, const S& doppler, const S& reflected) {
    using std::max;
    using std::pow;
    using std::sqrt;
    using Vector = Eigen::Matrix<S, 3, 1>;
    const auto unit = [](const Vector& a) -> Vector { return a / sqrt(a.squaredNorm()); };
    const Vector inS = unit(depth * d - lightRelative);  // light -> apparent hit, in S
    const Vector back = -d;
    const Vector minusBeta = -beta;
    const Vector vIn = boostDirection<S>(minusBeta, inS), vOut = boostDirection<S>(minusBeta, back);
    Vector n = unit((S(1.0) - u - v) * n0 + u * n1 + v * n2);
    n = ifPositive(-n.dot(vOut), S(-1.0), S(1.0)) * n;  // two-sided: face the viewer
    const S diff = max(S(0.0), -n.dot(vIn));
    const Vector h = unit(vOut - vIn);
    const S spec = ifPositive(diff, pow(max(S(0.0), n.dot(h)), material(3)), S(0.0));
    const S factor = ifPositive(shading, material(0) + material(1) * diff + material(2) * spec, S(1.0));
    const S observed = ifPositive(
        reflected, lightTemperature * ifPositive(doppler, reflectionFrequencyRatio<S>(beta, inS, back), S(1.0)),
        ifPositive(doppler, D * temperature, temperature));  // observedTemperature: D T
    return Eigen::Matrix<S, 2, 1>(factor, observed);
}

class SrRenderer {
public:
    // The table is shared so several renderers (and a GPU upload) can use one.
    explicit SrRenderer(std::shared_ptr<const colour::BlackbodyTable> table = nullptr);

    // The camera is lc::Camera at the observer's position (pinhole or panorama; both fields of view
    // honoured). Throws std::invalid_argument for a camera ObserverCamera::validate refuses.
    SrImage render(const SrScene& scene, const ObserverCamera& camera, const SrRenderOptions& options) const;

    const colour::BlackbodyTable& table() const { return *table_; }

private:
    std::shared_ptr<const colour::BlackbodyTable> table_;
};

}  // namespace lc::sr
