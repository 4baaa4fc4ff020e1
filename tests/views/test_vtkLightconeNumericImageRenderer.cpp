// SPDX-License-Identifier: BSD-3-Clause
// The GPU Hamiltonian ray tracer (vtkLightconeNumericImageRenderer: single-precision
// Dormand-Prince in a fragment shader, the metric and its derivatives generated as GLSL from the
// metric's C++ code) against
// references computed independently on the CPU: lc::renderNumeric + lc::shadePixels (double
// precision, odeint dopri5, Eigen autodiff), the flat-space sky mapping, and Synge's exact
// shadow radius. Runs under Xvfb (Mesa llvmpipe is enough).
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "core/render/render.hpp"
#include "readers/io/metric_file.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeNumericImageRenderer.h"

#include "dump_image.hpp"

#include "tests/common/test_camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace {

using Renderer = vtkLightconeNumericImageRenderer;

lc::Scene jsonScene(const std::string& name, int width, int height) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/" + name);
    scene.camera.width = width;
    scene.camera.height = height;
    scene.settings.progress = false;
    scene.settings.threads = 2;
    return scene;
}

lc::Scene codedScene(lc::SpacetimePtr st, const lc::Vec4& observer, const lc::Camera& cam) {
    lc::Scene scene;
    scene.spacetime = std::move(st);
    scene.observer = observer;
    scene.camera = cam;
    scene.sky = std::make_shared<lc::CheckerTexture>(36, 18, lc::Vec3(0.9, 0.9, 0.85), lc::Vec3(0.1, 0.15, 0.3));
    scene.settings.progress = false;
    scene.settings.threads = 2;
    return scene;
}

using lc::test::dump;

lc::Camera pinholeCamera(int width, int height, double fovXDeg, double fovYDeg, const lc::Vec3& forward,
                         const lc::Vec3& up) {
    return lc::test::testCamera(lc::Camera::Projection::Pinhole, width, height, fovXDeg, fovYDeg, forward, up);
}

struct Extent {
    int left = 1 << 30, right = -1, top = 1 << 30, bottom = -1;
    int width() const { return right - left + 1; }
    int height() const { return bottom - top + 1; }
};
Extent extentOf(const std::vector<bool>& mask, int w, int h) {
    Extent e;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            if (mask[static_cast<std::size_t>(j) * w + i]) {
                e.left = std::min(e.left, i);
                e.right = std::max(e.right, i);
                e.top = std::min(e.top, j);
                e.bottom = std::max(e.bottom, j);
            }
    return e;
}

// True if a pixel within Chebyshev distance d of (i, j) has a different value in mask.
bool nearEdge(const std::vector<bool>& mask, int w, int h, int i, int j, int d) {
    const bool c = mask[static_cast<std::size_t>(j) * w + i];
    for (int dj = -d; dj <= d; ++dj)
        for (int di = -d; di <= d; ++di) {
            const int ni = i + di, nj = j + dj;
            if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
            if (mask[static_cast<std::size_t>(nj) * w + ni] != c) return true;
        }
    return false;
}

lc::Vec3 skyColour(const lc::Scene& scene, const lc::Vec3& d) {
    const double u = 0.5 + std::atan2(d(1), d(0)) / (2 * lc::kPi);
    const double v = std::acos(std::clamp(d(2), -1.0, 1.0)) / lc::kPi;
    return scene.sky->sample(u, v);
}

// A metric that is not written as code (no CodedMetric, so no expression to generate GLSL from).
class OpaqueMetric final : public lc::Spacetime {
public:
    std::string name() const override { return "opaque"; }
    std::map<std::string, double> parameters() const override { return {}; }
    std::array<std::string, 4> coordinateNames() const override { return {"t", "x", "y", "z"}; }
    lc::Mat4 metric(const lc::Vec4&) const override { return lc::Vec4(1, -1, -1, -1).asDiagonal(); }
    void metricAndDerivatives(const lc::Vec4& x, lc::Mat4& g, std::array<lc::Mat4, 4>& dg) const override {
        g = metric(x);
        for (auto& d : dg) d.setZero();
    }
};

TEST(GeodesicShader, RejectsMetricsNotWrittenAsCode) {
    lc::Camera cam;
    cam.width = 16;
    cam.height = 8;
    vtkNew<Renderer> r;
    try {
        r->SetScene(codedScene(std::make_shared<OpaqueMetric>(), lc::Vec4(0, -5, 0, 0), cam));
        FAIL() << "accepted a metric without code";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("metric 'opaque'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(r->Build(), std::logic_error);  // no scene accepted yet
    // Every coded metric is accepted; VTK conventions (clamped setters, PrintSelf).
    r->SetScene(codedScene(std::make_shared<lc::KerrNewman>(1.0, 0.5, 0.3), lc::Vec4(0, 20, 0, 0), cam));
    r->SetTolerance(10.0);
    EXPECT_DOUBLE_EQ(r->GetTolerance(), 1e-1);
    std::ostringstream os;
    r->PrintSelf(os, vtkIndent());
    EXPECT_NE(os.str().find("kerr-newman"), std::string::npos);
    EXPECT_NE(os.str().find("(generated)"), std::string::npos);
}

// Flat space: every ray escapes along its initial direction, so the image is the sky mapped
// through lc::Camera::direction and toSkyUv with no distortion. The sky is baked with texel
// edges on the checker's cell edges (2016 x 1008 texels for 36 x 18 cells), so the nearest
// texel is the exact checker colour and the images agree pixel for pixel except where a
// single-precision direction and its double twin straddle a cell edge.
TEST(GeodesicShader, MinkowskiIsTheUndistortedSky) {
    for (const auto projection : {lc::Camera::Projection::Pinhole, lc::Camera::Projection::Panorama}) {
        lc::Camera cam;
        cam.projection = projection;
        cam.width = 160;
        cam.height = 80;
        cam.fovXDeg = projection == lc::Camera::Projection::Pinhole ? 100 : 300;
        cam.fovYDeg = projection == lc::Camera::Projection::Pinhole ? 60 : 150;
        cam.forward = lc::Vec3(1, 0.4, 0.3);
        cam.up = lc::Vec3(0, 0.1, 1);
        const lc::Scene scene = codedScene(std::make_shared<lc::Minkowski>(), lc::Vec4(0, 0.5, -1, 2), cam);
        vtkNew<Renderer> r;
        r->SetScene(scene);
        r->SetTextureSize(1008);
        const std::vector<int> ids = r->RenderIds();
        const std::vector<float> dirs = r->RenderEscapeDirections();
        const std::vector<float> rgb = r->RenderColour();
        dump(projection == lc::Camera::Projection::Pinhole ? "geo_minkowski_pinhole" : "geo_minkowski_panorama", rgb,
             cam.width, cam.height);
        double worstDir = 0;
        std::size_t colourMismatch = 0, notSky = 0;
        for (int j = 0; j < cam.height; ++j)
            for (int i = 0; i < cam.width; ++i) {
                const std::size_t k = static_cast<std::size_t>(j) * cam.width + i;
                notSky += ids[k] != Renderer::Sky;
                const lc::Vec3 n = cam.direction(i, j);
                for (int c = 0; c < 3; ++c) {
                    const double e = std::abs(dirs[3 * k + c] - n(c));
                    if (e > worstDir && e > 0.01)
                        std::printf("pixel (%d, %d): direction (%.3f %.3f %.3f) vs (%.3f %.3f %.3f)\n", i, j,
                                    dirs[3 * k], dirs[3 * k + 1], dirs[3 * k + 2], n(0), n(1), n(2));
                    worstDir = std::max(worstDir, e);
                }
                const lc::Vec3 expect = skyColour(scene, n);
                bool same = true;
                for (int c = 0; c < 3; ++c) same = same && std::abs(rgb[3 * k + c] - expect(c)) <= 1.0 / 255;
                colourMismatch += !same;
            }
        EXPECT_EQ(notSky, 0u);
        // 8-bit read-back of (d + 1) / 2: half a quantum is 1/255 per component.
        EXPECT_LE(worstDir, 1.0 / 255 + 1e-4);
        EXPECT_LE(colourMismatch, 3u) << "pixels whose colour is not the flat-space sky's";
    }
}

// One scene on both sides: lc::renderNumeric + lc::shadePixels (the reference) and the shader
// tracer's classes and colours; both images dumped as geo_<name>_cpu and geo_<name>_gpu.
struct CpuAndGpuImages {
    lc::RenderResult cpu;
    std::vector<float> cpuRgb;
    std::vector<int> ids;
    std::vector<float> rgb;
};

CpuAndGpuImages renderOnCpuAndGpu(const lc::Scene& scene, const std::string& name) {
    CpuAndGpuImages im;
    im.cpu = lc::renderNumeric(scene);
    im.cpuRgb = lc::shadePixels(scene, im.cpu);
    vtkNew<Renderer> r;
    r->SetScene(scene);
    im.ids = r->RenderIds();
    im.rgb = r->RenderColour();
    dump("geo_" + name + "_gpu", im.rgb, scene.camera.width, scene.camera.height);
    dump("geo_" + name + "_cpu", im.cpuRgb, scene.camera.width, scene.camera.height);
    return im;
}

// The GPU image against lc::renderNumeric + lc::shadePixels on the same scene.
void compareWithCpu(const lc::Scene& scene, const std::string& name) {
    SCOPED_TRACE(name);
    const int w = scene.camera.width, h = scene.camera.height;
    const CpuAndGpuImages im = renderOnCpuAndGpu(scene, name);
    const lc::RenderResult& cpu = im.cpu;
    const std::vector<float>& cpuRgb = im.cpuRgb;
    const std::vector<int>& ids = im.ids;
    const std::vector<float>& rgb = im.rgb;

    const std::size_t n = ids.size();
    std::vector<bool> cpuShadow(n), gpuShadow(n);
    std::size_t cpuCount = 0, gpuFailed = 0, cpuFailed = 0;
    for (std::size_t k = 0; k < n; ++k) {
        cpuShadow[k] = cpu.pixels[k].kind == lc::PixelRecord::Horizon;
        gpuShadow[k] = ids[k] == Renderer::Horizon;
        cpuCount += cpuShadow[k];
        gpuFailed += ids[k] == Renderer::Failed;

        cpuFailed += cpu.pixels[k].kind != lc::PixelRecord::Horizon && cpu.pixels[k].kind != lc::PixelRecord::Sky;
    }
    ASSERT_EQ(cpuFailed, 0u);
    ASSERT_GT(cpuCount, 500u);  // the shadow is ~40 x 20 px at this size
    // A GPU ray may fail (null-condition drift in single precision) only on the photon ring,
    // i.e. on the CPU shadow's edge, and rarely.
    std::size_t failedOffEdge = 0;
    for (std::size_t k = 0; k < n; ++k)
        if (ids[k] == Renderer::Failed)
            failedOffEdge += !nearEdge(cpuShadow, w, h, static_cast<int>(k % w), static_cast<int>(k / w), 1);
    EXPECT_EQ(failedOffEdge, 0u);
    EXPECT_LE(gpuFailed, cpuCount / 200) << "failed rays";

    // Classification: a pixel may differ only on the shadow's edge (a CPU pixel with a
    // neighbour of the other class), where rays graze the photon region and the exponential
    // sensitivity there turns single- vs double-precision round-off into a flip. The edge is
    // ~120 px long; allowing 2% of the shadow (~30 px) means at most a quarter of it flips.
    std::size_t differing = 0, offEdge = 0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * w + i;
            if (cpuShadow[k] == gpuShadow[k]) continue;
            ++differing;
            offEdge += !nearEdge(cpuShadow, w, h, i, j, 1);
        }
    const double fraction = static_cast<double>(differing) / cpuCount;
    std::printf("%s %dx%d: shadow %zu px (CPU), %zu differ (%.2f%%), %zu off the edge\n", name.c_str(), w, h, cpuCount,
                differing, 100 * fraction, offEdge);
    EXPECT_EQ(offEdge, 0u);
    EXPECT_LT(fraction, 0.02);

    const Extent ce = extentOf(cpuShadow, w, h), ge = extentOf(gpuShadow, w, h);
    std::printf("shadow extent: CPU x [%d, %d] y [%d, %d]; GPU x [%d, %d] y [%d, %d]\n", ce.left, ce.right, ce.top,
                ce.bottom, ge.left, ge.right, ge.top, ge.bottom);
    EXPECT_LE(std::abs(ce.left - ge.left), 1);
    EXPECT_LE(std::abs(ce.right - ge.right), 1);
    EXPECT_LE(std::abs(ce.width() - ge.width()), 1);
    EXPECT_LE(std::abs(ce.height() - ge.height()), 1);

    // Sky colours away from the photon ring (no shadow pixel within 4 px in either image):
    // the lensed checker agrees except on cell edges that pass through a pixel.
    double sum = 0;
    std::size_t count = 0, flipped = 0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * w + i;
            if (cpuShadow[k] || gpuShadow[k]) continue;
            bool ring = false;
            for (int dj = -4; dj <= 4 && !ring; ++dj)
                for (int di = -4; di <= 4 && !ring; ++di) {
                    const int ni = i + di, nj = j + dj;
                    if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
                    const std::size_t q = static_cast<std::size_t>(nj) * w + ni;
                    ring = cpuShadow[q] || gpuShadow[q];
                }
            if (ring) continue;
            double d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d, static_cast<double>(std::abs(rgb[3 * k + c] - cpuRgb[3 * k + c])));
            sum += d;
            flipped += d > 0.05;
            ++count;
        }
    const double mean = sum / count;
    const double flippedFraction = static_cast<double>(flipped) / count;
    std::printf("sky away from the ring: %zu px, mean |diff| %.4f, %.2f%% differ by > 0.05\n", count, mean,
                100 * flippedFraction);
    EXPECT_GT(count, static_cast<std::size_t>(w * h / 2));
    EXPECT_LT(mean, 0.01);
    EXPECT_LT(flippedFraction, 0.01);
}

// Kerr a = 0.9 edge-on from r = 30 M (data/kerr.json).
TEST(GeodesicShader, KerrMatchesCpuRenderer) { compareWithCpu(jsonScene("kerr.json", 160, 80), "kerr"); }

// The same scene with Kerr typed as text (data/metrics/kerr.json): the GLSL is generated at run
// time from the parsed formula, and the GPU image agrees with the CPU's as for the built-in.
TEST(GeodesicShader, FormulaKerrMatchesCpuRenderer) {
    const lc::Scene scene = jsonScene("kerr_formula.json", 160, 80);
    ASSERT_EQ(scene.spacetime->name(), "kerr-formula");
    compareWithCpu(scene, "kerr_formula");
}

// Kerr-Newman a = 0.6 M, Q = 0.5 M, seen from above the equator (observer off every symmetry
// axis of the chart, camera tilted), so that every metric term and derivative is exercised.
TEST(GeodesicShader, KerrNewmanMatchesCpuRenderer) {
    const lc::Vec4 observer(0, 18, 12, 10);
    const lc::Camera cam =
        pinholeCamera(120, 80, 60, 40, -observer.tail<3>() + lc::Vec3(0, 1.5, 0), lc::Vec3(0.1, 0, 1));
    compareWithCpu(codedScene(std::make_shared<lc::KerrNewman>(1.0, 0.6, 0.5), observer, cam), "kerr_newman");
}

// Schwarzschild, static observer at r = 30 M: the shadow's angular radius is exactly
// sin(alpha) = 3 sqrt(3) M sqrt(1 - 2M/r) / r (Synge 1966). Every pixel whose direction is more
// than one pixel inside the cone is horizon, every pixel more than one pixel outside is sky.
TEST(GeodesicShader, SchwarzschildShadowRadiusIsSynges) {
    const lc::Camera cam = pinholeCamera(160, 160, 24, 24, lc::Vec3(-1, 0, 0), lc::Vec3(0, 0, 1));
    const double M = 1, R = 30;
    const lc::Scene scene = codedScene(std::make_shared<lc::Schwarzschild>(M), lc::Vec4(0, R, 0, 0), cam);
    vtkNew<Renderer> r;
    r->SetScene(scene);
    const std::vector<int> ids = r->RenderIds();
    dump("geo_schwarzschild", r->RenderColour(), cam.width, cam.height);

    const double alpha = std::asin(3 * std::sqrt(3.0) * M * std::sqrt(1 - 2 * M / R) / R);
    const double pixel = cam.fovXDeg / cam.width * lc::kPi / 180;  // at the centre (largest)
    double maxShadow = 0, minSky = lc::kPi;
    std::size_t inside = 0, outside = 0, wrongInside = 0, wrongOutside = 0, failed = 0;
    for (int j = 0; j < cam.height; ++j)
        for (int i = 0; i < cam.width; ++i) {
            const int id = ids[static_cast<std::size_t>(j) * cam.width + i];
            const double theta = std::acos(std::clamp(cam.direction(i, j).dot(cam.forward.normalized()), -1.0, 1.0));
            failed += id == Renderer::Failed;
            if (id == Renderer::Horizon) maxShadow = std::max(maxShadow, theta);
            if (id == Renderer::Sky) minSky = std::min(minSky, theta);
            if (theta < alpha - pixel) {
                ++inside;
                wrongInside += id != Renderer::Horizon;
            } else if (theta > alpha + pixel) {
                ++outside;
                wrongOutside += id != Renderer::Sky;
            }
        }
    std::printf(
        "Synge alpha = %.4f deg; GPU: last shadow pixel at %.4f deg, first sky pixel at %.4f deg (pixel %.3f deg)\n",
        alpha * 180 / lc::kPi, maxShadow * 180 / lc::kPi, minSky * 180 / lc::kPi, pixel * 180 / lc::kPi);
    EXPECT_EQ(failed, 0u);
    EXPECT_GT(inside, 1000u);
    EXPECT_EQ(wrongInside, 0u);
    EXPECT_EQ(wrongOutside, 0u);
    EXPECT_NEAR(maxShadow, alpha, pixel);
    EXPECT_NEAR(minSky, alpha, pixel);
}

// Alcubierre (v = 1.5, R = 1, sigma = 8): a static observer 4 R ahead of the superluminal
// bubble's path looks back at it: no horizon, so the image is the sky lensed by the walls. The GLSL
// of this metric (tanh walls) is generated, none written by hand. Against the CPU numeric image:
// the classes agree everywhere (all sky), colours differ only where a cell edge of the checker
// passes between the single- and the double-precision escape direction.
void expectAlcubierreMatchesCpu(lc::SpacetimePtr bubble, const std::string& name) {
    SCOPED_TRACE(name);
    const lc::Camera cam = pinholeCamera(120, 60, 120, 60, lc::Vec3(-1, 0.2, 0.1), lc::Vec3(0, 0, 1));
    lc::Scene scene = codedScene(std::move(bubble), lc::Vec4(0, 4, 0, 0), cam);
    scene.settings.trace.absTol = scene.settings.trace.relTol = 1e-9;
    const CpuAndGpuImages im = renderOnCpuAndGpu(scene, name);
    const lc::RenderResult& cpu = im.cpu;
    const std::vector<float>& cpuRgb = im.cpuRgb;
    const std::vector<int>& ids = im.ids;
    const std::vector<float>& rgb = im.rgb;
    std::size_t notSky = 0, cpuNotSky = 0, differ = 0;
    double sum = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        notSky += ids[k] != Renderer::Sky;
        cpuNotSky += cpu.pixels[k].kind != lc::PixelRecord::Sky;
        double d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, static_cast<double>(std::abs(rgb[3 * k + c] - cpuRgb[3 * k + c])));
        sum += d;
        differ += d > 0.05;
    }
    std::printf("alcubierre %dx%d: mean |diff| %.4f, %zu of %zu px differ by > 0.05\n", cam.width, cam.height,
                sum / ids.size(), differ, ids.size());
    EXPECT_EQ(cpuNotSky, 0u);
    EXPECT_EQ(notSky, 0u);
    EXPECT_LT(sum / ids.size(), 0.01);
    EXPECT_LT(differ, ids.size() / 50);
}

TEST(GeodesicShader, AlcubierreMatchesCpuRenderer) {
    expectAlcubierreMatchesCpu(std::make_shared<lc::Alcubierre>(1.5, 1.0, 8.0), "alcubierre");
}

// The same with Alcubierre typed as text (data/metrics/alcubierre.json): GLSL generated at run time.
TEST(GeodesicShader, FormulaAlcubierreMatchesCpuRenderer) {
    expectAlcubierreMatchesCpu(
        lc::io::loadFormulaMetric(std::string(LIGHTCONE_SOURCE_DIR) + "/data/metrics/alcubierre.json",
                                  {{"v", 1.5}, {"R", 1.0}, {"sigma", 8.0}}),
        "alcubierre_formula");
}

// Schwarzschild typed in spherical coordinates (t, r, theta, phi), pulled back to the tracer's
// Cartesian chart, seen from the polar axis looking down it: the GPU's image against the CPU's,
// as for the built-in, with no seam where the rays cross the axis.
TEST(GeodesicShader, SphericalChartFormulaMatchesCpuRenderer) {
    const lc::Camera cam = pinholeCamera(120, 80, 60, 40, lc::Vec3(0, 0, -1), lc::Vec3(1, 0, 0));
    compareWithCpu(codedScene(lc::io::loadFormulaMetric(
                                  std::string(LIGHTCONE_SOURCE_DIR) + "/data/metrics/schwarzschild_spherical.json", {}),
                              lc::Vec4(0, 0, 0, 20), cam),
                   "schwarzschild_spherical");
}

// Goedel (axis-regular Cartesian chart, a = 1) from the axis: not asymptotically flat, so no
// ray escapes; every ray is traced to the affine limit and ends as background, as on the CPU.
// In single precision the generated metric keeps every ray null (no failed pixel), also rays
// that pass the axis again and that approach the horizon r = 2a.
void expectGodelTracedToTheAffineLimit(lc::SpacetimePtr godel, const std::string& name) {
    SCOPED_TRACE(name);
    lc::Camera cam;
    cam.width = 48;
    cam.height = 24;
    cam.projection = lc::Camera::Projection::Panorama;
    cam.fovXDeg = 360;
    cam.fovYDeg = 150;
    lc::Scene scene = codedScene(std::move(godel), lc::Vec4(0, 0, 0, 0), cam);
    scene.settings.trace.maxAffine = 12;
    scene.background = lc::Vec3(0.2, 0.4, 0.6);
    const CpuAndGpuImages im = renderOnCpuAndGpu(scene, name);
    const lc::RenderResult& cpu = im.cpu;
    const std::vector<int>& ids = im.ids;
    const std::vector<float>& rgb = im.rgb;
    std::size_t cpuBackground = 0, gpuBackground = 0, colourOff = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        cpuBackground += cpu.pixels[k].kind == lc::PixelRecord::Background;
        gpuBackground += ids[k] == Renderer::Background;
        for (int c = 0; c < 3; ++c) colourOff += std::abs(rgb[3 * k + c] - scene.background(c)) > 1.0 / 255;
    }
    EXPECT_EQ(cpuBackground, ids.size());
    EXPECT_EQ(gpuBackground, ids.size());
    EXPECT_EQ(colourOff, 0u);
}

TEST(GeodesicShader, GodelNumericChartTracesToTheAffineLimitLikeTheCpu) {
    expectGodelTracedToTheAffineLimit(std::make_shared<lc::GodelCartesian>(1.0), "godel_numeric");
}

// Goedel typed as components in the signature (+,-,-,-) (data/metrics/godel.json).
TEST(GeodesicShader, FormulaGodelTracesToTheAffineLimitLikeTheCpu) {
    expectGodelTracedToTheAffineLimit(
        lc::io::loadFormulaMetric(std::string(LIGHTCONE_SOURCE_DIR) + "/data/metrics/godel.json", {{"a", 1.0}}),
        "godel_formula");
}

}  // namespace

namespace {

// An accretion disk: the GPU's disk crossings, table of orbits, generated radius (lcDiskRadius)
// and Planck colours against lc::renderNumeric + lc::shadePixels. Pixels may differ in class only
// where the CPU's class changes within a pixel (the disk's edges and the secondary image's thin
// ring); the colours elsewhere agree to 8-bit rounding and the float redshift.
void expectDiskMatchesCpu(const std::string& file, const std::string& label) {
    const lc::Scene scene = jsonScene(file, 160, 90);
    const int w = scene.camera.width, h = scene.camera.height;
    const CpuAndGpuImages im = renderOnCpuAndGpu(scene, label);
    std::vector<bool> cpuDisk(im.ids.size());
    std::size_t disk = 0;
    for (std::size_t k = 0; k < im.ids.size(); ++k) disk += cpuDisk[k] = im.cpu.pixels[k].kind == lc::PixelRecord::Disk;
    ASSERT_GT(disk, 3000u);
    std::size_t classOffEdge = 0, compared = 0, colourOff = 0;
    double worst = 0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * w + i;
            const bool edge = nearEdge(cpuDisk, w, h, i, j, 1);
            if (cpuDisk[k] != (im.ids[k] == Renderer::Disk)) {
                classOffEdge += !edge;
                continue;
            }
            if (!cpuDisk[k] || edge) continue;
            ++compared;
            double d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d,
                             static_cast<double>(std::abs(im.rgb[3 * k + c] - std::min(im.cpuRgb[3 * k + c], 1.0f))));
            worst = std::max(worst, d);
            colourOff += d > 2.5 / 255;
        }
    std::printf("%s: %zu disk pixels (CPU), %zu compared, worst colour difference %.4f, %zu beyond 2.5/255\n",
                label.c_str(), disk, compared, worst, colourOff);
    EXPECT_EQ(classOffEdge, 0u);
    EXPECT_LE(colourOff, compared / 100);
}

}  // namespace

// data/kerr_disk.json: a = 0.9, i = 75 degrees, black body.
TEST(GeodesicShader, AccretionDiskMatchesCpuRenderer) { expectDiskMatchesCpu("kerr_disk.json", "kerr_disk"); }

// The same disk around the Kerr metric typed as text (data/kerr_disk_formula.json): its orbits
// come from the formula's g, the GPU's disk radius is generated from the file's "radius".
TEST(GeodesicShader, AccretionDiskAroundFormulaKerrMatchesCpuRenderer) {
    expectDiskMatchesCpu("kerr_disk_formula.json", "kerr_disk_formula");
}
