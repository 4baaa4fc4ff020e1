// SPDX-License-Identifier: BSD-3-Clause
// The shadow measured (lc::measureShadow: symmetry line, edges, offset, height) by the CPU's
// bisection at several tolerances and by the GPU tracer's pixel strips (lc::views::gpuShadowEdges)
// at several narrowing passes: seconds per measurement against the error of the width and height,
// relative to the CPU at 1e-12 (which tests/validation holds to the closed forms to 1e-10).
// Run under xvfb-run -a from the repository root.
#include "bench_common.hpp"

#include "core/analysis/shadow.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "gpu_shadow_edges.hpp"

#include <cmath>
#include <cstdio>
#include <memory>

namespace {

lc::Scene inclined(double a, double r, double inclinationDeg) {
    lc::Scene s;
    s.spacetime = std::make_shared<lc::KerrNewman>(1, a, 0);
    const double i = inclinationDeg * lc::kPi / 180;
    s.observer = lc::Vec4(0, r * std::sin(i), 0, r * std::cos(i));
    s.camera.lookAt = lc::Vec3::Zero();
    s.camera.up = lc::Vec3(-std::cos(i), 0, std::sin(i));
    return s;
}

}  // namespace

int main() {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows appear as they are measured
    std::printf("Machine: %s (GPU path: VTK's GLX, Mesa llvmpipe under Xvfb where there is no GPU)\n\n",
                lc::bench::machineName().c_str());
    struct Case {
        const char* name;
        lc::Scene scene;
    };
    const Case cases[] = {{"Schwarzschild, r = 6 M, i = 30 deg", inclined(0, 6, 30)},
                          {"Kerr a = 0.9, r = 10 M, i = 60 deg", inclined(0.9, 10, 60)},
                          {"Kerr a = 0.998, r = 200 M, i = 85 deg", inclined(0.998, 200, 85)}};
    for (const Case& c : cases) {
        const lc::ShadowSize ref = lc::measureShadow(c.scene, 1e-12);
        std::printf("### %s (width %.9f deg, height %.9f deg)\n\n", c.name, ref.widthDegrees(), ref.heightDegrees);
        std::printf(
            "| method | setting | s per measurement | width rel. error | height rel. error |\n|---|---|---|---|---|\n");
        auto row = [&](const char* method, const std::string& setting, double secs, const lc::ShadowSize& m) {
            std::printf("| %s | %s | %.3f | %.1e | %.1e |\n", method, setting.c_str(), secs,
                        std::abs(m.widthDegrees() / ref.widthDegrees() - 1),
                        std::abs(m.heightDegrees / ref.heightDegrees - 1));
        };
        for (double tol : {1e-4, 1e-6, 1e-8, 1e-11}) {
            lc::ShadowSize m;
            const double secs = lc::bench::seconds([&] { m = lc::measureShadow(c.scene, tol); });
            char setting[32];
            std::snprintf(setting, sizeof setting, "bisection %.0e", tol);
            row("CPU (2 cores idle: one ray at a time)", setting, secs, m);
        }
        for (int passes : {2, 3, 4}) {
            lc::views::GpuShadowEdgeOptions o;
            o.passes = passes;
            lc::ShadowSize m;
            const std::string setting = std::to_string(o.stripPixels) + " px x " + std::to_string(passes) + " passes";
            try {
                const double secs =
                    lc::bench::seconds([&] { m = lc::measureShadow(c.scene, lc::views::gpuShadowEdges(c.scene, o)); });
                row("GPU tracer strips", setting, secs, m);
            } catch (const std::exception& e) {
                std::printf("| GPU tracer strips | %s | failed: %s | | |\n", setting.c_str(), e.what());
            }
        }
        std::printf("\n");
    }
    return 0;
}
