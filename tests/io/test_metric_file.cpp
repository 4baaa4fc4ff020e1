// SPDX-License-Identifier: BSD-3-Clause
// Metrics written as text, read from metric files (data/metrics/) and from scenes: every shipped
// metric file loads and is Lorentzian where its scenes put observers; a scene that names the
// formula Kerr, Schwarzschild, Alcubierre or Goedel renders the same per-pixel image as the same
// scene with the built-in metric (the built-ins are the independent reference: C++ templates
// differentiated by Eigen's automatic differentiation); errors name the file, the line, the field
// and, inside a formula, the column; rays that meet a singularity stop as such, never as NaN.
#include "core/accretion/thin_disk.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/render/render.hpp"
#include "core/scene/observer_world_line.hpp"
#include "core/spacetime/frame.hpp"
#include "core/spacetime/metric_check.hpp"
#include "core/spacetime/scattering.hpp"
#include "readers/io/metric_file.hpp"
#include "readers/io/scene_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>

using namespace lc;

namespace {

const std::string kMetricData = std::string(LIGHTCONE_SOURCE_DIR) + "/data/";

std::string formulaSceneError(const std::string& text) {
    try {
        io::parseScene(text, "scene.json", kMetricData);
    } catch (const io::InputError& e) {
        return e.what();
    }
    return "";
}

std::string formulaSceneText(const std::string& metric, const std::string& observer = "[0, 30, 0, 3]",
                             const std::string& extra = "") {
    return "{\n  \"metric\": " + metric + ",\n  \"observer\": {\"position\": " + observer +
           "},\n  \"camera\": {\"width\": 36, \"height\": 18, \"fov\": [40, 20], \"forward\": [-1, 0, -0.1], "
           "\"up\": [0, 0, 1]},\n  \"render\": {\"stepper\": \"dopri5\", \"tolerance\": 1e-10" +
           extra + "}\n}\n";
}

TEST(MetricFile, EveryShippedMetricLoadsAndIsLorentzianAwayFromItsCentre) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kMetricData + "metrics")) {
        SCOPED_TRACE(entry.path().string());
        const auto m = io::loadFormulaMetric(entry.path().string(), {});
        EXPECT_EQ(metricProblemAt(*m, Vec4(0, 5, 1, 1)), "");
        ++files;
    }
    EXPECT_GE(files, 5);
}

// The same scene with the built-in metric and with its formula: the same pixels. Sky pixels
// carry their escape direction (u, v), which agree to float rounding; kinds and stop reasons
// agree exactly. Rays that graze the photon orbit amplify round-off, so a few pixels on the
// shadow's edge may differ in u, v by more.
void expectSameImage(const std::string& builtin, const std::string& formula, const std::string& observer,
                     const std::string& extra = "") {
    SCOPED_TRACE(formula);
    const Scene a = io::parseScene(formulaSceneText(builtin, observer, extra), "builtin.json", kMetricData);
    const Scene b = io::parseScene(formulaSceneText(formula, observer, extra), "formula.json", kMetricData);
    const RenderResult ra = renderNumeric(a), rb = renderNumeric(b);
    ASSERT_EQ(ra.pixels.size(), rb.pixels.size());
    std::size_t sky = 0, apart = 0;
    for (std::size_t k = 0; k < ra.pixels.size(); ++k) {
        const PixelRecord &p = ra.pixels[k], &q = rb.pixels[k];
        EXPECT_EQ(p.kind, q.kind) << "pixel " << k;
        EXPECT_EQ(p.stopReason, q.stopReason) << "pixel " << k;
        if (p.kind != PixelRecord::Sky) continue;
        ++sky;
        apart += std::abs(p.u - q.u) > 1e-6f || std::abs(p.v - q.v) > 1e-6f;
    }
    EXPECT_LE(apart, ra.pixels.size() / 100) << "sky pixels whose direction differs by more than float rounding";
    EXPECT_EQ(rb.stats.stopCounts, ra.stats.stopCounts);
    std::printf("%s: %zu sky pixels, %zu apart; built-in %.3f s, formula %.3f s\n", formula.c_str(), sky, apart,
                ra.stats.seconds, rb.stats.seconds);
}

TEST(MetricFile, FormulaKerrSchwarzschildAlcubierreGodelReissnerNordstromRenderAsTheBuiltins) {
    expectSameImage(R"js({"name": "kerr", "M": 1, "a": 0.9})js", R"js({"file": "metrics/kerr.json", "a": 0.9})js",
                    "[0, 30, 2, 3]");
    expectSameImage(R"js({"name": "kerr", "M": 1, "a": -0.6})js", R"js({"file": "metrics/kerr.json", "a": -0.6})js",
                    "[0, 20, -8, -5]");
    expectSameImage(R"js({"name": "schwarzschild", "M": 1})js", R"js({"file": "metrics/schwarzschild.json"})js",
                    "[0, 30, 0, 3]");
    expectSameImage(R"js({"name": "alcubierre", "v": 0.5, "R": 1, "sigma": 8})js",
                    R"js({"file": "metrics/alcubierre.json", "v": 0.5, "sigma": 8})js", "[0, 0, 0, 0]");
    expectSameImage(R"js({"name": "godel", "a": 1})js", R"js({"file": "metrics/godel.json", "a": 1})js",
                    "[0, 0.3, 0.2, 0]", R"js(, "max_affine": 10)js");
    // The catalogue's Reissner-Nordstrom (spherical chart, Kerr-Schild form, issue #43) is the
    // built-in Kerr-Newman without spin, in the same time and pulled back to the same chart.
    expectSameImage(R"js({"name": "kerr-newman", "M": 1, "a": 0, "Q": 0.5})js",
                    R"js({"file": "metrics/reissner_nordstrom.json", "Q": 0.5})js", "[0, 25, 3, 4]");
}

// A formula metric that is stationary, axisymmetric and mirror-symmetric gets circular orbits
// and the thin disk from its own g: the formula Kerr (disk radius "r", Boyer-Lindquist) has
// Bardeen, Press & Teukolsky's ISCO in both senses and both spin signs and the built-in's
// Page-Thorne flux; Schwarzschild typed in spherical coordinates (its default label, the distance
// from the axis, is r on the equator) has the ISCO at 6 M; metrics without the symmetries get none.
TEST(MetricFile, FormulaMetricsWithTheSymmetriesCarryTheThinDisk) {
    for (double a : {0.9, -0.6, 0.0})
        for (bool prograde : {true, false}) {
            SCOPED_TRACE("a = " + std::to_string(a) + (prograde ? " prograde" : " retrograde"));
            const auto formula = io::loadFormulaMetric(kMetricData + "metrics/kerr.json", {{"a", a}});
            ASSERT_TRUE(formula->equatorialRadius()) << formula->whyNoCircularOrbits();
            const ThinDiskModel disk(formula, 0, 30, prograde);
            EXPECT_NEAR(disk.isco(), ThinDiskModel::bardeenIsco(a, prograde), 1e-7 * disk.isco());
            const ThinDiskModel builtin(std::make_shared<KerrNewman>(1.0, a, 0.0), 0, 30, prograde);
            for (double r : {1.01 * disk.isco(), 9.0, 29.0}) {
                EXPECT_NEAR(disk.orbit(r).omega, builtin.orbit(r).omega, 1e-12) << r;
                EXPECT_NEAR(disk.flux(r), builtin.flux(r), 1e-9 * builtin.maxFlux()) << r;
            }
            EXPECT_NEAR(disk.maxFlux(), builtin.maxFlux(), 1e-9 * builtin.maxFlux());
        }
    const auto spherical = io::loadFormulaMetric(kMetricData + "metrics/schwarzschild_spherical.json", {});
    EXPECT_NEAR(ThinDiskModel(spherical, 0, 30, true).isco(), 6.0, 1e-7);
    // The Ellis wormhole has the symmetries but no mass: a static particle is already a geodesic,
    // orbits gain no energy outwards, and there is no ISCO and no disk (said, not a made-up radius).
    const auto ellis = io::loadFormulaMetric(kMetricData + "metrics/ellis_wormhole.json", {});
    ASSERT_TRUE(ellis->equatorialRadius());
    try {
        ThinDiskModel(ellis, 0, 30, true);
        ADD_FAILURE() << "a disk around a massless wormhole must be refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("do not gain energy outwards"), std::string::npos) << e.what();
    }
    const auto warp = io::loadFormulaMetric(kMetricData + "metrics/alcubierre.json", {{"v", 0.5}});
    EXPECT_FALSE(warp->equatorialRadius());
    EXPECT_NE(warp->whyNoCircularOrbits().find("not stationary"), std::string::npos) << warp->whyNoCircularOrbits();
    EXPECT_THROW(ThinDiskModel(warp, 0, 30, true), std::invalid_argument);
    const auto godel = io::loadFormulaMetric(kMetricData + "metrics/godel.json", {{"a", 1.0}});
    EXPECT_FALSE(godel->equatorialRadius());
    EXPECT_NE(godel->whyNoCircularOrbits().find("far_field"), std::string::npos) << godel->whyNoCircularOrbits();
}

// data/kerr_disk.json and its twin with the formula Kerr (data/kerr_disk_formula.json): the same
// disk pixels, with the same emission radius, redshift and flux to rounding.
TEST(MetricFile, FormulaKerrDiskImageIsTheBuiltinsPixelForPixel) {
    auto small = [](Scene s) {
        s.camera.width = 96;
        s.camera.height = 54;
        return s;
    };
    const Scene a = small(io::readScene(kMetricData + "kerr_disk.json"));
    const Scene b = small(io::readScene(kMetricData + "kerr_disk_formula.json"));
    ASSERT_EQ(b.spacetime->name(), "kerr-formula");
    const RenderResult ra = renderNumeric(a), rb = renderNumeric(b);
    std::size_t disk = 0;
    for (std::size_t k = 0; k < ra.pixels.size(); ++k) {
        const PixelRecord &p = ra.pixels[k], &q = rb.pixels[k];
        ASSERT_EQ(p.kind, q.kind) << "pixel " << k;
        if (p.kind != PixelRecord::Disk) continue;
        ++disk;
        EXPECT_NEAR(q.diskRadius, p.diskRadius, 1e-5f * p.diskRadius) << "pixel " << k;
        EXPECT_NEAR(q.frequencyRatio, p.frequencyRatio, 1e-5f) << "pixel " << k;
        EXPECT_NEAR(q.intensity, p.intensity, 1e-5f * p.intensity + 1e-9f) << "pixel " << k;
        EXPECT_EQ(q.order, p.order) << "pixel " << k;
    }
    EXPECT_GT(disk, ra.pixels.size() / 4);
}

// Schwarzschild typed in spherical coordinates (t, r, theta, phi) and traced in its Cartesian
// pull-back, against the built-in: an observer on the polar axis looking down it, so that the
// central rays run along the axis and the rest cross it; and an observer off the axis. Pixel
// kinds and stop reasons agree exactly, escape directions to 1e-6 (the docs' promise for a chart
// change), except where rays graze the photon sphere.
TEST(MetricFile, SphericalChartHasNoSeamAtThePolarAxis) {
    for (const auto& [observer, camera] : std::vector<std::pair<std::string, std::string>>{
             {"[0, 0, 0, 30]", R"js("forward": [0, 0, -1], "up": [1, 0, 0])js"},
             {"[0, 0, 0, -25]", R"js("forward": [0.05, 0, 1], "up": [0, 1, 0])js"},
             {"[0, 12, -9, 14]", R"js("look_at": [0, 0, 0], "up": [0, 0, 1])js"}}) {
        SCOPED_TRACE(observer);
        auto text = [&](const std::string& metric) {
            return "{\"metric\": " + metric + ", \"observer\": {\"position\": " + observer +
                   "}, \"camera\": {\"width\": 41, \"height\": 41, \"fov\": [50, 50], " + camera +
                   "}, \"render\": {\"stepper\": \"dopri5\", \"tolerance\": 1e-10}}";
        };
        const Scene a = io::parseScene(text(R"js({"name": "schwarzschild", "M": 1})js"), "builtin.json", kMetricData);
        const Scene b = io::parseScene(text(R"js({"file": "metrics/schwarzschild_spherical.json"})js"),
                                       "spherical.json", kMetricData);
        const RenderResult ra = renderNumeric(a), rb = renderNumeric(b);
        std::size_t sky = 0, apart = 0, shadow = 0;
        float worst = 0;
        for (std::size_t k = 0; k < ra.pixels.size(); ++k) {
            const PixelRecord &p = ra.pixels[k], &q = rb.pixels[k];
            EXPECT_EQ(p.kind, q.kind) << "pixel " << k;
            EXPECT_EQ(p.stopReason, q.stopReason) << "pixel " << k;
            shadow += p.kind == PixelRecord::Horizon;
            if (p.kind != PixelRecord::Sky) continue;
            ++sky;
            // u, v are the sky's texture coordinates (fractions of 2 pi and pi).
            const float d = std::max(std::abs(p.u - q.u) * 6.2832f, std::abs(p.v - q.v) * 3.1416f);
            if (std::abs(p.u - q.u) > 0.5f) continue;  // the sky's seam at u = 0 = 1
            worst = std::max(worst, d);
            apart += d > 1e-6f;
        }
        std::printf("spherical chart, observer %s: %zu shadow, %zu sky pixels, worst direction %.2e rad, %zu apart\n",
                    observer.c_str(), shadow, sky, static_cast<double>(worst), apart);
        EXPECT_GT(sky, 100u);
        EXPECT_LE(apart, 4u);  // photon-sphere grazers on the shadow's rim
    }
}

TEST(MetricFile, InlineFormulaWithItsOwnParameters) {
    const Scene s = io::parseScene(formulaSceneText(R"js({"formula": {
        "name": "hayward",
        "parameters": {"M": {"default": 1, "range": [0.001, 1000]}, "l": {"default": 0.3, "range": [0, 10]}},
        "define": ["r = sqrt(x^2 + y^2 + z^2)", "m = M*r^3/(r^3 + 2*M*l^2)"],
        "ds2": "-dt^2 + dx^2 + dy^2 + dz^2 + 2*m/r*(dt - (x*dx + y*dy + z*dz)/r)^2",
        "far_field": {"mass": "M", "capture": "4*M"}}, "l": 0.5})js"),
                                   "scene.json", kMetricData);
    EXPECT_EQ(s.spacetime->name(), "hayward");
    EXPECT_EQ(s.spacetime->parameters().at("l"), 0.5);
    EXPECT_TRUE(s.spacetime->asymptoticallyFlat());
    const RenderResult r = renderNumeric(s);
    for (const PixelRecord& p : r.pixels)
        EXPECT_TRUE(std::isfinite(p.u) && std::isfinite(p.v) && std::isfinite(p.drift));
}

TEST(MetricFile, ErrorsNameFileLineFieldAndColumn) {
    const std::string typo = formulaSceneError(formulaSceneText(R"js({"formula": {
        "ds2": "-dt^2 + dx^2 + dy^2 + dz^2 + 2/rr*dt^2"}})js"));
    EXPECT_NE(typo.find("scene.json:3: field 'metric.formula.ds2': column 32: unknown name 'rr'"), std::string::npos)
        << typo;
    EXPECT_NE(typo.find("\n    -dt^2 + dx^2 + dy^2 + dz^2 + 2/rr*dt^2\n                                   ^"),
              std::string::npos)
        << typo;
    const std::string range = formulaSceneError(formulaSceneText(R"js({"file": "metrics/kerr.json", "a": 2e6})js"));
    EXPECT_NE(range.find("scene.json:2: field 'metric.a'"), std::string::npos) << range;
    EXPECT_NE(range.find("got 2e+06"), std::string::npos) << range;
    const std::string unknown = formulaSceneError(formulaSceneText(R"js({"file": "metrics/kerr.json", "Q": 1})js"));
    EXPECT_NE(unknown.find("has no parameter 'Q' (it takes: M, a)"), std::string::npos) << unknown;
    const std::string missing = formulaSceneError(formulaSceneText(R"js({"file": "metrics/nothing.json"})js"));
    EXPECT_NE(missing.find("nothing.json"), std::string::npos) << missing;
    const std::string riemannian =
        formulaSceneError(formulaSceneText(R"js({"formula": {"ds2": "dt^2 + dx^2 + dy^2 + dz^2"}})js"));
    EXPECT_NE(riemannian.find("the metric cannot serve at the observer's event (0, 30, 0, 3): the metric is "
                              "not Lorentzian"),
              std::string::npos)
        << riemannian;
    const std::string singular = formulaSceneError(
        formulaSceneText(R"js({"formula": {"ds2": "-dt^2 + dx^2/(x - 30) + dy^2 + dz^2"}})js", "[0, 30, 0, 0]"));
    EXPECT_NE(singular.find("g_xx = -inf"), std::string::npos) << singular;
    const std::string field = formulaSceneError(formulaSceneText(R"js({"formula": {"ds2": "-dt^2", "colour": 1}})js"));
    EXPECT_NE(field.find("colour"), std::string::npos) << field;
    const std::string component = formulaSceneError(formulaSceneText(R"js({"formula": {"g": {"tq": "1"}}})js"));
    EXPECT_NE(component.find("'tq' names no pair of coordinates (t, x, y, z)"), std::string::npos) << component;
    const std::string both = formulaSceneError(formulaSceneText(R"js({"formula": {"g": {"tt": "1", "t,t": "2"}}})js"));
    EXPECT_NE(both.find("g_tt is given twice"), std::string::npos) << both;
}

// Schwarzschild typed without a horizon: rays that fall in meet r = 0, where g is not finite.
// They stop as singular rays (counted), and every stored number stays finite.
TEST(MetricFile, RaysIntoASingularityStopAndAreCountedNeverNaN) {
    const Scene s = io::parseScene(formulaSceneText(R"js({"formula": {
        "define": ["r = sqrt(x^2 + y^2 + z^2)"],
        "ds2": "-dt^2 + dx^2 + dy^2 + dz^2 + 2/r*(dt - (x*dx + y*dy + z*dz)/r)^2",
        "far_field": {"mass": 1}}})js",
                                                    "[0, 30, 0, 0]"),
                                   "scene.json", kMetricData);
    const RenderResult r = renderNumeric(s);
    std::size_t stoppedInside = 0;
    for (const PixelRecord& p : r.pixels) {
        EXPECT_TRUE(std::isfinite(p.u) && std::isfinite(p.v) && std::isfinite(p.affine) && std::isfinite(p.drift));
        stoppedInside += p.kind != PixelRecord::Sky;
    }
    EXPECT_GT(stoppedInside, 20u);  // the shadow, about 10 degrees across, in a 40 x 20 degree view
    EXPECT_EQ(r.stats.stopCounts[static_cast<std::size_t>(StopReason::Escaped)] + stoppedInside, r.pixels.size());
}

// The closing example of docs/METRICS.md: a metric no built-in covers. Rays that cross the throat
// of the Ellis wormhole go on towards the other side's infinity (R -> 0 in this chart) and stop
// there (the file's "horizon"); the rest escape to this side's sky. The edge between them is the
// wormhole's shadow: for ds^2 = -dt^2 + dl^2 + r(l)^2 dOmega^2 a static observer at areal radius
// r_O sees rays of impact parameter h at sin(alpha) = h / r_O, and the critical one grazes the
// throat, h = b (Perlick and Tsupko 2022, Phys. Rep. 947, 1, eq. for sin^2 alpha_sh with A = 1,
// D = r^2): sin(alpha_sh) = b / r_O, with r_O = R (1 + b^2 / 4R^2) in this chart.
TEST(MetricFile, EllisWormholeShadowHasTheClosedFormRadius) {
    const double b = 1.3, R = 7;
    const Scene s = io::parseScene(
        "{\"metric\": {\"file\": \"metrics/ellis_wormhole.json\", \"b\": 1.3},"
        " \"observer\": {\"position\": [0, 0, 0, 7]},"  // off the x axis: the chart's z axis
        " \"camera\": {\"width\": 601, \"height\": 1, \"fov\": [30, 0.05], \"forward\": [0, 0, -1], \"up\": [0, 1, 0]},"
        " \"render\": {\"stepper\": \"dopri5\", \"tolerance\": 1e-10}}",
        "scene.json", kMetricData);
    const RenderResult r = renderNumeric(s);
    const auto& stops = r.stats.stopCounts;
    EXPECT_EQ(
        stops[static_cast<std::size_t>(StopReason::Escaped)] + stops[static_cast<std::size_t>(StopReason::OtherEnd)],
        r.pixels.size());
    // The throat's right edge: the last pixel whose ray reached the far side and the first that
    // stayed on this one, both sky.
    const int w = s.camera.width;
    int last = -1;
    for (int i = w / 2; i < w; ++i) {
        const PixelRecord& p = r.pixels[static_cast<std::size_t>(i)];
        EXPECT_EQ(p.kind, PixelRecord::Sky);
        EXPECT_EQ(p.end == 1, p.stopReason == static_cast<std::int8_t>(StopReason::OtherEnd));
        if (p.end == 1) last = i;
    }
    ASSERT_GT(last, w / 2);
    ASSERT_LT(last, w - 1);
    EXPECT_EQ(r.pixels[static_cast<std::size_t>(last + 1)].end, 0);
    const double halfTan = std::tan(15 * kPi / 180);
    auto angle = [&](double i) { return std::atan((i + 0.5 - 0.5 * w) / (0.5 * w) * halfTan); };
    const double alpha = std::asin(b / (R * (1 + b * b / (4 * R * R))));
    std::printf("Ellis shadow: closed form %.5f deg, image between %.5f and %.5f deg\n", alpha * 180 / kPi,
                angle(last) * 180 / kPi, angle(last + 1) * 180 / kPi);
    EXPECT_GE(alpha, angle(last));
    EXPECT_LE(alpha, angle(last + 1));
    for (const PixelRecord& p : r.pixels)
        EXPECT_TRUE(std::isfinite(p.u) && std::isfinite(p.v) && std::isfinite(p.drift));
}

// Through the throat to the far side's sky (the file's "other_end"): a ray of impact parameter
// b_i < b sweeps, from l1 > 0 on this side to the far side's infinity, the angle
// (b_i/b) (F(atan(l1/c), k) + K(k)) about the centre, c = sqrt(b^2 - b_i^2), k = b_i/b (the
// integral of b_i dl / sqrt((l^2 + b^2)(l^2 + c^2)), Gradshteyn and Ryzhik 3.152.1), and leaves
// in that direction. The tracer stops it at l = -100 b and reads its direction there through the
// chart's inversion; the bending still ahead, b_i (b^2 - 2c^2)/(6 l^3), is below 2e-7 rad.
TEST(MetricFile, EllisWormholeRaysReachTheFarSideWhereTheEllipticIntegralSays) {
    const double b = 1.3;
    const auto st = io::loadFormulaMetric(kMetricData + "metrics/ellis_wormhole.json", {{"b", b}});
    ASSERT_TRUE(st->hasOtherEnd());
    TraceOptions opt;
    opt.stepper = StepperKind::Dopri87;
    opt.absTol = opt.relTol = 1e-12;
    const auto properDistance = [&](const Vec4& x) {
        const double R = x.tail<3>().norm();
        return R - b * b / (4 * R);
    };
    for (const double bi : {0.0, 0.3, 0.9, 1.25}) {
        const PhasePoint start = impactParameterRay(*st, bi, 1e3);
        const TraceResult r = traceGeodesic(*st, start, opt);
        ASSERT_EQ(r.reason, StopReason::OtherEnd) << bi;
        const double c = std::sqrt(b * b - bi * bi), k = bi / b;
        const double l1 = properDistance(start.x), l2 = properDistance(r.end.x);
        const double expected = k * (std::ellint_1(k, std::atan(l1 / c)) + std::comp_ellint_1(k));
        // The sense the ray turns in about the centre: that of x k^y - y k^x at the start.
        const Vec4 k0 = st->inverseMetric(start.x) * start.p;
        const double sense = start.x[1] * k0[2] - start.x[2] * k0[1] > 0 ? 1 : -1;
        const double startAngle = std::atan2(start.x[2], start.x[1]);
        const Vec3 far = st->otherEndDirection(r.end);
        const double turned = std::atan2(far.y(), far.x()) - startAngle;
        // Angles are known modulo 2 pi; the swept one is the expected one plus this residue.
        const double swept = expected + std::remainder(sense * turned - expected, 2 * kPi);
        std::printf(
            "Ellis b_i = %.2f: l from %.1f to %.1f, far-side direction swept %.10f rad, elliptic integral "
            "%.10f\n",
            bi, l1, l2, swept, expected);
        // Stopped at the first step past the file's other_end, l = -100 b (steps grow like |l| there).
        EXPECT_LT(l2, -100 * b + 1e-6) << bi;
        EXPECT_GT(l2, -115 * b) << bi;
        EXPECT_NEAR(swept, expected, 1e-6) << bi;
    }
}

// The fall through the throat (data/ellis_wormhole_passage.json): its animation's free fall goes
// on at l = 10 - k b in frame k (no gravity: g_tt = -1, so the proper distance falls at gamma v
// per unit proper time) and crosses to the far side. Where the skies meet is the throat's edge,
// the rays of b_i = b, at sin(alpha) = b/sqrt(l^2 + b^2) from the throat's direction for a static
// observer, moved by the aberration of the observer's speed v: cos(theta) = (cos(alpha) +- v)/(1 +-
// v cos(alpha)) from the direction of motion (ahead, frame 0) or from the direction away from it
// (behind, frame 20); at the throat (frame 10) alpha = 90 degrees: the great circle, seen at
// arccos(v) = 60 degrees from ahead.
TEST(MetricFile, EllisPassageSeesTheSkiesMeetWhereTheAberratedThroatEdgeIs) {
    const Scene scene = io::readScene(kMetricData + "ellis_wormhole_passage.json");
    ASSERT_TRUE(scene.animation.properTime.has_value());
    const FrameInterval tau = *scene.animation.properTime;
    const double b = 1, v = 0.5;
    TraceOptions opt;
    opt.stepper = StepperKind::Dopri87;
    opt.absTol = opt.relTol = 1e-12;
    const std::vector<ObserverEvent> events =
        observerWorldLine(*scene.spacetime, scene.observer, scene.observerVelocity, ObserverMotion::FreeFall,
                          {tau.at(0), tau.at(10), tau.at(20)}, opt);
    for (int k = 0; k < 3; ++k) {
        const double R = events[static_cast<std::size_t>(k)].position.tail<3>().norm(), l = R - b * b / (4 * R);
        EXPECT_NEAR(l, 10 - 10 * k, 1e-7) << "frame " << 10 * k;
        const LocalFrame frame =
            LocalFrame::withVelocity(*scene.spacetime, events[static_cast<std::size_t>(k)].position,
                                     events[static_cast<std::size_t>(k)].velocity);
        // Along a great circle from the direction of the throat (frame -x before it, +x after).
        const double throatSide = k < 2 ? -1 : 1;
        const auto farSide = [&](double degrees) {
            const double a = degrees * kPi / 180;
            const PhasePoint ray{
                frame.x, frame.pastNullMomentum(*scene.spacetime, Vec3(throatSide * std::cos(a), std::sin(a), 0))};
            return traceGeodesic(*scene.spacetime, ray, opt).reason == StopReason::OtherEnd;
        };
        // The throat shows the other side's sky: the far one before it, this one after it.
        const bool throatShowsFarSide = k < 2;
        double inside = 1e-3, outside = 179;
        ASSERT_EQ(farSide(inside), throatShowsFarSide) << "frame " << 10 * k;
        ASSERT_NE(farSide(outside), throatShowsFarSide) << "frame " << 10 * k;
        while (outside - inside > 1e-10) {
            const double mid = 0.5 * (inside + outside);
            (farSide(mid) == throatShowsFarSide ? inside : outside) = mid;
        }
        const double cosAlpha = std::sqrt(l * l / (l * l + b * b)), sign = k < 2 ? 1 : -1;
        const double expected = std::acos((cosAlpha + sign * v) / (1 + sign * v * cosAlpha)) * 180 / kPi;
        std::printf(
            "Ellis passage, frame %d (l = %+.0f b): the skies meet %.9f deg from the throat, aberrated "
            "closed form %.9f deg\n",
            10 * k, l, 0.5 * (inside + outside), expected);
        EXPECT_NEAR(0.5 * (inside + outside), expected, 3e-6) << "frame " << 10 * k;
    }
}

}  // namespace
