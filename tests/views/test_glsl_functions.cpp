// SPDX-License-Identifier: BSD-3-Clause
// Each GLSL function against its C++ twin at sample points, evaluated on the GPU (under Xvfb:
// Mesa llvmpipe) and read back bit for bit (glsl_probe): the metric and its gradient
// generated from every metric's code (core/codegen) against lc::Spacetime::metricAndDerivatives,
// at points that include the Kerr horizon and the Goedel axis and for a metric defined only in
// the tests (tests/common/test_metric.hpp); Hamilton's equations (lcFlow, generated from
// lc::hamiltonEquations) against Spacetime::flow; one Dormand-Prince step (lcDopri5Step, generated
// by running odeint's runge_kutta_dopri5::do_step on codegen::Expr) against odeint itself; the sky
// lookup, sRGB decode, day/night blend, SR aberration, rest-frame ray hit and flat hit against
// their core functions.
// Tolerances are single precision: each value is a short chain of float operations, so its
// error is a few ulp (6e-8 relative) of the largest intermediate term; we allow ~100 ulp of the
// scale stated at each check, far below any formula error (a wrong sign, factor or index is off
// by O(1)).
#include "core/accretion/thin_disk.hpp"
#include "core/codegen/symbolic_metric.hpp"
#include "core/codegen/tracer_glsl.hpp"
#include "core/colour/srgb.hpp"
#include "core/scene/camera.hpp"
#include "core/spacetime/frame.hpp"
#include "core/sr/observer_camera.hpp"
#include "core/render/post_render.hpp"
#include "core/render/render.hpp"
#include "core/scene/scene.hpp"
#include "core/scene/texture.hpp"
#include "core/sr/doppler.hpp"
#include "core/sr/local_ray_tracing.hpp"
#include "core/sr/renderer.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "glsl_probe.hpp"
#include "core_formula_glsl.hpp"
#include "core/numerics/bessel.hpp"
#include "readers/io/metric_file.hpp"
#include "glsl_sources.hpp"
#include "metric_glsl.hpp"
#include "sr_glsl.hpp"
#include "tests/common/test_metric.hpp"

#include <gtest/gtest.h>

#include <boost/numeric/odeint.hpp>

#include <cmath>
#include <memory>
#include <sstream>

namespace {
using namespace lc;

// lcOut[0..15] = g, lcOut[16 + 16 k ..] = d g / d x^k (column-major, as GLSL stores mat4).
const char* kMetricProbeBody =
    "mat4 g, d0, d1, d2, d3; lcMetric(lcIn, g, d0, d1, d2, d3);"
    "for (int m = 0; m < 4; ++m) for (int n = 0; n < 4; ++n) {"
    "  lcOut[4 * m + n] = g[m][n]; lcOut[16 + 4 * m + n] = d0[m][n]; lcOut[32 + 4 * m + n] = d1[m][n];"
    "  lcOut[48 + 4 * m + n] = d2[m][n]; lcOut[64 + 4 * m + n] = d3[m][n]; }"
    "lcOut[80] = lcBoundary(lcIn);";

void expectGpuMetricMatches(const Spacetime& st, const std::vector<Vec4>& points) {
    SCOPED_TRACE(st.name());
    const codegen::GeneratedGlsl glsl = codegen::metricGlsl(*st.symbolic());
    std::vector<std::array<float, 4>> inputs;
    for (const Vec4& x : points) inputs.push_back({float(x(0)), float(x(1)), float(x(2)), float(x(3))});
    const auto gpu = views::evaluateOnGpu(
        {views::metricShaderFunctions(st), kMetricProbeBody, 81, {}, {}, nullptr, colour::ToneMap::ColourOnly}, inputs);
    double worst = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        // The C++ reference at the float-rounded point the GPU saw.
        const Vec4 x(inputs[i][0], inputs[i][1], inputs[i][2], inputs[i][3]);
        Mat4 g;
        std::array<Mat4, 4> dg;
        st.metricAndDerivatives(x, g, dg);
        const double scale = 1 + x.cwiseAbs().maxCoeff();
        for (int m = 0; m < 4; ++m)
            for (int n = 0; n < 4; ++n) {
                const double eg = std::abs(gpu[i][std::size_t(4 * m + n)] - g(m, n)) / (1 + std::abs(g(m, n)) * scale);
                EXPECT_LT(eg, 2e-5) << "g" << m << n << " at " << x.transpose();
                worst = std::max(worst, eg);
                for (int k = 0; k < 4; ++k) {
                    const double v = gpu[i][std::size_t(16 + 16 * k + 4 * m + n)];
                    const double e = std::abs(v - dg[k](m, n)) / (1 + std::abs(dg[k](m, n)) * scale);
                    EXPECT_LT(e, 2e-5) << "d" << k << " g" << m << n << " at " << x.transpose() << ": GPU " << v
                                       << " CPU " << dg[k](m, n);
                    worst = std::max(worst, e);
                }
            }
    }
    std::printf("%s: %zu points, %d generated temporaries, worst scaled error %.2e\n", st.name().c_str(), points.size(),
                glsl.temporaries, worst);
}

TEST(GlslFunctions, GeneratedMetricAndGradientMatchCoreForEveryMetric) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const double rh = kerr.outerHorizon();
    expectGpuMetricMatches(Minkowski(), {Vec4(0, 1, 2, 3)});
    expectGpuMetricMatches(Schwarzschild(1.0), {Vec4(0, 10, 0, 0), Vec4(0, 1.2, 1.2, 0.3), Vec4(0, 2.05, 0, 0)});
    expectGpuMetricMatches(
        kerr, {Vec4(0, 10, -3, 2), Vec4(0, rh * 1.02, 0, 0.1), Vec4(0, 0.5, 0.5, 1.9), Vec4(0, 0.1, 0, 3)});
    expectGpuMetricMatches(KerrNewman(1.0, 0.5, 0.6), {Vec4(0, 3, 1, -1), Vec4(0, 1.9, 0, 0.2)});
    expectGpuMetricMatches(Alcubierre(2.0, 1.0, 8.0),
                           {Vec4(0, 0.2, 0, 0.5), Vec4(0.3, 1.5, 0.2, 0), Vec4(1, 2.1, 0, 0.4)});
    expectGpuMetricMatches(GodelCartesian(1.0),
                           {Vec4(0, 0, 0, 0), Vec4(0, 0, 0, 5), Vec4(0, 1.9, 0.3, 0), Vec4(0, -2, 0.01, 1)});
    expectGpuMetricMatches(lc::test::RippleMetric(), {Vec4(0.5, 0.2, -0.3, 0.1), Vec4(3, 1, 1, -2)});
}

// A metric typed with Bessel functions (data/metrics/bessel_gravitational_wave.json): the GPU's
// float approximation of J0 and J1 and its generated derivatives against the CPU's exact ones,
// near the axis, across |rho| = 3 (the approximation's branch) and far out.
TEST(GlslFunctions, GeneratedBesselWaveMetricAndGradientMatchCore) {
    const auto wave = io::loadFormulaMetric(
        std::string(LIGHTCONE_SOURCE_DIR) + "/data/metrics/bessel_gravitational_wave.json", {{"C", 0.8}});
    expectGpuMetricMatches(
        *wave, {Vec4(0.7, 0.05, 0.02, 0.2), Vec4(2.0, 1.3, -1.1, 0), Vec4(-1, 2.1, 2.2, 1), Vec4(0.3, -5, 4, 0.5)});
}

// lcFlow, generated from lc::hamiltonEquations, against Spacetime::flow (the same template in
// double) for the covector p at each point (Hamilton's equations hold for any p; inside the
// ergosphere no static observer exists to make a null one). dx = g^{-1} p loses float digits
// with g's condition number (large near a horizon), so the error is scaled by the largest term.
void expectGpuFlowMatches(const Spacetime& st, const std::vector<Vec4>& points, const Vec4& covector) {
    SCOPED_TRACE(st.name());
    double worst = 0;
    for (const Vec4& x0 : points) {
        const Vec4 x = x0.cast<float>().cast<double>();
        const Vec4 p = covector.cast<float>().cast<double>();
        views::GlslProbe probe;
        probe.declarations = views::tracerShaderFunctions(st);
        probe.body =
            "vec4 dx, dp; lcFlow(lcIn, lcP, dx, dp); for (int k = 0; k < 4; ++k) { lcOut[k] = dx[k]; lcOut[4 + k] = "
            "dp[k]; }";
        probe.outputs = 8;
        probe.uniforms = {{"lcP", {float(p(0)), float(p(1)), float(p(2)), float(p(3))}}, {"lcTolerance", {1e-6f}}};
        const std::vector<float> gpu =
            views::evaluateOnGpu(probe, {{float(x(0)), float(x(1)), float(x(2)), float(x(3))}})[0];
        const HamiltonianFlow f = st.flow(x, p);
        const double scale = std::max(f.dxdl.cwiseAbs().maxCoeff(), f.dpdl.cwiseAbs().maxCoeff()) + 1e-30;
        for (int k = 0; k < 4; ++k) {
            const double ex = std::abs(gpu[std::size_t(k)] - f.dxdl(k)) / scale,
                         ep = std::abs(gpu[std::size_t(4 + k)] - f.dpdl(k)) / scale;
            EXPECT_LT(ex, 1e-5) << "dx" << k << " at " << x.transpose() << ": GPU " << gpu[std::size_t(k)] << " CPU "
                                << f.dxdl(k);
            EXPECT_LT(ep, 1e-5) << "dp" << k << " at " << x.transpose() << ": GPU " << gpu[std::size_t(4 + k)]
                                << " CPU " << f.dpdl(k);
            worst = std::max({worst, ex, ep});
        }
    }
    std::printf("%s: lcFlow at %zu points, worst scaled error %.2e\n", st.name().c_str(), points.size(), worst);
}

TEST(GlslFunctions, GeneratedFlowMatchesHamiltonsEquationsForEveryMetric) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const double rh = kerr.outerHorizon();
    const Vec4 n(-1.0, 0.8, -0.5, 0.33);
    expectGpuFlowMatches(Minkowski(), {Vec4(0, 1, 2, 3)}, n);
    expectGpuFlowMatches(Schwarzschild(1.0), {Vec4(0, 10, 0, 0), Vec4(0, 2.05, 0, 0)}, n);
    expectGpuFlowMatches(kerr, {Vec4(0, 10, -3, 2), Vec4(0, rh * 1.02, 0, 0.1), Vec4(0, 0.5, 0.5, 1.9)}, n);
    expectGpuFlowMatches(KerrNewman(1.0, 0.5, 0.6), {Vec4(0, 3, 1, -1)}, n);
    expectGpuFlowMatches(Alcubierre(2.0, 1.0, 8.0), {Vec4(0, 0.2, 0, 0.5), Vec4(1, 2.1, 0, 0.4)}, n);
    expectGpuFlowMatches(GodelCartesian(1.0), {Vec4(0, 0, 0, 0), Vec4(0, 1.9, 0.3, 0)}, n);
    expectGpuFlowMatches(lc::test::RippleMetric(), {Vec4(0.5, 0.2, -0.3, 0.1)}, n);
}

TEST(GlslFunctions, GeneratedBoundaryIsKerrsHorizonFunction) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const double rh = kerr.outerHorizon(), x = std::sqrt(rh * rh + 0.81);
    const auto gpu = views::evaluateOnGpu(
        {views::metricShaderFunctions(kerr), kMetricProbeBody, 81, {}, {}, nullptr, colour::ToneMap::ColourOnly},
        {{0.f, float(x), 0.f, 0.f}, {0.f, 10.f, 0.f, 0.f}});
    EXPECT_NEAR(gpu[0][80], 0.0, 1e-6);  // on the horizon
    EXPECT_NEAR(gpu[1][80], kerr.boundaryFunction<double>(Vec4(0, 10, 0, 0)), 1e-6);
}

TEST(GlslFunctions, ProbeRefusesBadRequestsAndTransfersFloatsExactly) {
    EXPECT_THROW(views::evaluateOnGpu({"", "lcOut[0] = 1.0;", 1, {}, {}, nullptr, colour::ToneMap::ColourOnly}, {}),
                 std::invalid_argument);
    EXPECT_THROW(
        views::evaluateOnGpu({"", "lcOut[0] = 1.0;", 0, {}, {}, nullptr, colour::ToneMap::ColourOnly}, {{0, 0, 0, 0}}),
        std::invalid_argument);
    // Exact transfer: a value with every mantissa bit set comes back bit for bit.
    const auto v = views::evaluateOnGpu(
        {"", "lcOut[0] = lcIn.x; lcOut[1] = -lcIn.y * 2.0;", 2, {}, {}, nullptr, colour::ToneMap::ColourOnly},
        {{1.99999988f, 3.0e-38f, 0, 0}});
    EXPECT_EQ(v[0][0], 1.99999988f);
    EXPECT_EQ(v[0][1], -6.0e-38f);
}

// One step of the GPU stepper from a Kerr null ray's state, against odeint's dopri5 step on the
// CPU flow in double: the GLSL was recorded from that same do_step, so this checks the recording
// (every stage fed to lcFlow in order, the tableau's constants, the first-same-as-last stage)
// and its float evaluation: the fifth-order state, and the error norm of odeint's y5 - y4.
TEST(GlslFunctions, Dopri5StepMatchesOdeint) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const Vec4 x(0, 6, 2, 1);
    const Vec4 p = LocalFrame::staticObserver(kerr, x).pastNullMomentum(kerr, Vec3(-0.8, 0.5, 0.33).normalized());
    const double h = 2.5, tol = 1e-5;
    using State = std::array<double, 8>;
    auto system = [&kerr](const State& s, State& d, double) {
        const HamiltonianFlow f = kerr.flow(Vec4(s[0], s[1], s[2], s[3]), Vec4(s[4], s[5], s[6], s[7]));
        for (int i = 0; i < 4; ++i) {
            d[std::size_t(i)] = f.dxdl(i);
            d[std::size_t(4 + i)] = f.dpdl(i);
        }
    };
    // The GPU starts from the float-rounded state: so does the reference.
    State in;
    for (int i = 0; i < 4; ++i) {
        in[std::size_t(i)] = float(x(i));
        in[std::size_t(4 + i)] = float(p(i));
    }
    State dxdt, out, dxdtOut, err;
    system(in, dxdt, 0);
    boost::numeric::odeint::runge_kutta_dopri5<State> stepper;
    stepper.do_step(system, in, dxdt, 0.0, out, dxdtOut, h, err);
    // The norm odeint's controlled dopri5 computes (its default_error_checker), the generated
    // lcStepErrorNorm's source.
    decltype(stepper)::algebra_type algebra;
    const double cpuNorm = boost::numeric::odeint::default_error_checker<double, decltype(stepper)::algebra_type,
                                                                         decltype(stepper)::operations_type>(tol, tol)
                               .error(algebra, in, dxdt, err, h);

    views::GlslProbe probe;
    probe.declarations = views::tracerShaderFunctions(kerr);
    probe.body =
        "vec4 k1x, k1p; lcFlow(lcX, lcP, k1x, k1p); vec4 xn, pn, k7x, k7p;"
        "float e = lcDopri5Step(lcX, lcP, k1x, k1p, lcH, xn, pn, k7x, k7p);"
        "for (int k = 0; k < 4; ++k) { lcOut[k] = xn[k]; lcOut[4 + k] = pn[k]; } lcOut[8] = e;";
    probe.outputs = 9;
    probe.uniforms = {{"lcX", {float(in[0]), float(in[1]), float(in[2]), float(in[3])}},
                      {"lcP", {float(in[4]), float(in[5]), float(in[6]), float(in[7])}},
                      {"lcH", {float(h)}},
                      {"lcTolerance", {float(tol)}}};
    const std::vector<float> gpu = views::evaluateOnGpu(probe, {{0, 0, 0, 0}})[0];
    for (std::size_t i = 0; i < 8; ++i)
        EXPECT_NEAR(gpu[i], out[i], 2e-5 * (1 + std::abs(out[i]))) << "state component " << i;
    // The error estimate is a difference of nearly equal sums: float round-off of the stages
    // (~1e-7 x |y| / h) enters it, so it agrees to a few percent where it is well above that.
    ASSERT_GT(cpuNorm, 0.05) << "choose a step whose error estimate is well above float round-off";
    EXPECT_NEAR(gpu[8], cpuNorm, 0.05 * cpuNorm);
    std::printf("dopri5 step h = %.2f: error norm GPU %.4f, odeint %.4f\n", h, gpu[8], cpuNorm);
}

// The generated step control against odeint's own controlled stepper in double: lcDecreaseStep
// (recorded from default_step_adjuster::decrease_step), lcIncreaseStep (lc::increasedStep) at
// errors on both sides of odeint's branches, and lcStepErrorNorm (default_error_checker) on a
// state with components of mixed sign and size.
TEST(GlslFunctions, StepControlMatchesOdeint) {
    namespace odeint = boost::numeric::odeint;
    using Dopri5 = odeint::runge_kutta_dopri5<std::array<double, 8>>;
    const odeint::default_step_adjuster<double, double> adjuster;
    const float h = 0.75f;
    std::vector<std::array<float, 4>> in;
    for (float e : {1e-9f, 3.2e-4f, 0.01f, 0.3f, 0.49f, 0.5f, 0.51f, 0.9f, 1.0f, 1.01f, 2.0f, 40.0f, 1e6f, 1e30f})
        in.push_back({h, e, 0, 0});
    views::GlslProbe probe;
    probe.declarations = codegen::stepControlGlsl().source;
    probe.body = "lcOut[0] = lcDecreaseStep(lcIn.x, lcIn.y); lcOut[1] = lcIncreaseStep(lcIn.x, lcIn.y);";
    probe.outputs = 2;
    const auto gpu = views::evaluateOnGpu(probe, in);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const double e = in[i][1];
        if (e > 1) {
            const double cpu = adjuster.decrease_step(h, e, Dopri5::error_order_value);
            EXPECT_NEAR(gpu[i][0], cpu, 1e-6 * cpu) << "decrease at error " << e;
        } else {
            const double cpu = adjuster.increase_step(h, e, Dopri5::stepper_order_value);
            EXPECT_NEAR(gpu[i][1], cpu, 1e-6 * cpu) << "increase at error " << e;
        }
    }

    const std::array<double, 8> y{1.5, -40, 0.25, 3e3, -0.9, 2.0, -7.5, 0.001},
        dy{0.3, 12, -5, 0.02, 1e-3, -4, 60, 0.7}, e0{2e-6, -3e-5, 1e-7, 4e-3, -1e-6, 5e-6, -2e-5, 1e-8};
    const double tol = 1e-5, step = 0.4;
    std::array<double, 8> e = e0;
    Dopri5::algebra_type algebra;
    const double cpuNorm =
        odeint::default_error_checker<double, Dopri5::algebra_type, Dopri5::operations_type>(tol, tol).error(
            algebra, y, dy, e, step);
    auto v4 = [](const std::array<double, 8>& a, std::size_t first) {
        return std::vector<float>{float(a[first]), float(a[first + 1]), float(a[first + 2]), float(a[first + 3])};
    };
    views::GlslProbe norm;
    norm.declarations = codegen::stepControlGlsl().source;
    norm.body = "lcOut[0] = lcStepErrorNorm(lcX, lcP, lcDx, lcDp, lcEx, lcEp, lcH, lcTol);";
    norm.uniforms = {{"lcX", v4(y, 0)},   {"lcP", v4(y, 4)},   {"lcDx", v4(dy, 0)},    {"lcDp", v4(dy, 4)},
                     {"lcEx", v4(e0, 0)}, {"lcEp", v4(e0, 4)}, {"lcH", {float(step)}}, {"lcTol", {float(tol)}}};
    const float gpuNorm = views::evaluateOnGpu(norm, {{0, 0, 0, 0}})[0][0];
    EXPECT_NEAR(gpuNorm, cpuNorm, 1e-5 * cpuNorm);
}

// The null condition's drift the GPU tracer stops on (lcConstraintDrift) against lc::constraintDrift,
// which the CPU tracer stops on: a null momentum of Kerr near its horizon (drift ~ rounding), the
// same momentum off the light cone by 1e-3 and 0.1 of its size, the launch scale dominating, and
// terms of size 1e4 (a ray piling up on a chart's horizon). Float: ~1e-6 of the terms' size.
TEST(GlslFunctions, ConstraintDriftMatchesCore) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const Vec4 x(0, 2.2, 0.3, 0.4);
    const Mat4 gi = kerr.inverseMetric(x);
    // A null covector at x: the spatial components chosen, p_t solved from g^{mu nu} p_mu p_nu = 0.
    Vec4 p(0, 0.3, -0.8, 0.5);
    const double a = gi(0, 0), b = 2 * gi(0, 1) * p(1) + 2 * gi(0, 2) * p(2) + 2 * gi(0, 3) * p(3);
    double c = 0;
    for (int m = 1; m < 4; ++m)
        for (int n = 1; n < 4; ++n) c += gi(m, n) * p(m) * p(n);
    p(0) = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
    struct Sample {
        Vec4 p;
        double scale;
    };
    const std::vector<Sample> samples{{p, 1.0},
                                      {p + Vec4(1e-3 * p.norm(), 0, 0, 0), 1.0},
                                      {p + Vec4(0, 0.1 * p.norm(), 0, 0), 1.0},
                                      {p + Vec4(0, 0.1 * p.norm(), 0, 0), 50.0},
                                      {1e2 * p + Vec4(0, 1e-2, 0, 0), 1.0}};
    std::vector<std::array<float, 4>> in;
    for (const Sample& s : samples) in.push_back({float(s.p(0)), float(s.p(1)), float(s.p(2)), float(s.p(3))});
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const Vec4 pf(in[i][0], in[i][1], in[i][2], in[i][3]);  // the float-rounded momentum the GPU sees
        const Vec4 v = gi * pf;
        views::GlslProbe probe;
        probe.declarations = codegen::constraintDriftGlsl().source;
        probe.body = "lcOut[0] = lcConstraintDrift(lcIn, lcV, lcScale);";
        probe.uniforms = {{"lcV", {float(v(0)), float(v(1)), float(v(2)), float(v(3))}},
                          {"lcScale", {float(samples[i].scale)}}};
        const double gpu = views::evaluateOnGpu(probe, {in[i]})[0][0];
        const double cpu = constraintDrift<double>(pf, v, samples[i].scale);
        EXPECT_NEAR(gpu, cpu, 2e-6) << "sample " << i;
    }
    // The samples span the outcomes: on the light cone, just off it, far off it.
    EXPECT_LT(constraintDrift<double>(samples[0].p, gi * samples[0].p, 1.0), 1e-12);
    EXPECT_GT(constraintDrift<double>(samples[2].p, gi * samples[2].p, 1.0), 1e-2);
}

// Runs `glsl` (a function of glsl/<stem>) on each input and returns its outputs.
std::vector<std::vector<float>> probeFunction(const std::string& declarations, const std::string& body, int outputs,
                                              const std::vector<std::array<float, 4>>& inputs) {
    return views::evaluateOnGpu({declarations, body, outputs, {}, {}, nullptr, colour::ToneMap::ColourOnly}, inputs);
}

TEST(GlslFunctions, SkyUvMatchesToSkyUv) {
    std::vector<std::array<float, 4>> in;
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(-1, 0.01, 0.2),
                          Vec3(-1, -0.01, -0.2), Vec3(0.3, -0.7, 0.5), Vec3(-0.2, 0.1, -0.9)}) {
        const Vec3 n = d.normalized();
        in.push_back({float(n(0)), float(n(1)), float(n(2)), 0});
    }
    const auto gpu =
        probeFunction(views::skyUvGlsl(), "vec2 uv = lcSkyUv(lcIn.xyz); lcOut[0] = uv.x; lcOut[1] = uv.y;", 2, in);
    for (std::size_t i = 0; i < in.size(); ++i) {
        float u, v;
        toSkyUv(Vec3(in[i][0], in[i][1], in[i][2]), u, v);
        EXPECT_NEAR(gpu[i][0], u, 2e-6) << i;  // u, v in [0, 1]: ~30 ulp; acos near the poles loses more
        EXPECT_NEAR(gpu[i][1], v, 1e-4) << i;
    }
}

// The far side's direction of a two-ended metric (lc::Spacetime::otherEndDirection): the ray's
// direction k = (kx, 0.3, -0.8) at x reflected in the plane normal to x.
TEST(GlslFunctions, OtherEndDirectionMatchesTheInversion) {
    std::vector<std::array<float, 4>> in;
    for (const auto& [x, kx] : std::vector<std::pair<Vec3, double>>{{Vec3(1, 0, 0), -1.0},
                                                                    {Vec3(0.01, 0.002, -0.003), 0.5},
                                                                    {Vec3(-0.2, 0.7, 0.1), 0.0},
                                                                    {Vec3(3, -4, 12), 2.0}})
        in.push_back({float(x(0)), float(x(1)), float(x(2)), float(kx)});
    const auto gpu = probeFunction(views::otherEndDirectionGlsl(),
                                   "vec3 d = lcOtherEndDirection(lcIn.xyz, vec3(lcIn.w, 0.3, -0.8));"
                                   "lcOut[0] = d.x; lcOut[1] = d.y; lcOut[2] = d.z;",
                                   3, in);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const Vec3 x(in[i][0], in[i][1], in[i][2]), k(in[i][3], 0.3, -0.8);
        const Vec3 n = x.normalized(), expected = (k - 2 * n.dot(k) * n).normalized();
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[i][std::size_t(c)], expected(c), 1e-6) << i << " " << c;
    }
}

// The GPU's Bessel functions (generated from lc::besselJ0Approximation and
// besselJ1Approximation, Abramowitz and Stegun 9.4) against std::cyl_bessel_j, on both sides of
// the branch at |x| = 3, at 0 and far out: the approximation's 5e-8 plus float rounding.
TEST(GlslFunctions, BesselFunctionsMatchTheStandardLibrary) {
    std::vector<std::array<float, 4>> in;
    for (const float x : {0.0f, 1e-4f, 0.7f, -1.3f, 2.999f, 3.001f, -4.2f, 9.5f, 40.0f, -123.4f})
        in.push_back({x, 0, 0, 0});
    const auto gpu =
        probeFunction(views::besselGlsl(), "lcOut[0] = lcBesselJ0(lcIn.x); lcOut[1] = lcBesselJ1(lcIn.x);", 2, in);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const double x = in[i][0];
        // Float rounding of the phase |x| + theta, 2^-24 |x|, times the amplitude sqrt(2/(pi |x|)).
        const double tolerance = 1e-7 + 1.2e-7 * std::sqrt(std::abs(x));
        EXPECT_NEAR(gpu[i][0], besselJ0(x), tolerance) << x;
        EXPECT_NEAR(gpu[i][1], besselJ1(x), tolerance) << x;
    }
}

TEST(GlslFunctions, SrgbDecodeAndDayNightMatchCore) {
    std::vector<std::array<float, 4>> in;
    for (float e : {0.0f, 0.01f, 0.04f, 0.0405f, 0.05f, 0.2f, 0.5f, 0.999f, 1.0f})
        in.push_back({e, e * 0.5f, 1.0f - e, 0});
    const auto dec =
        probeFunction(views::srgbDecodeGlsl(),
                      "vec3 c = lcSrgbDecode(lcIn.xyz); lcOut[0] = c.x; lcOut[1] = c.y; lcOut[2] = c.z;", 3, in);
    for (std::size_t i = 0; i < in.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(dec[i][std::size_t(c)], colour::srgbDecode(in[i][std::size_t(c)]), 1e-6) << i;
    // lcDayNight takes the light with its ambient term, dayNightColour without it.
    const Vec3 day(0.6, 0.5, 0.3), night(0.9, 0.8, 0.2);
    std::vector<std::array<float, 4>> lights;
    for (double l : {0.0, 0.05, 0.1, 0.19, 0.25, 1.0}) lights.push_back({float(l), float(0.8 * l), float(1.2 * l), 0});
    const auto gpu =
        probeFunction(views::dayNightGlsl(),
                      "vec3 c = lcDayNight(vec3(0.6, 0.5, 0.3), vec3(0.9, 0.8, 0.2), lcIn.xyz + vec3(0.08));"
                      "lcOut[0] = c.x; lcOut[1] = c.y; lcOut[2] = c.z;",
                      3, lights);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Vec3 cpu = dayNightColour(day, &night, Vec3(lights[i][0], lights[i][1], lights[i][2]));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[i][std::size_t(c)], cpu(c), 1e-6) << i;
    }
}

// The post-rendering formulas (core/render/post_render.hpp) and the display encode, generated for
// the GPU post-renderer: float against double, so 1e-6 (values of order 1) or 1e-6 relative (D T).
// Sample points avoid the edges (window ends, blink switch, u = integer), where a float rounding
// may fall on either side.
TEST(GlslFunctions, PostRenderFormulasMatchCore) {
    std::vector<std::array<float, 4>> in;
    for (float t : {-7.3f, -2.1f, -0.6f, 0.35f, 1.6f, 4.2f})
        for (float u : {0.05f, 0.43f, 0.91f}) in.push_back({t, u, 1.0f - 0.8f * u, 0.37f + 0.1f * t});
    const auto gpu = probeFunction(views::postRenderGlsl(),
                                   "vec2 uv = lcRetexturedUv(lcIn.yz, vec2(0.3, -0.15), vec2(2.5, 0.7));"
                                   "lcOut[0] = uv.x; lcOut[1] = uv.y;"
                                   "lcOut[2] = lcInsideTimeWindow(lcIn.x, vec2(-2.5, 1.0));"
                                   "lcOut[3] = lcBlinkLevel(lcIn.x, vec4(1.7, 0.4, -0.2, 0.15));"
                                   "lcOut[4] = lcShiftedTemperature(lcIn.w, 9000.0);"
                                   "vec3 e = lcSrgbEncodeDisplay(vec3(lcIn.y - 0.1, lcIn.z * 1.3, 0.002));"
                                   "lcOut[5] = e.x; lcOut[6] = e.y; lcOut[7] = e.z;",
                                   8, in);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const double t = in[i][0], u = in[i][1], v = in[i][2], d = in[i][3];
        const Eigen::Vector2d uv = retexturedUv<double>(u, v, 0.3, -0.15, 2.5, 0.7);
        EXPECT_NEAR(gpu[i][0], uv(0), 1e-6) << i;
        EXPECT_NEAR(gpu[i][1], uv(1), 1e-6) << i;
        EXPECT_EQ(gpu[i][2], insideTimeWindow<double>(t, -2.5, 1.0)) << i;
        EXPECT_EQ(gpu[i][3], float(blinkLevel<double>(t, 1.7, 0.4, -0.2, 0.15))) << i;
        EXPECT_NEAR(gpu[i][4], shiftedTemperature<double>(d, 9000.0), 1e-6 * 9000 * std::abs(d) + 1e-3) << i;
        const double linear[3] = {u - 0.1, v * 1.3, 0.002};
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[i][5 + c], colour::srgbEncodeDisplay(linear[c]), 1e-6) << i;
    }
    // The clamp of D T to the Planck colour's range, on both sides.
    EXPECT_EQ(shiftedTemperature<double>(0.01, 9000.0), kShadeMinTemperature);
    EXPECT_EQ(shiftedTemperature<double>(2000.0, 9000.0), kShadeMaxTemperature);
}

// The image texture's lookup (lc::ImageTexture::sample): where (u, v) falls in texel units (u
// wrapping, also for u < 0 and u > 1; v clamped at both ends) and the bilinear blend.
TEST(GlslFunctions, TexelPositionAndBilinearMatchImageTexture) {
    std::vector<std::array<float, 4>> in;
    for (float u : {-1.3f, -0.02f, 0.0f, 0.37f, 0.999f, 2.61f})
        for (float v : {-0.4f, 0.0f, 0.52f, 1.0f, 1.7f}) in.push_back({u, v, 0.25f + 0.1f * u, 0.8f - 0.3f * v});
    const auto gpu =
        probeFunction(views::textureSampleGlsl(),
                      "vec2 p = lcTexelPosition(lcIn.xy, vec2(37.0, 12.0)); lcOut[0] = p.x; lcOut[1] = p.y;"
                      "vec3 c = lcBilinear(vec3(1.0, 0.0, 0.2), vec3(0.0, 1.0, 0.4), vec3(0.5, 0.5, 0.6),"
                      " vec3(0.1, 0.9, 0.8), fract(lcIn.zw));"
                      "lcOut[2] = c.x; lcOut[3] = c.y; lcOut[4] = c.z;",
                      5, in);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const Eigen::Vector2d p = texelPosition<double>(in[i][0], in[i][1], 37.0, 12.0);
        EXPECT_NEAR(gpu[i][0], p(0), 1e-5 * 37) << i;
        EXPECT_NEAR(gpu[i][1], p(1), 1e-5 * 12) << i;
        const double fx = in[i][2] - std::floor(in[i][2]), fy = in[i][3] - std::floor(in[i][3]);
        const Vec3 c =
            bilinear<double>(Vec3(1, 0, 0.2), Vec3(0, 1, 0.4), Vec3(0.5, 0.5, 0.6), Vec3(0.1, 0.9, 0.8), fx, fy);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(gpu[i][2 + std::size_t(k)], c(k), 1e-6) << i;
    }
    // The texel addressing: whole-numbered x wraps, y is clamped, exactly on both sides (a texel
    // index off by one would fetch the next texture's rows in the atlas).
    std::vector<std::array<float, 4>> texels;
    for (float w : {1.0f, 3.0f, 37.0f, 4096.0f, 16383.0f})
        for (float x : {-2.0f * w - 1, -w, -1.0f, 0.0f, 1.0f, w - 1, w, w + 1, 3 * w - 1})
            for (float y : {-5.0f, 0.0f, 11.0f, 12.0f, 40.0f}) texels.push_back({x, y, w, 12.0f});
    const auto addressed =
        probeFunction(views::textureSampleGlsl(),
                      "vec2 t = lcTexelIndex(lcIn.xy, lcIn.zw); lcOut[0] = t.x; lcOut[1] = t.y;", 2, texels);
    for (std::size_t i = 0; i < texels.size(); ++i) {
        const auto [x, y, w, h] = texels[i];
        const int wi = static_cast<int>(w), xi = static_cast<int>(x);
        EXPECT_EQ(addressed[i][0], float(((xi % wi) + wi) % wi)) << "x " << x << ", width " << w;
        EXPECT_EQ(addressed[i][1], std::clamp(y, 0.0f, h - 1)) << "y " << y;
        const Eigen::Vector2d t = texelIndex<double>(x, y, w, h);
        EXPECT_EQ(t(0), double(((xi % wi) + wi) % wi)) << "x " << x << ", width " << w;
        EXPECT_EQ(t(1), std::clamp(double(y), 0.0, double(h) - 1));
    }
    // The core function is the image texture's: a 2 x 1 image sampled between its texels.
    const ImageTexture image(2, 1, {0, 0, 0, 1, 1, 1});
    EXPECT_NEAR(image.sample(0.5, 0.5)(0), 0.5, 1e-12);
    EXPECT_NEAR(image.sample(0.0, 0.5)(0), 0.5, 1e-12);  // u wraps: halfway between the last and first texel
}

// Aberration up to gamma = 22 (beta = 0.999): in float, 1 - beta.k loses digits as beta -> 1, so
// the tolerance is ~100 ulp of gamma^2 (the amplification of a unit vector's round-off).
TEST(GlslFunctions, SrAberrationMatchesAberrateToRest) {
    std::vector<std::array<float, 4>> in;
    std::vector<Vec3> betas, ks;
    for (const Vec3& beta : {Vec3(0.5, 0, 0), Vec3(0, 0.9, 0.1), Vec3(-0.6, 0.5, 0.3), Vec3(0.999, 0, 0)})
        for (const Vec3& k : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0.3, 0.4, -0.866), Vec3(0, 0, 1)}) {
            const Vec3 kn = k.normalized();
            betas.push_back(beta);
            ks.push_back(kn);
            in.push_back({float(kn(0)), float(kn(1)), float(kn(2)), 0});
        }
    std::vector<std::vector<float>> gpu;
    for (std::size_t i = 0; i < in.size(); ++i) {
        std::ostringstream body;
        body.precision(9);
        body << "vec3 r = lcAberrateToRest(vec3(" << float(betas[i](0)) << ", " << float(betas[i](1)) << ", "
             << float(betas[i](2)) << "), lcIn.xyz); lcOut[0] = r.x; lcOut[1] = r.y; lcOut[2] = r.z;";
        gpu.push_back(probeFunction(views::aberrationGlsl(), body.str(), 3, {in[i]})[0]);
    }
    for (std::size_t i = 0; i < in.size(); ++i) {
        const Vec3 beta(float(betas[i](0)), float(betas[i](1)), float(betas[i](2)));
        const Vec3 cpu = sr::aberrateToRest(beta, Vec3(in[i][0], in[i][1], in[i][2]));
        const double gamma2 = 1 / (1 - beta.squaredNorm());
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(gpu[i][std::size_t(c)], cpu(c), 1e-5 * gamma2) << "beta " << beta.transpose() << " k " << i;
    }
}

// The rest-frame hit of local ray tracing and the flat hit of polygon distortion against
// lc::sr::makeRestRay + intersectRest and lc::sr::intersectFlat, for a triangle moving at 0.6 c.
TEST(GlslFunctions, SrTriangleHitsMatchCore) {
    const Vec3 beta(0.6, 0.1, 0);
    const sr::MovingFrame frame(beta, Vec3(0, 0, -5));
    const Vec4 observer(0, 0, 0, 0);
    const sr::RestTriangle tri{{Vec3(-3, -3, 0), Vec3(4, -3, 0.5), Vec3(-3, 4, -0.5)},
                               {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)}};
    const Vec4 obs = frame.eventToRest(observer);
    std::ostringstream decl;
    decl.precision(9);
    decl << views::restRayGlsl() << views::srTriangleHitsGlsl() << views::glslSource("sr_rest_ray_hit")
         << views::glslSource("sr_flat_hit");
    std::ostringstream body;
    body.precision(9);
    auto vec3 = [&body](const Vec3& v) {
        body << "vec3(" << float(v(0)) << ", " << float(v(1)) << ", " << float(v(2)) << ")";
    };
    body << "float s, D, u, v; bool hit = lcRestRayHit(normalize(lcIn.xyz), ";
    vec3(beta);
    body << ", ";
    vec3(obs.tail<3>());
    for (const Vec3& p : tri.p) {
        body << ", ";
        vec3(p);
    }
    body << ", s, D, u, v); lcOut[0] = hit ? 1.0 : 0.0; lcOut[1] = s; lcOut[2] = D; lcOut[3] = u; lcOut[4] = v;"
            "float fs, fu, fv; lcFlatHit(normalize(lcIn.xyz), ";
    vec3(tri.p[0] - obs.tail<3>());
    body << ", ";
    vec3(tri.p[1] - obs.tail<3>());
    body << ", ";
    vec3(tri.p[2] - obs.tail<3>());
    body << ", fs, fu, fv); lcOut[5] = fs; lcOut[6] = fu; lcOut[7] = fv;";
    std::vector<std::array<float, 4>> in;
    std::vector<Vec3> dirs;
    for (double a = -1.5; a <= 1.51; a += 0.3)
        for (double b = -1.5; b <= 1.51; b += 0.3) {
            const Vec3 d = Vec3(a, b, -1).normalized();
            dirs.push_back(d);
            in.push_back({float(d(0)), float(d(1)), float(d(2)), 0});
        }
    const auto gpu = probeFunction(decl.str(), body.str(), 8, in);
    int hits = 0;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const Vec3 d = Vec3(in[i][0], in[i][1], in[i][2]).normalized();
        const sr::RestRay ray = sr::makeRestRay(frame, observer, d);
        const auto cpu = sr::intersectRest(tri, ray);
        ASSERT_EQ(gpu[i][0] == 1.0f, cpu.has_value()) << "direction " << d.transpose();
        // The flat hit in the rest frame: from the rest-frame observer along the rest direction.
        const auto flat = sr::intersectFlat(
            {tri.p[0] - obs.tail<3>(), tri.p[1] - obs.tail<3>(), tri.p[2] - obs.tail<3>()}, Vec3::Zero(), d);
        if (flat) {
            EXPECT_NEAR(gpu[i][5], flat->distance, 2e-5 * flat->distance);
            EXPECT_NEAR(gpu[i][6], flat->barycentric(1), 2e-5);
            EXPECT_NEAR(gpu[i][7], flat->barycentric(2), 2e-5);
        }
        if (!cpu) continue;
        ++hits;
        EXPECT_NEAR(gpu[i][1], cpu->sigma, 2e-5 * cpu->sigma);
        EXPECT_NEAR(gpu[i][2], ray.doppler, 2e-5 * ray.doppler);
        EXPECT_NEAR(gpu[i][3], cpu->barycentric(1), 2e-5);
        EXPECT_NEAR(gpu[i][4], cpu->barycentric(2), 2e-5);
    }
    EXPECT_GT(hits, 3);
    EXPECT_LT(hits, static_cast<int>(in.size()));  // some rays miss: the test sees both outcomes
}

std::vector<float> floats(const Vec3& v) { return {float(v(0)), float(v(1)), float(v(2))}; }

// The launch momentum of the GPU tracer against lc::LocalFrame::pastNullMomentum: a static
// observer's frame near a Kerr hole, several directions; then the null condition as the oracle
// independent of both (g^{-1}(p, p) = 0 for the momentum of a light ray).
TEST(GlslFunctions, PastNullMomentumMatchesTheLocalFrame) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const Vec4 x(0, 6.0, 2.0, 1.5);
    const LocalFrame frame = LocalFrame::staticObserver(kerr, x);
    const Mat4 g = kerr.metric(x);
    auto vec4 = [](const Vec4& v) { return std::vector<float>{float(v(0)), float(v(1)), float(v(2)), float(v(3))}; };
    views::GlslProbe probe;
    probe.declarations = views::pastNullMomentumGlsl();
    probe.body =
        "vec4 p = lcPastNullMomentum(normalize(lcIn.xyz), lcE0, lcE1, lcE2, lcE3, lcG0, lcG1, lcG2, lcG3); "
        "for (int k = 0; k < 4; ++k) lcOut[k] = p[k];";
    probe.outputs = 4;
    probe.uniforms = {{"lcE0", vec4(frame.e[0])}, {"lcE1", vec4(frame.e[1])}, {"lcE2", vec4(frame.e[2])},
                      {"lcE3", vec4(frame.e[3])}, {"lcG0", vec4(g.row(0))},   {"lcG1", vec4(g.row(1))},
                      {"lcG2", vec4(g.row(2))},   {"lcG3", vec4(g.row(3))}};
    const std::vector<Vec3> directions{Vec3(1, 0, 0), Vec3(-1, 0.2, 0.1), Vec3(0.3, -0.8, 0.5), Vec3(0, 0, -1)};
    std::vector<std::array<float, 4>> in;
    for (const Vec3& n : directions) in.push_back({float(n(0)), float(n(1)), float(n(2)), 0});
    const auto gpu = views::evaluateOnGpu(probe, in);
    const Mat4 gInverse = g.inverse();
    for (std::size_t k = 0; k < directions.size(); ++k) {
        const Vec4 cpu = frame.pastNullMomentum(kerr, directions[k]);
        Vec4 p;
        for (int c = 0; c < 4; ++c) {
            p(c) = gpu[k][std::size_t(c)];
            EXPECT_NEAR(p(c), cpu(c), 2e-5 * (1 + std::abs(cpu(c)))) << "direction " << directions[k].transpose();
        }
        EXPECT_NEAR(p.dot(gInverse * p) / p.squaredNorm(), 0.0, 1e-5) << "null";
        EXPECT_NEAR(cpu.dot(gInverse * cpu) / cpu.squaredNorm(), 0.0, 1e-12) << "null";
    }
}

// The pixel directions of both projections against lc::Camera::direction, with the uniforms the
// geodesic renderer sets (the frame of forward and up, tangents or half angles of the field).
TEST(GlslFunctions, CameraDirectionMatchesCamera) {
    for (const auto projection : {Camera::Projection::Pinhole, Camera::Projection::Panorama}) {
        Camera cam;
        cam.projection = projection;
        cam.width = 64;
        cam.height = 32;
        cam.fovXDeg = projection == Camera::Projection::Pinhole ? 100 : 360;
        cam.fovYDeg = projection == Camera::Projection::Pinhole ? 60 : 170;
        cam.forward = Vec3(1, 0.4, 0.3);
        cam.up = Vec3(0, 0.1, 1);
        const Vec3 f = cam.forward.normalized(), r = f.cross(cam.up).normalized(), u = r.cross(f);
        const double deg = kPi / 180;
        views::GlslProbe probe;
        probe.declarations = views::cameraDirectionsGlsl() + views::glslSource("camera_direction");
        probe.body = "vec3 d = lcCameraDirection(lcIn.xy); lcOut[0] = d.x; lcOut[1] = d.y; lcOut[2] = d.z;";
        probe.outputs = 3;
        probe.uniforms = {{"lcWidth", {float(cam.width)}},
                          {"lcHeight", {float(cam.height)}},
                          {"lcForward", floats(f)},
                          {"lcRight", floats(r)},
                          {"lcUp", floats(u)},
                          {"lcTanHalfX", {float(std::tan(0.5 * cam.fovXDeg * deg))}},
                          {"lcTanHalfY", {float(std::tan(0.5 * cam.fovYDeg * deg))}},
                          {"lcHalfX", {float(0.5 * cam.fovXDeg * deg)}},
                          {"lcHalfY", {float(0.5 * cam.fovYDeg * deg)}}};
        probe.intUniforms = {{"lcProjection", projection == Camera::Projection::Pinhole ? 0 : 1}};
        std::vector<std::array<float, 4>> in;
        std::vector<std::pair<int, int>> pixels{{0, 0}, {63, 0}, {0, 31}, {63, 31}, {32, 16}, {10, 25}};
        for (const auto& [i, j] : pixels) in.push_back({i + 0.5f, cam.height - j - 0.5f, 0, 0});  // window coordinates
        const auto gpu = views::evaluateOnGpu(probe, in);
        for (std::size_t k = 0; k < pixels.size(); ++k) {
            const Vec3 cpu = cam.direction(pixels[k].first, pixels[k].second);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(gpu[k][std::size_t(c)], cpu(c), 2e-6)
                    << "pixel " << pixels[k].first << ", " << pixels[k].second;
        }
    }
}

// The inverse, the projection the Goedel mapper's vertex shader calls (glsl/godel_projection):
// the generated lcPinholeHomogeneous and lcPanoramaScreen against lc::Camera::project's screen
// offsets, for directions all round the sky (behind the pinhole too: w < 0 there, as project's
// refusal), near the poles of the panorama and at its +-180 degree seam.
TEST(GlslFunctions, CameraProjectionMatchesCameraProject) {
    Camera cam;
    cam.width = 64;
    cam.height = 32;
    cam.forward = Vec3(1, 0.4, 0.3);
    cam.up = Vec3(0, 0.1, 1);
    const Vec3 f = cam.forward.normalized(), r = f.cross(cam.up).normalized(), u = r.cross(f);
    std::vector<Vec3> directions{f,
                                 -f,
                                 r,
                                 u,
                                 (f + 0.3 * r - 0.2 * u).normalized(),
                                 Vec3(0.3, -0.8, 0.5).normalized(),
                                 (u + 1e-3 * f).normalized(),
                                 (-f + 1e-4 * r).normalized(),
                                 (-f - 1e-4 * r).normalized()};
    std::vector<std::array<float, 4>> in;
    for (const Vec3& d : directions) in.push_back({float(d(0)), float(d(1)), float(d(2)), 0});
    const double deg = kPi / 180;
    for (const auto projection : {Camera::Projection::Pinhole, Camera::Projection::Panorama}) {
        SCOPED_TRACE(projection == Camera::Projection::Pinhole ? "pinhole" : "panorama");
        cam.projection = projection;
        cam.fovXDeg = projection == Camera::Projection::Pinhole ? 100 : 360;
        cam.fovYDeg = projection == Camera::Projection::Pinhole ? 60 : 170;
        views::GlslProbe probe;
        probe.declarations = views::cameraProjectionGlsl();
        probe.body = projection == Camera::Projection::Pinhole
                         ? "vec3 h = lcPinholeHomogeneous(lcIn.xyz, lcF, lcR, lcU, lcA, lcB);"
                           "lcOut[0] = h.x; lcOut[1] = h.y; lcOut[2] = h.z;"
                         : "vec2 s = lcPanoramaScreen(lcIn.xyz, lcF, lcR, lcU, lcA, lcB);"
                           "lcOut[0] = s.x; lcOut[1] = s.y; lcOut[2] = 1.0;";
        probe.outputs = 3;
        const bool pinhole = projection == Camera::Projection::Pinhole;
        probe.uniforms = {{"lcF", floats(f)},
                          {"lcR", floats(r)},
                          {"lcU", floats(u)},
                          {"lcA", {float(pinhole ? std::tan(0.5 * cam.fovXDeg * deg) : 0.5 * cam.fovXDeg * deg)}},
                          {"lcB", {float(pinhole ? std::tan(0.5 * cam.fovYDeg * deg) : 0.5 * cam.fovYDeg * deg)}}};
        const auto gpu = views::evaluateOnGpu(probe, in);
        int compared = 0;
        for (std::size_t k = 0; k < directions.size(); ++k) {
            const Vec3 d(in[k][0], in[k][1], in[k][2]);  // the float-rounded direction the GPU saw
            double x = 0, y = 0;
            const bool inFront = cam.project(d, x, y);
            if (pinhole) {
                EXPECT_EQ(gpu[k][2] > 0, inFront) << "direction " << k;
            }
            if (!inFront) continue;
            const double sx = 2 * x / cam.width - 1, sy = 1 - 2 * y / cam.height;
            const double gx = gpu[k][0] / gpu[k][2], gy = gpu[k][1] / gpu[k][2];
            if (!pinhole && std::abs(d.dot(u)) > 1 - 1e-6) {  // a pole: no azimuth to compare
                EXPECT_NEAR(gy, sy, 1e-5 * (1 + std::abs(sy))) << "direction " << k;
                ++compared;
                continue;
            }
            // At the seam (k = 7, 8: just left and right of straight behind) the azimuth is +-pi:
            // the side must agree, which a float error of 1e-4 rad could not flip.
            EXPECT_NEAR(gx, sx, 1e-5 * (1 + std::abs(sx))) << "direction " << k;
            EXPECT_NEAR(gy, sy, 1e-5 * (1 + std::abs(sy))) << "direction " << k;
            ++compared;
        }
        EXPECT_GE(compared, pinhole ? 4 : 9);
    }
}

// The projection of the polygon-distortion vertex shader (glsl/sr_polygon_vertex: the generated
// lcPinholeHomogeneous taken as clip coordinates) and the footprint quads' pixel placement
// (glsl/sr_pixel_clip, GL's viewport transform inverted) against lc::Camera::project's pixel
// coordinates, with non-square pixels, for directions in view, outside the image and behind the
// camera (w < 0 there, as project's refusal).
TEST(GlslFunctions, SrPixelProjectionMatchesCameraProject) {
    Camera cam;
    cam.width = 80;
    cam.height = 40;
    cam.fovXDeg = 100;
    cam.fovYDeg = 60;
    cam.forward = Vec3(0.2, 0.1, -1);
    cam.up = Vec3(0, 1, 0);
    const Camera::Axes b = cam.axes();
    const Vec2 t = cam.halfFieldTangents();
    const std::vector<Vec3> directions{b.forward,
                                       -b.forward,
                                       (b.forward + 0.3 * b.right - 0.2 * b.up).normalized(),
                                       Vec3(0.3, -0.8, -0.5).normalized(),
                                       (b.forward + 3.0 * b.right + 2.0 * b.up).normalized(),
                                       (b.right - 1e-3 * b.forward).normalized(),
                                       Vec3(-7.5, 2.25, -30.0)};  // not unit: a vertex relative to the eye
    std::vector<std::array<float, 4>> in;
    for (const Vec3& d : directions) in.push_back({float(d(0)), float(d(1)), float(d(2)), 0});
    views::GlslProbe probe;
    probe.declarations = views::cameraProjectionGlsl() + views::glslSource("sr_pixel_clip");
    probe.body =
        "vec3 h = lcPinholeHomogeneous(lcIn.xyz, lcForward, lcRight, lcUp, lcTanHalfX, lcTanHalfY);"
        "vec4 p = lcPixelClip(vec3(lcIn.x, lcIn.y, 1.0));"
        "lcOut[0] = h.x; lcOut[1] = h.y; lcOut[2] = h.z; lcOut[3] = p.x / p.w; lcOut[4] = p.y / p.w;";
    probe.outputs = 5;
    probe.uniforms = {{"lcForward", floats(b.forward)}, {"lcRight", floats(b.right)},   {"lcUp", floats(b.up)},
                      {"lcTanHalfX", {float(t.x())}},   {"lcTanHalfY", {float(t.y())}}, {"lcWidth", {float(cam.width)}},
                      {"lcHeight", {float(cam.height)}}};
    const auto gpu = views::evaluateOnGpu(probe, in);
    int inFront = 0;
    for (std::size_t k = 0; k < directions.size(); ++k) {
        const Vec3 d(in[k][0], in[k][1], in[k][2]);  // the float-rounded direction the GPU saw
        // sr_pixel_clip: pixel (x, y) from the top-left to NDC, x from -1 to 1, y from 1 (top) to -1.
        EXPECT_NEAR(gpu[k][3], 2 * d.x() / cam.width - 1, 1e-5 * (1 + std::abs(d.x())));
        EXPECT_NEAR(gpu[k][4], 1 - 2 * d.y() / cam.height, 1e-5 * (1 + std::abs(d.y())));
        double px = 0, py = 0;
        const bool front = cam.project(d, px, py);
        EXPECT_EQ(gpu[k][2] > 0, front) << "direction " << k;
        if (!front) continue;
        ++inFront;
        // Normalised device coordinates of the clip position (h.x, h.y, 0, h.z) against project's pixels.
        EXPECT_NEAR(gpu[k][0] / gpu[k][2], 2 * px / cam.width - 1, 1e-5 * (1 + std::abs(px))) << "direction " << k;
        EXPECT_NEAR(gpu[k][1] / gpu[k][2], 1 - 2 * py / cam.height, 1e-5 * (1 + std::abs(py))) << "direction " << k;
    }
    EXPECT_GE(inFront, 4);
}

// The shading of both SR techniques against SrRenderer's: the generated lcSrShading against
// lc::sr::srShading (the Phong factor in the emitter's rest frame and the observed temperature),
// and the glue glsl/sr_shade, which feeds it the object's and options' uniforms and looks the
// temperature up in the Planck texture, against clamp(factor BlackbodyTable::lookup(T)); for
// emitted and reflected light, Doppler and shading on and off, up to beta = 0.9, from all sides.
TEST(GlslFunctions, SrShadingMatchesCore) {
    struct Case {
        Vec3 beta;
        Vec3 n0, n1, n2;
        Eigen::Vector4d material;
        Vec3 lightRel;
        double D, T, lightT, u, v, shading, doppler, reflected;
    };
    const std::vector<Case> cases{
        {Vec3(0.5, 0, 0),
         Vec3(0, 0, 1),
         Vec3(0, 0.6, 0.8),
         Vec3(0.6, 0, 0.8),
         {0.25, 0.75, 0.2, 32},
         Vec3(0, 10, 10),
         1.4,
         6000,
         6000,
         0.2,
         0.3,
         1,
         1,
         0},
        {Vec3(-0.3, 0.8, 0.1),
         Vec3(1, 0, 0),
         Vec3(0, 1, 0),
         Vec3(0, 0, 1),
         {0.1, 0.9, 0.5, 8},
         Vec3(-4, 3, 2),
         0.7,
         4500,
         3000,
         0.6,
         0.1,
         1,
         1,
         1},
        {Vec3(0.9, 0, 0),
         Vec3(0, -1, 0),
         Vec3(0, -1, 0),
         Vec3(0, -1, 0),
         {0.3, 0.6, 0.4, 64},
         Vec3(5, -10, 0),
         2.6,
         8000,
         6000,
         0.0,
         0.0,
         1,
         0,
         1},
        {Vec3(0, 0, -0.7),
         Vec3(0.2, 0.3, 0.9),
         Vec3(-0.2, 0.3, 0.9),
         Vec3(0, -0.4, 0.9),
         {0.2, 0.7, 0.1, 16},
         Vec3(1, 1, 1),
         0.5,
         5000,
         6000,
         0.3,
         0.3,
         0,
         1,
         0},
    };
    std::vector<std::array<float, 4>> in;
    for (const Vec3& d : {Vec3(0.1, 0.2, -1), Vec3(-0.4, 0.1, -1), Vec3(0.3, -0.5, -0.8), Vec3(0.9, 0.1, 0.2)}) {
        const Vec3 dn = d.normalized();
        in.push_back({float(dn(0)), float(dn(1)), float(dn(2)), 7.5f});
    }
    views::PlanckTexture planck;
    const auto f = [](double x) { return double(float(x)); };
    const auto fv = [&f](const Vec3& x) { return Vec3(f(x(0)), f(x(1)), f(x(2))); };
    int lit = 0;
    for (std::size_t c = 0; c < cases.size(); ++c) {
        const Case& k = cases[c];
        views::GlslProbe probe;
        probe.declarations = views::srShadingGlsl() + views::planckLookupGlsl() + views::glslSource("sr_shade");
        probe.body =
            "vec2 s = lcSrShading(lcIn.xyz, lcIn.w, lcD, lcU, lcV, lcN0, lcN1, lcN2, lcBeta, lcTemperature, lcMaterial,"
            " lcLightRel, lcLightT, float(lcShading), float(lcDoppler), float(lcReflected));"
            "lcOut[0] = s.x; lcOut[1] = s.y;"
            "vec3 c = lcShade(lcIn.xyz, lcIn.w, lcD, lcU, lcV, lcN0, lcN1, lcN2);"
            "lcOut[2] = c.x; lcOut[3] = c.y; lcOut[4] = c.z;";
        probe.outputs = 5;
        const Eigen::Vector4d& m = k.material;
        // What glsl/sr_uniforms declares for the mappers (the probe declares them here).
        probe.uniforms = {{"lcD", {float(k.D)}},
                          {"lcU", {float(k.u)}},
                          {"lcV", {float(k.v)}},
                          {"lcN0", floats(k.n0)},
                          {"lcN1", floats(k.n1)},
                          {"lcN2", floats(k.n2)},
                          {"lcBeta", floats(k.beta)},
                          {"lcTemperature", {float(k.T)}},
                          {"lcMaterial", {float(m(0)), float(m(1)), float(m(2)), float(m(3))}},
                          {"lcLightRel", floats(k.lightRel)},
                          {"lcLightT", {float(k.lightT)}}};
        probe.intUniforms = {
            {"lcShading", int(k.shading)}, {"lcDoppler", int(k.doppler)}, {"lcReflected", int(k.reflected)}};
        probe.planck = &planck;
        const auto gpu = views::evaluateOnGpu(probe, in);
        for (std::size_t i = 0; i < in.size(); ++i) {
            const Vec3 d(in[i][0], in[i][1], in[i][2]);
            const Eigen::Vector2d cpu =
                sr::srShading<double>(d, f(in[i][3]), f(k.D), f(k.u), f(k.v), fv(k.n0), fv(k.n1), fv(k.n2), fv(k.beta),
                                      f(k.T), Eigen::Vector4d(f(m(0)), f(m(1)), f(m(2)), f(m(3))), fv(k.lightRel),
                                      f(k.lightT), k.shading, k.doppler, k.reflected);
            // Factor: float rounding amplified by the specular power (up to 64) and by gamma^2.
            EXPECT_NEAR(gpu[i][0], cpu(0), 2e-4 * (1 + cpu(0))) << "case " << c << " direction " << i;
            EXPECT_NEAR(gpu[i][1], cpu(1), 2e-5 * cpu(1)) << "case " << c << " direction " << i;
            // The colour: the table interpolated by GL's filter (8-bit weights: 1e-4, as the Planck
            // test) times the factor with its own float error.
            const Vec3 rgb = (cpu(0) * planck.table().lookup(cpu(1), colour::ToneMap::ColourOnly)).cwiseMin(1.0);
            for (int q = 0; q < 3; ++q)
                EXPECT_NEAR(gpu[i][std::size_t(2 + q)], rgb(q), 1e-4 + 2e-4 * cpu(0))
                    << "case " << c << " direction " << i << " channel " << q;
            lit += cpu(0) > m(0) + 1e-3;  // diffuse or specular light seen, not only ambient
        }
    }
    EXPECT_GT(lit, 3);
}

// The Planck lookup texture and its GLSL against lc::colour::BlackbodyTable::lookup, both tone
// maps, from below the table to above it. GL's linear filter weights carry 8 fractional bits
// on llvmpipe, so between two texels the GPU may be off by 1/512 of their difference (< 1e-5
// here); we allow 1e-4.
TEST(GlslFunctions, PlanckLookupMatchesBlackbodyTable) {
    views::PlanckTexture planck;
    std::vector<std::array<float, 4>> in;
    for (float T : {500.f, 1000.f, 1500.f, 2700.f, 4000.f, 5778.f, 6500.f, 10000.f, 23456.f, 59000.f, 80000.f})
        in.push_back({T, 0, 0, 0});
    for (const auto map : {colour::ToneMap::ColourOnly, colour::ToneMap::ReferenceLog}) {
        views::GlslProbe probe;
        probe.declarations = views::planckLookupGlsl();
        probe.body = "vec3 c = lcPlanckLookup(lcIn.x); lcOut[0] = c.x; lcOut[1] = c.y; lcOut[2] = c.z;";
        probe.outputs = 3;
        probe.planck = &planck;
        probe.planckToneMap = map;
        const auto gpu = views::evaluateOnGpu(probe, in);
        for (std::size_t i = 0; i < in.size(); ++i) {
            const Vec3 cpu = planck.table().lookup(in[i][0], map);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[i][std::size_t(c)], cpu(c), 1e-4) << "T = " << in[i][0] << " K";
        }
    }
}

}  // namespace

// The thin disk's generated formulas (views::diskGlsl) against their core templates: the
// Boyer-Lindquist radius of Kerr-Schild points (on and off the equator, inside the ergoregion),
// the Keplerian redshift of ThinDiskModel's orbits, and the local temperature from g and intensity.
TEST(GlslFunctions, DiskFormulasMatchCore) {
    const double a = 0.9;
    const ThinDiskModel disk(std::make_shared<KerrNewman>(1.0, a, 0.0), 0, 30, true);
    const std::vector<std::array<float, 4>> in{
        {2.5f, 0.4f, 0.0f, 0}, {6.0f, -3.0f, 0.0f, 0}, {1.4f, 0.9f, 0.3f, 0}, {20.0f, 7.0f, -5.0f, 0}};
    views::GlslProbe probe;
    probe.declarations = views::diskRadiusGlsl(disk.radiusExpression()) + views::diskGlsl();
    probe.body =
        "vec4 x = vec4(0.0, lcIn.xyz); vec4 p = vec4(-1.0, 0.3, -0.7, 0.2);"
        "lcOut[0] = lcDiskRadius(x);"
        "lcOut[1] = lcKeplerianRedshift(x, p, lcOmega, lcUt, -1.0);"
        "lcOut[2] = lcDiskLocalTemperature(9000.0, 0.7, 1.2);";
    probe.outputs = 3;
    const CircularOrbit o = disk.orbit(8.0);
    probe.uniforms = {{"lcOmega", {float(o.omega)}}, {"lcUt", {float(o.ut)}}};
    const auto gpu = views::evaluateOnGpu(probe, in);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const Vec4 x(0, in[i][0], in[i][1], in[i][2]), p(-1, 0.3, -0.7, 0.2);
        const double r = kerrSchildRadius<double>(x(1), x(2), x(3), a);
        EXPECT_NEAR(gpu[i][0], r, 1e-5 * r) << i;
        const double g = keplerianRedshift<double>(x, p, o.omega, o.ut, -1.0);
        EXPECT_NEAR(gpu[i][1], g, 1e-5 * std::abs(g)) << i;
        const double T = diskLocalTemperature<double>(9000, 0.7, 1.2);
        EXPECT_NEAR(gpu[i][2], T, 1e-5 * T);
    }
}
