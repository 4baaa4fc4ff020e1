// SPDX-License-Identifier: BSD-3-Clause
// The special-relativity route of `lightcone render` (lc::renderSrImage): a 6000 K
// face coming head-on at 0.2c shows the colour of 7348.47 K, receding 4898.98 K
// (docs/PHYSICS.md section 6), in the linear RGB the rest of the pipeline carries.
#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"
#include "core/metrics/minkowski.hpp"
#include "core/render/special_relativity.hpp"

#include <gtest/gtest.h>

using namespace lc;

namespace {

Vec3 centreColour(double betaZ) {
    Scene s;
    s.spacetime = std::make_shared<Minkowski>();
    s.camera.width = 41;
    s.camera.height = 41;
    s.camera.fovXDeg = s.camera.fovYDeg = 20;
    s.camera.forward = Vec3(0, 0, -1);
    s.camera.up = Vec3(0, 1, 0);
    MeshObject box;
    box.name = "box";
    box.centre = Vec4(0, 0, 0, -20);
    const double h = 3;
    // One face towards the observer (+z), two triangles.
    box.positions = {Vec3(-h, -h, h), Vec3(h, -h, h), Vec3(h, h, h), Vec3(-h, h, h)};
    box.normals.assign(4, Vec3(0, 0, 1));
    box.triangles = {{0, 1, 2}, {0, 2, 3}};
    box.temperature = 6000;
    box.motion.kind = Motion::Kind::ConstantVelocity;
    box.motion.beta = Vec3(0, 0, betaZ);
    s.meshes.push_back(box);
    PointLight lamp;
    lamp.position = Vec4(0, 0, 100, -18);  // far above: grazing light, no highlight, no clamping
    s.lights.push_back(lamp);
    const ColouredImage r = renderSrImage(s);
    const std::size_t centre = 20 * 41 + 20;
    EXPECT_EQ(r.records.pixels[centre].kind, PixelRecord::Object);
    Vec3 c;
    for (int k = 0; k < 3; ++k) c(k) = colour::srgbEncode(r.rgb[3 * centre + k]);  // back to display values
    return c / c.maxCoeff();                                                       // shading scales all channels alike
}

TEST(RenderSpecialRelativity, HeadOnDopplerColoursInLinearRgb) {
    for (auto [beta, T] : {std::pair{0.2, 6000 * std::sqrt(1.2 / 0.8)}, std::pair{-0.2, 6000 * std::sqrt(0.8 / 1.2)}}) {
        const Vec3 got = centreColour(beta);
        Vec3 want = colour::blackbodySrgb(T, colour::ToneMap::ColourOnly);
        want /= want.maxCoeff();
        EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 5e-3)
            << "beta " << beta << ": got " << got.transpose() << ", want " << want.transpose();
    }
    // And the two differ visibly from each other and from 6000 K.
    EXPECT_GT((centreColour(0.2) - centreColour(-0.2)).norm(), 0.05);
}

}  // namespace
