// SPDX-License-Identifier: BSD-3-Clause
#include "core/render/special_relativity.hpp"
#include "core/scene/frame_camera.hpp"

#include "core/colour/srgb.hpp"
#include "core/sr/mesh.hpp"
#include "core/sr/renderer.hpp"

#include <chrono>
#include <stdexcept>

namespace lc {

bool isSrScene(const Scene& scene) { return scene.spacetime && scene.spacetime->name() == "minkowski"; }

namespace {

// The rest frame of an object whose centre passes the event `centre` with velocity beta:
// S' origin at t = 0 sits at x_c - beta t_c.
sr::MovingFrame restFrame(const Vec4& centre, const Motion& motion) {
    const Vec3 beta = motion.kind == Motion::Kind::ConstantVelocity ? motion.beta : Vec3::Zero();
    return sr::MovingFrame(beta, centre.tail<3>() - beta * centre(0));
}

}  // namespace

SrSceneAndCamera toSpecialRelativity(const Scene& scene) {
    if (!isSrScene(scene)) throw std::invalid_argument("special-relativity rendering needs the minkowski metric");
    if (scene.observerVelocity.tail<3>().norm() > 0)
        throw std::invalid_argument(
            "special relativity: the observer is at rest; give the objects the opposite velocity instead");
    scene.camera.validate();
    // The observer is at rest in Minkowski's chart, so its frame is the chart's: this only resolves look_at.
    const Camera cam = frameCamera(scene);

    SrSceneAndCamera out;
    sr::SrScene& srs = out.scene;
    srs.observerTime = scene.observer(0);
    auto material = [](double temperature) {
        sr::SrMaterial m;
        m.temperatureK = temperature > 0 ? temperature : 6000.0;
        return m;
    };
    auto checkMotion = [](const Motion& m, const std::string& name) {
        if (m.kind == Motion::Kind::FreeFall || m.kind == Motion::Kind::WorldLine || m.kind == Motion::Kind::ProperTime)
            throw std::invalid_argument("special relativity: object '" + name + "' needs constant velocity or rest");
    };
    for (const auto& s : scene.spheres) {
        checkMotion(s.motion, s.name);
        srs.objects.push_back(
            {sr::makeUvSphere(s.radius, 96, 48), restFrame(s.centre, s.motion), material(s.temperature)});
    }
    for (const auto& m : scene.meshes) {
        checkMotion(m.motion, m.name);
        sr::TriMesh mesh;
        mesh.positions = m.positions;
        mesh.normals = m.normals;
        mesh.triangles = m.triangles;
        srs.objects.push_back({mesh, restFrame(m.centre, m.motion), material(m.temperature)});
    }
    if (!scene.lights.empty()) {
        srs.lightPosition = scene.lights.front().position.tail<3>();
        srs.lightTemperatureK = scene.lights.front().temperature;
    }
    static_cast<Camera&>(out.camera) = cam;
    out.camera.position = scene.observer.tail<3>();
    return out;
}

ColouredImage renderSrImage(const Scene& scene, bool polygonDistortion) {
    const auto t0 = std::chrono::steady_clock::now();
    const SrSceneAndCamera in = toSpecialRelativity(scene);
    const sr::SrScene& srs = in.scene;
    const sr::ObserverCamera& pc = in.camera;
    sr::SrRenderOptions opt;
    opt.mode = polygonDistortion ? sr::SrRenderMode::PolygonDistortion : sr::SrRenderMode::LocalRayTracing;
    opt.threads = scene.settings.threads;
    opt.background = scene.background;
    const sr::SrImage img = sr::SrRenderer().render(srs, pc, opt);

    ColouredImage out;
    // SrRenderer's colours are display sRGB (tone-mapped table colours); the project's
    // pipeline carries linear RGB and encodes when writing.
    out.rgb.resize(img.rgb.size());
    for (std::size_t k = 0; k < img.rgb.size(); ++k) out.rgb[k] = static_cast<float>(colour::srgbDecode(img.rgb[k]));
    RenderResult& r = out.records;
    r.width = img.width;
    r.height = img.height;
    r.pixels.resize(static_cast<std::size_t>(img.width) * img.height);
    for (std::size_t n = 0; n < r.pixels.size(); ++n) {
        PixelRecord& p = r.pixels[n];
        if (img.object[n] < 0) {
            p.kind = PixelRecord::Background;
            continue;
        }
        p.kind = PixelRecord::Object;
        p.object = static_cast<std::int16_t>(img.object[n]);
        p.frequencyRatio = img.doppler[n];
        p.affine = img.depth[n];
        p.emissionTime = static_cast<float>(scene.observer(0) - img.depth[n]);  // light travels at c = 1
        p.stopReason = static_cast<std::int8_t>(StopReason::Hit);
        ++r.stats.hits;
    }
    r.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

ColouredImage renderColouredImage(const Scene& scene, const ProgressCallback& progress, bool polygonDistortion,
                                  const std::vector<PhotoSceneObject>* prebuiltPhotoScene) {
    if (isSrScene(scene)) {
        if (scene.settings.magnification)
            throw std::invalid_argument(
                "render.magnification (--magnification): the special-relativity renderer traces no ray bundles (in "
                "flat spacetime "
                "every image element's magnification is 1/g^2, g its frequency ratio: docs/PHYSICS.md 13a)");
        ColouredImage out = renderSrImage(scene, polygonDistortion);
        if (progress) progress(1.0);
        return out;
    }
    ColouredImage out;
    out.records = render(scene, progress, prebuiltPhotoScene);
    out.rgb = shadePixels(scene, out.records);
    return out;
}

}  // namespace lc
