// SPDX-License-Identifier: BSD-3-Clause
// Special relativity on the GPU (vtkLightconeSrImageRenderer, seed 003: local ray tracing
// and polygon distortion) against the CPU reference lc::sr::SrRenderer, which evaluates the same
// physics in double precision per pixel (the shaders run GLSL generated from the same C++ templates,
// in float, inside VTK's pipeline: footprints, rasterisation, depth test, 8-bit read-back). Runs
// under Xvfb (Mesa llvmpipe is enough).
#include "core/colour/blackbody.hpp"
#include "core/render/special_relativity.hpp"
#include "core/sr/doppler.hpp"
#include "core/sr/mesh.hpp"
#include "core/sr/photo_object.hpp"
#include "core/sr/renderer.hpp"
#include "readers/io/scene_reader.hpp"
#include "vtkLightconeSrImageRenderer.h"

#include "dump_image.hpp"

#include "tests/common/sr_camera.hpp"

#include <gtest/gtest.h>

#include <vtkNew.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

namespace {

using lc::test::srCamera;

using lc::Vec3;

using lc::test::dump;

// Seed 003 Fig. 10 / data/sr_cube.json: a cube of edge 4 passing at 0.95 c; at t = 0 its
// centre is at (9.5, 0, -10), the light seen at t = 0 left it at x ~ 0.
lc::sr::SrScene cubeScene(int n, double beta = 0.95) {
    lc::sr::SrScene s;
    s.objects.push_back({lc::sr::makeCube(4.0, n), lc::sr::MovingFrame(Vec3(beta, 0, 0), Vec3(9.5, 0, -10)), {}});
    s.lightPosition = Vec3(0, 10, 10);
    return s;
}

struct Comparison {
    std::size_t objectPixels = 0;       // object in either image
    std::size_t differing = 0;          // object id differs
    std::size_t offSilhouette = 0;      // differing pixels not next to a CPU silhouette
    std::size_t both = 0;               // object in both
    std::size_t triangleDiffering = 0;  // same object, another triangle
    double meanColour = 0;              // mean |rgb difference| over channels of `both` pixels
    double maxColour = 0;
    double fraction() const { return objectPixels ? double(differing) / objectPixels : 0.0; }
};

Comparison compare(const lc::sr::SrImage& cpu, const vtkLightconeSrImageRenderer::Ids& ids,
                   const std::vector<float>& rgb) {
    Comparison c;
    const int w = cpu.width, h = cpu.height;
    double sum = 0;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * w + i;
            const int ref = cpu.object[k], gpu = ids.object[k];
            if (ref < 0 && gpu < 0) continue;
            ++c.objectPixels;
            if (ref != gpu) {
                ++c.differing;
                bool silhouette = false;
                for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                    const int ni = i + di, nj = j + dj;
                    if (ni >= 0 && ni < w && nj >= 0 && nj < h &&
                        cpu.object[static_cast<std::size_t>(nj) * w + ni] != ref)
                        silhouette = true;
                }
                c.offSilhouette += !silhouette;
                continue;
            }
            ++c.both;
            c.triangleDiffering += cpu.triangle[k] != ids.triangle[k];
            for (int q = 0; q < 3; ++q) {
                const double d = std::abs(double(rgb[3 * k + q]) - cpu.rgb[3 * k + q]);
                sum += d;
                c.maxColour = std::max(c.maxColour, d);
            }
        }
    c.meanColour = c.both ? sum / (3.0 * c.both) : 0.0;
    return c;
}

// One scene drawn both ways with the same camera and options: the CPU SrRenderer, then `gpu`.
struct SrImages {
    lc::sr::SrImage cpu;
    std::vector<float> rgb;
    vtkLightconeSrImageRenderer::Ids ids;
    Comparison comparison() const { return compare(cpu, ids, rgb); }
};

SrImages renderBoth(vtkLightconeSrImageRenderer* gpu, const lc::sr::SrScene& scene, const lc::sr::ObserverCamera& cam,
                    const lc::sr::SrRenderOptions& opt) {
    SrImages im;
    im.cpu = lc::sr::SrRenderer().render(scene, cam, opt);
    gpu->SetScene(scene, cam);
    gpu->SetOptions(opt);
    im.rgb = gpu->RenderColour();
    im.ids = gpu->RenderIds();
    return im;
}

// Both renderers decide coverage by the same exact test on the same rays (pixel centres); the
// GPU does it in float, so only pixels whose centre lies within float rounding (~1e-5 px) of
// the apparent outline may flip: the threshold is 0.2 % of the object pixels, and every
// differing pixel must lie on a silhouette of the CPU image. Colours: the GPU writes 8-bit
// values (rounding error <= 0.5/255) of the same Planck table sampled by a float texture with
// linear filtering, and float Phong: mean difference < 1/255, max < 4/255.
void expectMatchesCpu(const Comparison& c) {
    EXPECT_GT(c.objectPixels, 2000u);  // the object is well in view
    EXPECT_LT(c.fraction(), 0.002);
    EXPECT_EQ(c.offSilhouette, 0u);
    EXPECT_LT(c.meanColour, 1.0 / 255);
    EXPECT_LT(c.maxColour, 4.0 / 255);
}

// Coverage difference between two id images.
double coverageDifference(const std::vector<int>& a, const std::vector<int>& b, std::size_t* differing = nullptr) {
    std::size_t obj = 0, diff = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (a[k] < 0 && b[k] < 0) continue;
        ++obj;
        diff += (a[k] < 0) != (b[k] < 0);
    }
    if (differing) *differing = diff;
    return obj ? double(diff) / obj : 0.0;
}

}  // namespace

// Local ray tracing of seed 003's cube (200 triangles per face) at beta = 0.95: the GPU image
// against the CPU SrRenderer (expectMatchesCpu), with both tone maps.
TEST(SrGpuRender, CubeLocalRayTracingMatchesCpu) {
    const int W = 320, H = 180;
    const lc::sr::SrScene scene = cubeScene(10);
    const lc::sr::ObserverCamera cam = srCamera(W, H);
    for (int toneMap : {0, 1}) {
        lc::sr::SrRenderOptions opt;
        opt.toneMap = toneMap == 0 ? lc::colour::ToneMap::ColourOnly : lc::colour::ToneMap::ReferenceLog;
        vtkNew<vtkLightconeSrImageRenderer> gpu;
        const SrImages im = renderBoth(gpu, scene, cam, opt);
        dump("sr_cube_gpu_" + std::to_string(toneMap), im.rgb, W, H);
        dump("sr_cube_cpu_" + std::to_string(toneMap), im.cpu.rgb, W, H);

        const Comparison c = im.comparison();
        std::printf(
            "tone map %d: object pixels %zu, coverage differing %zu (%.4f %%, off silhouette %zu), "
            "triangle ids differing %zu, colour mean %.3f/255 max %.1f/255, %zu quads (%zu full screen), "
            "mean quad %.1f px\n",
            toneMap, c.objectPixels, c.differing, 100 * c.fraction(), c.offSilhouette, c.triangleDiffering,
            255 * c.meanColour, 255 * c.maxColour, gpu->GetNumberOfQuads(), gpu->GetNumberOfFullScreenQuads(),
            gpu->GetMeanQuadPixels());
        expectMatchesCpu(c);
        // Interior edges: a pixel centre within float rounding of an edge may go to either
        // neighbour (same colour up to interpolation); at most 0.5 % of the pixels.
        EXPECT_LT(double(c.triangleDiffering), 0.005 * c.both);
    }
}

// The same scene read from data/sr_cube.json through the lc::Scene conversion, against
// lc::renderSrImage (coverage only, 320 x 180).
TEST(SrGpuRender, SceneFileConversionMatchesCpu) {
    lc::Scene scene = lc::io::readScene(std::string(LIGHTCONE_SOURCE_DIR) + "/data/sr_cube.json");
    scene.camera.width = 320;
    scene.camera.height = 180;
    scene.settings.progress = false;
    const lc::ColouredImage cpu = lc::renderSrImage(scene);
    vtkNew<vtkLightconeSrImageRenderer> gpu;
    gpu->SetScene(scene);
    const auto ids = gpu->RenderIds();
    std::vector<int> ref(ids.object.size());
    for (std::size_t k = 0; k < ref.size(); ++k)
        ref[k] = cpu.records.pixels[k].kind == lc::PixelRecord::Object ? cpu.records.pixels[k].object : -1;
    std::size_t diff = 0;
    const double f = coverageDifference(ids.object, ref, &diff);
    std::printf("sr_cube.json: coverage differing %zu pixels (%.4f %%)\n", diff, 100 * f);
    EXPECT_GT(std::count(ref.begin(), ref.end(), 0), 2000);
    EXPECT_LT(f, 0.002);
}

// Polygon distortion on the GPU against the CPU's PolygonDistortion mode (same flat
// apparent triangles): rasterisation and the CPU's flat-triangle test both sample pixel
// centres, so again only silhouette pixels may flip (expectMatchesCpu).
TEST(SrGpuRender, CubePolygonDistortionMatchesCpu) {
    const int W = 320, H = 180;
    const lc::sr::SrScene scene = cubeScene(5);
    const lc::sr::ObserverCamera cam = srCamera(W, H);
    lc::sr::SrRenderOptions opt;
    opt.mode = lc::sr::SrRenderMode::PolygonDistortion;
    vtkNew<vtkLightconeSrImageRenderer> gpu;
    const Comparison c = renderBoth(gpu, scene, cam, opt).comparison();
    std::printf(
        "polygon distortion: object pixels %zu, coverage differing %zu (%.4f %%, off silhouette %zu), "
        "colour mean %.3f/255 max %.1f/255\n",
        c.objectPixels, c.differing, 100 * c.fraction(), c.offSilhouette, 255 * c.meanColour, 255 * c.maxColour);
    expectMatchesCpu(c);
}

// Penrose-Terrell: a sphere at beta = 0.9 has a circular outline. The silhouette pixels
// (object pixels with a background 4-neighbour) are turned into sky directions and fitted
// by a small circle d . c = cos(alpha) (linear least squares for m = c / cos(alpha)); the
// radial spread of the silhouette must be pixel quantisation only (a length-contracted
// outline, 1/gamma = 0.44 along x, would spread by tens of pixels).
TEST(SrGpuRender, SphereOutlineIsCircular) {
    const int W = 320, H = 180;
    lc::sr::SrScene scene;
    const lc::sr::MovingFrame frame(Vec3(0.9, 0, 0), Vec3(0, 0, -6));
    scene.objects.push_back({lc::sr::makeUvSphere(1.0, 96, 48), frame, {}});
    lc::sr::ObserverCamera cam = srCamera(W, H, 15.0);
    cam.forward = lc::sr::apparentPosition(frame, Vec3::Zero(), lc::Vec4::Zero());
    vtkNew<vtkLightconeSrImageRenderer> gpu;
    gpu->SetScene(scene, cam);
    const auto ids = gpu->RenderIds();
    dump("sr_sphere_gpu", gpu->RenderColour(), W, H);
    std::vector<Vec3> dirs;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            if (ids.object[static_cast<std::size_t>(j) * W + i] < 0) continue;
            bool edge = false;
            for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const int ni = i + di, nj = j + dj;
                edge |= ni < 0 || ni >= W || nj < 0 || nj >= H || ids.object[static_cast<std::size_t>(nj) * W + ni] < 0;
            }
            if (edge) dirs.push_back(cam.direction(i, j));
        }
    ASSERT_GT(dirs.size(), 100u);
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    Vec3 rhs = Vec3::Zero();
    for (const Vec3& d : dirs) A += d * d.transpose(), rhs += d;
    const Vec3 m = A.ldlt().solve(rhs);
    const Vec3 c = m.normalized();
    const double alpha = std::acos(std::min(1.0, 1.0 / m.norm()));
    double sum = 0, sum2 = 0, worst = 0;
    for (const Vec3& d : dirs) {
        const double r = std::acos(std::clamp(d.dot(c), -1.0, 1.0)) - alpha;
        sum += r, sum2 += r * r, worst = std::max(worst, std::abs(r));
    }
    const double pixel = 1.0 / cam.pinholeFocalPixels().y();  // angle of one pixel near the axis
    const double spread = std::sqrt(std::max(0.0, sum2 / dirs.size() - (sum / dirs.size()) * (sum / dirs.size())));
    std::printf("sphere beta 0.9: %zu silhouette pixels, angular radius %.2f px, spread %.3f px, worst %.3f px\n",
                dirs.size(), alpha / pixel, spread / pixel, worst / pixel);
    EXPECT_GT(alpha / pixel, 30.0);
    // Silhouette pixel centres lie 0..1 px inside the outline: spread ~ 0.3 px, worst <= 1.5 px.
    EXPECT_LT(spread, 0.5 * pixel);
    EXPECT_LT(worst, 1.5 * pixel);
}

// docs/PHYSICS.md section 6: a 6000 K black body approaching head-on at beta = 0.2 is seen at
// 7348.47 K, receding at 4898.98 K. A large face moving along the view axis, flat colour
// (no shading), the pixel on the optical axis: its colour must be the table colour of the
// shifted temperature within the 8-bit read-back (0.5/255 rounding + 0.5/255 for filtering).
TEST(SrGpuRender, HeadOnDopplerColour) {
    const int W = 41, H = 41;  // odd: pixel (20, 20) is centred on the axis
    const double expectedK[2] = {6000.0 * std::sqrt(1.2 / 0.8), 6000.0 * std::sqrt(0.8 / 1.2)};
    EXPECT_NEAR(expectedK[0], 7348.47, 0.01);
    EXPECT_NEAR(expectedK[1], 4898.98, 0.01);
    const lc::colour::BlackbodyTable table(1000.0, 60000.0, 2048);
    for (int dir = 0; dir < 2; ++dir) {
        lc::sr::SrScene scene;
        const double bz = dir == 0 ? 0.2 : -0.2;  // +z: towards the camera looking along -z
        scene.objects.push_back({lc::sr::makeCube(20.0, 1), lc::sr::MovingFrame(Vec3(0, 0, bz), Vec3(0, 0, -30)), {}});
        vtkNew<vtkLightconeSrImageRenderer> gpu;
        gpu->SetScene(scene, srCamera(W, H, 30.0));
        gpu->SetShading(false);
        for (int toneMap : {0, 1}) {
            gpu->SetToneMap(toneMap);
            const auto map = toneMap == 0 ? lc::colour::ToneMap::ColourOnly : lc::colour::ToneMap::ReferenceLog;
            const auto rgb = gpu->RenderColour();
            const std::size_t k = 3 * (20 * W + 20);
            const Vec3 got(rgb[k], rgb[k + 1], rgb[k + 2]);
            const Vec3 want = table.lookup(expectedK[dir], map);
            const Vec3 exact = lc::colour::blackbodySrgb(expectedK[dir], map);
            const Vec3 rest = table.lookup(6000.0, map);
            std::printf(
                "beta_z %+.1f tone map %d: GPU (%.4f %.4f %.4f), table(%.2f K) (%.4f %.4f %.4f), 6000 K (%.4f %.4f "
                "%.4f)\n",
                bz, toneMap, got.x(), got.y(), got.z(), expectedK[dir], want.x(), want.y(), want.z(), rest.x(),
                rest.y(), rest.z());
            for (int q = 0; q < 3; ++q) {
                EXPECT_NEAR(got(q), want(q), 1.0 / 255) << "channel " << q;
                EXPECT_NEAR(want(q), exact(q), 0.5 / 255);  // the table itself is fine enough
            }
            // And the test can see a shift: the rest-frame colour is far outside tolerance
            // (ColourOnly; ReferenceLog saturates to white at these temperatures).
            if (toneMap == 0) {
                EXPECT_GT((got - rest).cwiseAbs().maxCoeff(), 5.0 / 255);
            }
        }
    }
}

// Seed 003 Table 1: polygon distortion draws flat triangles between apparent vertices, whose
// true images are curved. For a coarse cube (2 triangles per face) the outlines differ
// visibly from local ray tracing; refining the mesh makes the two converge (the chord error
// falls like 1/n^2).
TEST(SrGpuRender, PolygonDistortionConvergesToLocalRayTracing) {
    const int W = 320, H = 180;
    const lc::sr::ObserverCamera cam = srCamera(W, H);
    vtkNew<vtkLightconeSrImageRenderer> gpu;
    std::vector<double> fractions;
    std::size_t coarseDiff = 0;
    for (int n : {1, 4, 16}) {
        gpu->SetScene(cubeScene(n), cam);
        gpu->SetModeToLocalRayTracing();
        const auto lrt = gpu->RenderIds();
        gpu->SetModeToPolygonDistortion();
        const auto pd = gpu->RenderIds();
        std::size_t diff = 0;
        const double f = coverageDifference(lrt.object, pd.object, &diff);
        std::printf(
            "cube %d x %d per face (%d triangles): polygon distortion vs local ray tracing: %zu pixels differ (%.3f "
            "%%)\n",
            n, n, 12 * n * n, diff, 100 * f);
        if (n == 1) coarseDiff = diff;
        fractions.push_back(f);
    }
    EXPECT_GT(coarseDiff, 50u);
    EXPECT_GT(fractions[0], 0.01);
    EXPECT_LT(fractions[1], fractions[0]);
    EXPECT_LT(fractions[2], fractions[1]);
    EXPECT_LT(fractions[2], 0.25 * fractions[0]);
    EXPECT_LT(fractions[2], 0.005);
}

// Replacing the scene: a new object count (two, one, none, two again) draws exactly the new
// objects in both techniques, each where the CPU SrRenderer puts it; a scene the renderer refuses
// (a negative material value, a triangle without its vertex) names the object and leaves the
// accepted scene drawn.
TEST(SrGpuRender, ReplacingTheSceneDrawsExactlyItsObjects) {
    const int W = 96, H = 54;
    const lc::sr::ObserverCamera cam = srCamera(W, H, 60.0);
    lc::sr::SrScene two;
    two.objects.push_back({lc::sr::makeCube(2.0, 2), lc::sr::MovingFrame(Vec3(0.5, 0, 0), Vec3(-3, 0, -8)), {}});
    two.objects.push_back(
        {lc::sr::makeUvSphere(1.6, 24, 12), lc::sr::MovingFrame(Vec3(0, 0.2, 0.4), Vec3(3, 0.5, -8)), {}});
    lc::sr::SrScene one = two, none = two;
    one.objects.pop_back();
    none.objects.clear();
    vtkNew<vtkLightconeSrImageRenderer> gpu;
    for (int mode : {vtkLightconeSrImageRenderer::LocalRayTracing, vtkLightconeSrImageRenderer::PolygonDistortion}) {
        SCOPED_TRACE(mode == 0 ? "local ray tracing" : "polygon distortion");
        gpu->SetMode(mode);
        lc::sr::SrRenderOptions opt;
        opt.mode = mode == 0 ? lc::sr::SrRenderMode::LocalRayTracing : lc::sr::SrRenderMode::PolygonDistortion;
        for (const lc::sr::SrScene* scene : {&two, &one, &none, &two}) {
            gpu->SetScene(*scene, cam);
            const auto ids = gpu->RenderIds();
            const lc::sr::SrImage cpu = lc::sr::SrRenderer().render(*scene, cam, opt);
            std::size_t differing = 0, shown[2] = {0, 0};
            for (std::size_t k = 0; k < ids.object.size(); ++k) {
                ASSERT_LT(ids.object[k], static_cast<int>(scene->objects.size())) << "an object of an earlier scene";
                differing += ids.object[k] != cpu.object[k];
                if (ids.object[k] >= 0) ++shown[ids.object[k]];
            }
            for (std::size_t o = 0; o < scene->objects.size(); ++o) EXPECT_GT(shown[o], 40u) << "object " << o;
            EXPECT_LE(differing, 4u) << scene->objects.size() << " objects";  // silhouette pixels in float
        }
    }
    lc::sr::SrScene bad = two;
    bad.objects[1].material.diffuse = -1;
    try {
        gpu->SetScene(bad, cam);
        ADD_FAILURE() << "a negative diffuse factor was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("object 1: material values must be finite and >= 0"), std::string::npos)
            << e.what();
    }
    bad = two;
    bad.objects[0].mesh.triangles[3][1] = 100000;
    EXPECT_THROW(gpu->SetScene(bad, cam), std::invalid_argument);
    const auto ids = gpu->RenderIds();
    EXPECT_GT(std::count(ids.object.begin(), ids.object.end(), 1), 40);  // the accepted scene is drawn
}
