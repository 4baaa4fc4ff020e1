// SPDX-License-Identifier: BSD-3-Clause
#include "camera_uniforms.hpp"

#include <vtkShaderProgram.h>

namespace lc::views {

void setCameraUniforms(vtkShaderProgram* p, const Camera& camera) {
    const Camera::Axes a = camera.axes();
    const auto set3 = [p](const char* name, const Vec3& v) {
        const float f[3] = {float(v.x()), float(v.y()), float(v.z())};
        p->SetUniform3f(name, f);
    };
    set3("lcForward", a.forward);
    set3("lcRight", a.right);
    set3("lcUp", a.up);
    const bool pinhole = camera.projection == Camera::Projection::Pinhole;
    p->SetUniformi("lcProjection", pinhole ? 0 : 1);
    // A panorama's half extent may reach 180 degrees, whose tangent means nothing: 1 there, unused.
    const Vec2 half = camera.halfFieldRadians(), tangents = pinhole ? camera.halfFieldTangents() : Vec2(1, 1);
    p->SetUniformf("lcTanHalfX", float(tangents.x()));
    p->SetUniformf("lcTanHalfY", float(tangents.y()));
    p->SetUniformf("lcHalfX", float(half.x()));
    p->SetUniformf("lcHalfY", float(half.y()));
    p->SetUniformf("lcWidth", float(camera.width));
    p->SetUniformf("lcHeight", float(camera.height));
}

}  // namespace lc::views
