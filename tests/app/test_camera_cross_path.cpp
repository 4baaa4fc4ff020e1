// SPDX-License-Identifier: BSD-3-Clause
// One camera for every renderer (issue 51): small balls at known directions, rendered through every
// path that can show them, land where the documented camera (docs/SCENES.md "Camera") puts them.
// The oracle is written here from the documented formulas, not from lc::Camera: pixel (i, j) looks
// along f + sx tan(fov_x / 2) r + sy tan(fov_y / 2) u (pinhole) or at azimuth -sx fov_x / 2 and
// elevation sy fov_y / 2 (panorama), sx = 2 (i + 1/2) / W - 1, sy = 1 - 2 (j + 1/2) / H; a pixel
// shows a ball when that ray meets it, in flat space (Minkowski at rest; Schwarzschild with
// M = 1e-6, bending 1e-7; Goedel with a = 1000 at distance 10, where the chart is Minkowski to
// (r/a)^2) or, for balls moving at beta = 0.5, in the ball's rest frame after the Lorentz
// transformation of the viewing ray. Each path's centroid of each ball is compared with the
// oracle's centroid of the same pixel sampling: within 0.5 px. The paths: `render --data`'s object
// pixels (the command run as a user runs it, the EXR read back), the CPU's
// special-relativity local ray tracing and polygon distortion, the numeric (odeint) and closed-form
// renderers, and on the GPU the special-relativity techniques and the Goedel photo-object mapper
// (the GPU geodesic tracer draws no spheres: its camera, the same generated functions, is checked
// pixel for pixel against the CPU by ShaderImages); each with a pinhole of non-square pixels (the 640 x 360, 101.5 x 75
// degree camera of data/sr_cube.json, at half size) and a panorama with balls behind the observer.
#include "app/commands/commands.hpp"
#include "core/render/special_relativity.hpp"
#include "readers/io/scene_reader.hpp"
#include "tests/app/run_command.hpp"
#include "vtkLightconeSrImageRenderer.h"

#include <vtkNew.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using lc::Vec3;
using lc::Vec4;
constexpr double kDeg = 3.14159265358979323846 / 180;

// A view as docs/SCENES.md documents it: forward -z, up +y (right = forward x up = +x).
struct DocumentedView {
    bool panorama = false;
    int width = 320, height = 180;
    double fovX = 101.5, fovY = 75;
    // The chart's components of the view's directions (a rotation): the Goedel scenes turn the view
    // so that its up is the chart's z, the axis of the Goedel chart, where no ball lies.
    Eigen::Matrix3d toChart = Eigen::Matrix3d::Identity();
    Vec3 position = Vec3::Zero();  // the observer's place in the chart; the balls are given from it

    Vec3 pixelDirection(int i, int j) const {
        const Vec3 f(0, 0, -1), r(1, 0, 0), u(0, 1, 0);
        const double sx = 2 * (i + 0.5) / width - 1, sy = 1 - 2 * (j + 0.5) / height;
        if (!panorama)
            return (f + sx * std::tan(0.5 * fovX * kDeg) * r + sy * std::tan(0.5 * fovY * kDeg) * u).normalized();
        const double az = -sx * 0.5 * fovX * kDeg, el = sy * 0.5 * fovY * kDeg;
        return std::cos(el) * (std::cos(az) * f - std::sin(az) * r) + std::sin(el) * u;
    }
    // The chart direction at azimuth az (degrees, positive to the left) and elevation el.
    static Vec3 direction(double azDeg, double elDeg) {
        const double az = azDeg * kDeg, el = elDeg * kDeg;
        return Vec3(-std::sin(az) * std::cos(el), std::sin(el), -std::cos(az) * std::cos(el));
    }
    std::string cameraJson() const {
        const Vec3 f = toChart * Vec3(0, 0, -1), u = toChart * Vec3(0, 1, 0);
        std::ostringstream s;
        s << R"("camera": {"projection": ")" << (panorama ? "panorama" : "pinhole") << R"(", "width": )" << width
          << R"(, "height": )" << height << R"(, "fov": [)" << fovX << ", " << fovY << R"(], "forward": [)" << f.x()
          << ", " << f.y() << ", " << f.z() << R"(], "up": [)" << u.x() << ", " << u.y() << ", " << u.z() << "]}";
        return s.str();
    }
};

// A ball of radius `radius` whose centre passes the event `centre` (t, x, y, z) at velocity beta.
struct Ball {
    Vec4 centre;
    double radius;
    Vec3 beta = Vec3::Zero();

    // Whether the past light ray of the observer at the origin event, seen along d, meets the
    // ball: the null direction k = (-1, d) and the offset O - C, Lorentz-transformed into the
    // ball's rest frame (where its centre rests at the origin), then a line against a sphere.
    bool seenAlong(const Vec3& d) const {
        Vec4 k(-1, d.x(), d.y(), d.z()), x = -centre;
        const double b2 = beta.squaredNorm();
        if (b2 > 0) {
            const double gamma = 1 / std::sqrt(1 - b2);
            const Vec3 n = beta / std::sqrt(b2);
            auto boost = [&](const Vec4& v) {
                const double par = n.dot(v.tail<3>());
                const double t = gamma * (v(0) - beta.dot(v.tail<3>()));
                const Vec3 s = v.tail<3>() + ((gamma - 1) * par - gamma * std::sqrt(b2) * v(0)) * n;
                return Vec4(t, s.x(), s.y(), s.z());
            };
            k = boost(k), x = boost(x);
        }
        const Vec3 o = x.tail<3>(), v = k.tail<3>();
        // |o + s v| = radius, s > 0.
        const double a = v.squaredNorm(), bb = o.dot(v), c = o.squaredNorm() - radius * radius;
        const double disc = bb * bb - a * c;
        return disc >= 0 && (-bb + std::sqrt(disc)) > 0;
    }
};

struct Centroid {
    double x = 0, y = 0;
    int pixels = 0;
};

// The oracle's centroid of each ball: the pixels whose documented ray meets it.
std::vector<Centroid> oracleCentroids(const DocumentedView& view, const std::vector<Ball>& balls) {
    std::vector<Centroid> out(balls.size());
    for (int j = 0; j < view.height; ++j)
        for (int i = 0; i < view.width; ++i) {
            const Vec3 d = view.pixelDirection(i, j);
            for (std::size_t b = 0; b < balls.size(); ++b)
                if (balls[b].seenAlong(d)) out[b].x += i + 0.5, out[b].y += j + 0.5, ++out[b].pixels;
        }
    for (Centroid& c : out) c.x /= std::max(c.pixels, 1), c.y /= std::max(c.pixels, 1);
    return out;
}

// A rendered image's centroid of each ball: its lit pixels (the background is black), each given
// to the ball whose oracle centroid is nearest.
std::vector<Centroid> imageCentroids(const std::vector<float>& rgb, int width, int height,
                                     const std::vector<Centroid>& oracle) {
    std::vector<Centroid> out(oracle.size());
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const std::size_t p = 3 * (static_cast<std::size_t>(j) * width + i);
            if (std::max({rgb[p], rgb[p + 1], rgb[p + 2]}) < 0.01f) continue;
            std::size_t best = 0;
            double bestD = 1e300;
            for (std::size_t b = 0; b < oracle.size(); ++b) {
                const double d = std::hypot(i + 0.5 - oracle[b].x, j + 0.5 - oracle[b].y);
                if (d < bestD) bestD = d, best = b;
            }
            out[best].x += i + 0.5, out[best].y += j + 0.5, ++out[best].pixels;
        }
    for (Centroid& c : out) c.x /= std::max(c.pixels, 1), c.y /= std::max(c.pixels, 1);
    return out;
}

// The scene: the metric, the observer at the origin event, the balls as black-body emitters.
std::string sceneJson(const std::string& metric, const DocumentedView& view, const std::vector<Ball>& balls,
                      const std::string& extra = "") {
    std::ostringstream s;
    s.precision(17);
    s << "{\"metric\": " << metric << ", \"observer\": {\"position\": [0, " << view.position.x() << ", "
      << view.position.y() << ", " << view.position.z() << "]}, " << view.cameraJson() << ", \"objects\": [";
    for (std::size_t b = 0; b < balls.size(); ++b) {
        Ball ball = balls[b];
        ball.centre.tail<3>() = view.position + view.toChart * ball.centre.tail<3>().eval();
        ball.beta = view.toChart * ball.beta;
        s << (b ? ", " : "") << "{\"type\": \"sphere\", \"name\": \"ball" << b << "\", \"centre\": [" << ball.centre(0)
          << ", " << ball.centre(1) << ", " << ball.centre(2) << ", " << ball.centre(3)
          << "], \"radius\": " << ball.radius << ", \"temperature\": 6000";
        if (ball.beta.squaredNorm() > 0)
            s << ", \"motion\": {\"type\": \"constant_velocity\", \"beta\": [" << ball.beta.x() << ", " << ball.beta.y()
              << ", " << ball.beta.z() << "]}";
        s << "}";
    }
    s << "], \"background\": [0, 0, 0]" << extra << "}";
    return s.str();
}

// Balls of angular radius ~3 degrees at distance 10 towards (azimuth, elevation) pairs; moving ones
// pass that point 10 time units before the observer's event, so their light reaches it now.
std::vector<Ball> ballsAt(const std::vector<std::pair<double, double>>& directions, const Vec3& beta) {
    std::vector<Ball> balls;
    for (const auto& [az, el] : directions) {
        const Vec3 p = 10 * DocumentedView::direction(az, el);
        balls.push_back({Vec4(beta.squaredNorm() > 0 ? -10.0 : 0.0, p.x(), p.y(), p.z()), 0.52, beta});
    }
    return balls;
}

// The pinhole of data/sr_cube.json at half size, or a panorama of 360 x 160 degrees.
DocumentedView viewFor(bool panorama) {
    DocumentedView view;
    if (panorama) view.panorama = true, view.width = 360, view.height = 160, view.fovX = 360, view.fovY = 160;
    return view;
}

// Pinhole: centre, 45 degrees right, up-right, and near the lower-left and upper-right corners.
const std::vector<std::pair<double, double>> kPinholeDirections{{0, 0}, {-45, 0}, {-30, 20}, {40, -24}, {-44, 27}};
// Panorama: ahead, to the left, behind on both sides of the seam, high up and low down.
const std::vector<std::pair<double, double>> kPanoramaDirections{{0, 0},     {90, 10},  {150, -20},
                                                                 {-160, 15}, {-60, 55}, {30, -50}};

// A renderer of the scene (read from its JSON text): an image, linear or display RGB (only > 0 matters).
struct Path {
    std::string name;
    std::function<std::vector<float>(const lc::Scene&, const std::string& json)> render;
};

Path cpu(const char* name, bool polygons = false) {
    return {name, [polygons](const lc::Scene& s, const std::string&) {
                return lc::renderColouredImage(s, {}, polygons).rgb;
            }};
}
// `lightcone render SCENE --data FILE.exr` run as a user runs it, its object pixels read back.
Path dataFile() {
    return {"render --data (object pixels)", [](const lc::Scene& s, const std::string& json) {
                const lc::test::ScratchFolder folder("cross-path");
                std::ofstream(folder / "scene.json") << json;
                const lc::test::CommandResult run =
                    lc::test::runCommand(lc::test::lightcone() + " render " + folder / "scene.json" + " -o " +
                                         folder / "image.png" + " --data " + folder / "data.exr" + " --quiet");
                EXPECT_EQ(run.exitCode, 0) << run.output;
                const lc::RenderResult data = lc::cli::readPixelData(folder / "data.exr", s);
                std::vector<float> mask(3 * data.pixels.size(), 0.0f);
                for (std::size_t p = 0; p < data.pixels.size(); ++p)
                    if (data.pixels[p].kind == lc::PixelRecord::Object) mask[3 * p] = 1.0f;
                return mask;
            }};
}
Path gpu(const char* name) {
    return {name, [](const lc::Scene& s, const std::string&) { return lc::cli::renderShaderImage(s); }};
}
Path gpuPolygons() {
    return {"GPU SR polygon distortion", [](const lc::Scene& s, const std::string&) {
                vtkNew<vtkLightconeSrImageRenderer> r;
                r->SetScene(s);
                r->SetModeToPolygonDistortion();
                return r->RenderColour();
            }};
}

void expectEveryBallWhereTheCameraPutsIt(const std::string& what, const std::string& metric, const DocumentedView& view,
                                         const std::vector<Ball>& balls, const std::vector<Path>& paths,
                                         const std::string& extra = "") {
    const std::string json = sceneJson(metric, view, balls, extra);
    lc::Scene scene = lc::io::parseScene(json, what, ".", lc::cli::sceneReadOptions());
    scene.settings.progress = false;
    const std::vector<Centroid> want = oracleCentroids(view, balls);
    for (const Path& path : paths) {
        if (path.name.rfind("GPU", 0) == 0 && !std::getenv("DISPLAY")) continue;
        SCOPED_TRACE(what + ", " + path.name);
        const std::vector<float> rgb = path.render(scene, json);
        ASSERT_EQ(rgb.size(), 3u * view.width * view.height);
        const std::vector<Centroid> got = imageCentroids(rgb, view.width, view.height, want);
        for (std::size_t b = 0; b < balls.size(); ++b) {
            const double off = std::hypot(got[b].x - want[b].x, got[b].y - want[b].y);
            std::printf("| %s | %s | ball %zu | (%.2f, %.2f) | (%.2f, %.2f) | %.3f |\n", what.c_str(),
                        path.name.c_str(), b, want[b].x, want[b].y, got[b].x, got[b].y, off);
            ASSERT_GT(want[b].pixels, 20) << "ball " << b << " is not in the oracle's view";
            EXPECT_GT(got[b].pixels, want[b].pixels / 2) << "ball " << b;
            EXPECT_LT(off, 0.5) << "ball " << b;
        }
    }
}

// Every special-relativity path: the GPU's polygon distortion draws pinholes only.
std::vector<Path> srPaths(bool panorama) {
    std::vector<Path> paths{cpu("CPU SR local ray tracing"), cpu("CPU SR polygon distortion", true), dataFile(),
                            gpu("GPU SR local ray tracing")};
    if (!panorama) paths.push_back(gpuPolygons());
    return paths;
}

TEST(CameraCrossPath, MinkowskiAtRestLandsWhereTheDocumentedCameraPutsIt) {
    for (const bool panorama : {false, true}) {
        DocumentedView view = viewFor(panorama);
        expectEveryBallWhereTheCameraPutsIt(
            panorama ? "minkowski at rest, panorama" : "minkowski at rest, pinhole", R"({"name": "minkowski"})", view,
            ballsAt(panorama ? kPanoramaDirections : kPinholeDirections, Vec3::Zero()), srPaths(panorama));
    }
}

TEST(CameraCrossPath, MinkowskiMovingAtHalfLightSpeedIsAberrated) {
    for (const bool panorama : {false, true}) {
        DocumentedView view = viewFor(panorama);
        const std::vector<Ball> balls = ballsAt(panorama ? kPanoramaDirections : kPinholeDirections, Vec3(0.5, 0, 0));
        expectEveryBallWhereTheCameraPutsIt(panorama ? "minkowski beta 0.5, panorama" : "minkowski beta 0.5, pinhole",
                                            R"({"name": "minkowski"})", view, balls, srPaths(panorama));
    }
}

TEST(CameraCrossPath, NearlyFlatSchwarzschildLandsWhereTheDocumentedCameraPutsIt) {
    for (const bool panorama : {false, true}) {
        DocumentedView view = viewFor(panorama);
        view.position = Vec3(0, 1000, 0);  // the hole (M = 1e-6) 1000 units below: no ray passes near it
        expectEveryBallWhereTheCameraPutsIt(
            panorama ? "schwarzschild M = 1e-6, panorama" : "schwarzschild M = 1e-6, pinhole",
            R"({"name": "schwarzschild", "M": 1e-6})", view,
            ballsAt(panorama ? kPanoramaDirections : kPinholeDirections, Vec3::Zero()),
            {cpu("CPU numeric"), dataFile()},  // the GPU tracer draws no spheres
            R"(, "sky": {"type": "solid", "color": [0, 0, 0]})");
    }
}

// Light in the Goedel universe turns at first order in r / a (0.9 px at a = 1000 here): a = 1e5.
TEST(CameraCrossPath, GoedelAtDistancesFarBelowItsScaleLandsWhereTheDocumentedCameraPutsIt) {
    for (const bool panorama : {false, true}) {
        DocumentedView view = viewFor(panorama);
        view.toChart << 1, 0, 0, 0, 0, -1, 0, 1, 0;  // forward -z -> +y, up +y -> +z (the Goedel axis)
        expectEveryBallWhereTheCameraPutsIt(
            panorama ? "goedel a = 1e5, panorama" : "goedel a = 1e5, pinhole", R"({"name": "godel", "a": 100000})",
            view, ballsAt(panorama ? kPanoramaDirections : kPinholeDirections, Vec3::Zero()),
            {cpu("CPU closed form"), dataFile(), gpu("GPU Goedel photo-objects")}, R"(, "render": {"windings": 0})");
    }
}

}  // namespace
