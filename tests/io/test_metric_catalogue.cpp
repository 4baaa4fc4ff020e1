// SPDX-License-Identifier: BSD-3-Clause
// The catalogue of metric files (data/metrics, issue #43): each checked against a number published
// for it, traced from its file as a user would. The oracle is the publication's closed form typed
// here; the code under test is the formula parser, its exact derivatives and the tracer.
//  - the critical impact parameter of the shadow (rays sent in from far away, bisected between
//    capture and escape): Reissner-Nordstrom (Chandrasekhar 1983, section 5.40), Janis-Newman-
//    Winicour (Virbhadra and Ellis 2002, eqs. 9-10), Kerr in Boyer-Lindquist coordinates on both
//    sides of the equator's photon orbits (Bardeen 1973), Schwarzschild in isotropic and
//    Painleve-Gullstrand coordinates (3 sqrt3 M, Synge 1966);
//  - Kerr-Boyer-Lindquist's innermost stable circular orbits (Bardeen, Press and Teukolsky 1972,
//    eq. 2.21), found from its g by the disk model.
// docs/METRICS.md's catalogue table quotes the figures these tests print.
#include "catalogue_oracles.hpp"
#include "core/accretion/thin_disk.hpp"
#include "core/analysis/shadow.hpp"
#include "core/render/render.hpp"
#include "core/scene/scene.hpp"
#include "core/spacetime/frame.hpp"
#include "readers/io/scene_reader.hpp"
#include "tests/common/test_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <utility>

namespace {

using namespace lc::catalogue_test;
const std::string kMetrics = kCatalogue;

TEST(MetricCatalogue, ReissnerNordstromShadowAtChandrasekharsPhotonSphere) {
    for (const double Q : {0.0, 0.5, 0.9}) {
        const auto st = lc::io::loadFormulaMetric(kMetrics + "reissner_nordstrom.json", {{"Q", Q}});
        const double r = 0.5 * (3 + std::sqrt(9 - 8 * Q * Q));  // M = 1
        const double published = r / std::sqrt(1 - 2 / r + Q * Q / (r * r));
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
        report(("reissner_nordstrom Q = " + std::to_string(Q).substr(0, 3)).c_str(), "critical impact b_c / M",
               published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << "Q = " << Q;
    }
}

TEST(MetricCatalogue, JanisNewmanWinicourShadowAtVirbhadraEllisPhotonSphere) {
    for (const double gamma : {0.6, 0.8, 1.0}) {
        const auto st = lc::io::loadFormulaMetric(kMetrics + "janis_newman_winicour.json", {{"gamma", gamma}});
        const double B = 2 / gamma, rps = (1 + 2 * gamma) * B / 2;  // M = 1
        const double published = rps * std::pow(1 - B / rps, (1 - 2 * gamma) / 2);
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
        report(("janis_newman_winicour gamma = " + std::to_string(gamma).substr(0, 3)).c_str(),
               "critical impact b_c / M", published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << "gamma = " << gamma;
    }
}

TEST(MetricCatalogue, SchwarzschildInEveryChartHasTheShadowOf3Sqrt3) {
    // Synge (1966): b_c = 3 sqrt3 M whatever the chart; each file's photon sphere and horizon
    // sit at its own coordinate radius.
    const double published = 3 * std::sqrt(3.0);
    for (const char* file :
         {"schwarzschild_isotropic", "schwarzschild_painleve_gullstrand", "schwarzschild_ingoing_eddington_finkelstein",
          "schwarzschild", "schwarzschild_spherical"}) {
        const auto st = lc::io::loadFormulaMetric(kMetrics + file + ".json", {});
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
        report(file, "critical impact b_c / M", published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << file;
    }
}

// The shadow of a static black hole with g_tt = -f(r), g_thth = r^2: b_c = r/sqrt(f) at the
// photon sphere, the outermost root of r f' = 2 f (Virbhadra and Ellis 2002, eq. 7), found here by
// bisection on the closed-form f and f' (M = 1).
template <class F, class DF>
double staticShadow(F&& f, DF&& df) {
    const auto condition = [&](double r) { return r * df(r) - 2 * f(r); };
    double outside = 10, inside = 10;
    while (condition(inside) < 0) inside -= 0.01;  // r f' - 2f < 0 outside the photon sphere
    outside = inside + 0.01;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (inside + outside);
        (condition(mid) < 0 ? outside : inside) = mid;
    }
    return outside / std::sqrt(f(outside));
}

TEST(MetricCatalogue, RegularBlackHolesOfBardeenAndHaywardHaveTheirPhotonSpheresShadow) {
    for (const double g : {0.25, 0.5, 0.75}) {
        const auto st = lc::io::loadFormulaMetric(kMetrics + "bardeen_regular.json", {{"g", g}});
        const double published = staticShadow([&](double r) { return 1 - 2 * r * r / std::pow(r * r + g * g, 1.5); },
                                              [&](double r) {
                                                  const double q = r * r + g * g;
                                                  return -4 * r / std::pow(q, 1.5) + 6 * r * r * r / std::pow(q, 2.5);
                                              });
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
        report(("bardeen_regular g = " + std::to_string(g).substr(0, 4)).c_str(), "critical impact b_c / M", published,
               ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << "g = " << g;
    }
    for (const double l : {0.25, 0.5, 0.75}) {
        const auto st = lc::io::loadFormulaMetric(kMetrics + "hayward_regular.json", {{"l", l}});
        const double published = staticShadow([&](double r) { return 1 - 2 * r * r / (r * r * r + 2 * l * l); },
                                              [&](double r) {
                                                  const double q = r * r * r + 2 * l * l;
                                                  return -4 * r / q + 6 * r * r * r * r / (q * q);
                                              });
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
        report(("hayward_regular l = " + std::to_string(l).substr(0, 4)).c_str(), "critical impact b_c / M", published,
               ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << "l = " << l;
    }
}

TEST(MetricCatalogue, MinkowskiInSphericalCoordinatesBendsNoLight) {
    const auto st = lc::io::loadFormulaMetric(kMetrics + "minkowski_spherical.json", {});
    lc::TraceOptions opt;
    opt.absTol = opt.relTol = 1e-12;
    for (const double b : {0.5, 3.0, 40.0}) {
        const lc::DeflectionResult d = lc::measureDeflection(*st, lc::impactParameterRay(*st, b, 1e3), opt);
        report("minkowski_spherical", ("deflection at b = " + std::to_string(b).substr(0, 4)).c_str(), 0, d.deflection);
        EXPECT_EQ(d.trace.reason, lc::StopReason::Escaped) << b;
        EXPECT_NEAR(d.deflection, 0, 1e-10) << b;
    }
}

// Bardeen's xi = L/E of the equatorial photon orbit at r (M = 1).
double bardeenXi(double a, double r) { return -(r * r * r - 3 * r * r + a * a * r + a * a) / (a * (r - 1)); }

TEST(MetricCatalogue, KerrBoyerLindquistShadowEdgesAtBardeensPhotonOrbits) {
    for (const double a : {0.5, 0.9, 0.99, -0.99}) {  // |a| <= 0.99: the file's range
        const auto st = lc::io::loadFormulaMetric(kMetrics + "kerr_boyer_lindquist.json", {{"a", a}});
        // Bardeen's two equatorial photon orbits; the smaller one co-rotates with the hole. A ray
        // sent along +x at y = b p_t has L_z = -b E, so b = -xi.
        const double rOne = 2 * (1 + std::cos(2.0 / 3 * std::acos(-a)));
        const double rTwo = 2 * (1 + std::cos(2.0 / 3 * std::acos(a)));
        const double one = -bardeenXi(a, rOne), two = -bardeenXi(a, rTwo);
        const double oursOne = criticalImpact(*st, 0.98 * one, 1.02 * one);
        const double oursTwo = criticalImpact(*st, 0.98 * two, 1.02 * two);
        const std::string name = "kerr_boyer_lindquist a = " + std::to_string(a).substr(0, a < 0 ? 5 : 4);
        report(name.c_str(), rOne < rTwo ? "b_c, co-rotating orbit / M" : "b_c, counter-rotating orbit / M", one,
               oursOne);
        report(name.c_str(), rTwo < rOne ? "b_c, co-rotating orbit / M" : "b_c, counter-rotating orbit / M", two,
               oursTwo);
        EXPECT_NEAR(oursOne, one, 1e-8 * std::abs(one)) << "a = " << a;
        EXPECT_NEAR(oursTwo, two, 1e-8 * std::abs(two)) << "a = " << a;
    }
}

// The same edges in the Kerr-Schild file (data/metrics/kerr.json, the built-in typed as text).
TEST(MetricCatalogue, KerrSchildFileHasBardeensShadowEdges) {
    for (const double a : {0.9, -0.5}) {
        const auto st = lc::io::loadFormulaMetric(kMetrics + "kerr.json", {{"a", a}});
        for (const double sign : {-1.0, 1.0}) {
            const double r = 2 * (1 + std::cos(2.0 / 3 * std::acos(sign * a))), published = -bardeenXi(a, r);
            const double other = 2 * (1 + std::cos(2.0 / 3 * std::acos(-sign * a)));  // the smaller co-rotates
            const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
            report("kerr a = " + std::to_string(a).substr(0, a < 0 ? 4 : 3),
                   r < other ? "b_c, co-rotating orbit / M" : "b_c, counter-rotating orbit / M", published, ours);
            EXPECT_NEAR(ours, published, 1e-8 * std::abs(published)) << a << " " << sign;
        }
    }
}

TEST(MetricCatalogue, KerrBoyerLindquistIscoOfBardeenPressTeukolsky) {
    const double a = 0.9;
    const auto st = lc::io::loadFormulaMetric(kMetrics + "kerr_boyer_lindquist.json", {{"a", a}});
    // BPT 1972 eq. 2.21 (M = 1).
    const double z1 = 1 + std::cbrt(1 - a * a) * (std::cbrt(1 + a) + std::cbrt(1 - a));
    const double z2 = std::sqrt(3 * a * a + z1 * z1);
    const double pro = 3 + z2 - std::sqrt((3 - z1) * (3 + z1 + 2 * z2));
    const double retro = 3 + z2 + std::sqrt((3 - z1) * (3 + z1 + 2 * z2));
    const double oursPro = lc::ThinDiskModel(st, 0, 1e4, true).isco();
    const double oursRetro = lc::ThinDiskModel(st, 0, 1e4, false).isco();
    report("kerr_boyer_lindquist a = 0.9", "ISCO, prograde / M", pro, oursPro);
    report("kerr_boyer_lindquist a = 0.9", "ISCO, retrograde / M", retro, oursRetro);
    EXPECT_NEAR(oursPro, pro, 1e-6 * pro);
    EXPECT_NEAR(oursRetro, retro, 1e-6 * retro);
}

// The equatorial circular photon orbits of a Kerr-like metric with radial function Delta(r): the
// double roots of Carter's R(r) = (r^2 + a^2 - a b)^2 - Delta (b - a)^2 (E = 1; Chandrasekhar 1983,
// section 63 for Kerr, 11.111 for Kerr-Newman; Carter 1973 for Kerr-de Sitter, where R carries an
// overall Xi^2). R = R' = 0 give r Delta' - 4 Delta = 4 s a sqrt(Delta) and b = a + 4 s r
// sqrt(Delta)/Delta' (s = +1 co-rotating); solved here by scanning [from, to] and bisecting. The
// tracer's rays along +x at y = b p_t have L/E = -b (the Kerr test above).
struct PhotonOrbit {
    double radius, impact;
};
template <class D, class DD>
PhotonOrbit carterEquatorialOrbit(D&& delta, DD&& dDelta, double a, int s, double from, double to) {
    const auto condition = [&](double r) { return r * dDelta(r) - 4 * delta(r) - 4 * s * a * std::sqrt(delta(r)); };
    double lo = to, hi = to;
    for (double r = to; r > from; r -= 1e-3) {  // the outermost root
        if (delta(r) > 0 && delta(r + 1e-3) > 0 && condition(r) * condition(r + 1e-3) <= 0) {
            lo = r;
            hi = r + 1e-3;
            break;
        }
    }
    EXPECT_LT(lo, to) << "no photon orbit for s = " << s;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (condition(lo) * condition(mid) <= 0 ? hi : lo) = mid;
    }
    const double r = 0.5 * (lo + hi);
    return {r, -(a + 4 * s * r * std::sqrt(delta(r)) / dDelta(r))};
}

void expectKerrLikeShadowEdges(const lc::Spacetime& st, const std::string& label,
                               const std::function<double(double)>& delta, const std::function<double(double)>& dDelta,
                               double a, double distance = 1e4,
                               const std::function<bool(const lc::TraceResult&)>& fallsIn = {},
                               const std::function<double(double, double)>& measure = {}) {
    for (const int s : {+1, -1}) {
        const PhotonOrbit orbit = carterEquatorialOrbit(delta, dDelta, a, s, 1.0, 10.0);
        const double ours = measure ? measure(0.98 * orbit.impact, 1.02 * orbit.impact)
                                    : criticalImpact(st, 0.98 * orbit.impact, 1.02 * orbit.impact, distance, fallsIn);
        report(label, s > 0 ? "b_c, co-rotating orbit / M" : "b_c, counter-rotating orbit / M", orbit.impact, ours);
        EXPECT_NEAR(ours, orbit.impact, 1e-8 * std::abs(orbit.impact)) << label << " s = " << s;
    }
}

TEST(MetricCatalogue, KerrNewmanShadowEdgesAtCartersDoubleRoots) {
    for (const auto& [a, Q] : {std::pair{0.6, 0.6}, std::pair{-0.5, 0.3}}) {
        const auto st = catalogueMetric("kerr_newman", {{"a", a}, {"Q", Q}});
        const std::string label =
            "kerr_newman a = " + std::to_string(a).substr(0, a < 0 ? 4 : 3) + ", Q = " + std::to_string(Q).substr(0, 3);
        expectKerrLikeShadowEdges(
            *st, label, [&](double r) { return r * r - 2 * r + a * a + Q * Q; }, [](double r) { return 2 * r - 2; }, a);
    }
}

// A past-directed ray, as the camera traces, at (-distance, y, 0) moving along +x with L/E = b
// (y = b p_t by fixed-point iteration). Ingoing coordinates need it: a future-directed ray coming
// in along +x has v nearly constant (k^v -> 0 far away). Kerr's isometry (t, phi) -> (-t, -phi)
// maps it to the future-directed ray with the same b, so the critical values are Bardeen's.
lc::PhasePoint pastImpactParameterRay(const lc::Spacetime& st, double b, double distance) {
    lc::PhasePoint ray = nullRayAt(st, lc::Vec4(0, -distance, -b, 0), lc::Vec3(-1, 0, 0), true);
    for (int k = 0; k < 200; ++k) {
        const double y = b * ray.p[0];
        ray = nullRayAt(st, lc::Vec4(0, -distance, y, 0), lc::Vec3(-1, 0, 0), true);
        if (std::abs(ray.x[2] - b * ray.p[0]) < 1e-15 * std::abs(y)) break;
    }
    return ray;
}

TEST(MetricCatalogue, KerrInIngoingCoordinatesHasBardeensShadowEdgesForTheCamerasRays) {
    const double a = 0.9;
    const auto st = catalogueMetric("kerr_ingoing", {{"a", a}});
    const lc::TraceOptions opt = accurateTrace();
    expectKerrLikeShadowEdges(
        *st, "kerr_ingoing a = 0.9 (past-directed rays)", [&](double r) { return r * r - 2 * r + a * a; },
        [](double r) { return 2 * r - 2; }, a, 1e4, {},
        [&](double captured, double escapes) {
            return bisectPredicate(
                [&](double b) {
                    return traceGeodesic(*st, pastImpactParameterRay(*st, b, 1e4), opt).reason ==
                           lc::StopReason::Horizon;
                },
                captured, escapes);
        });
}

// The dark cap of an observer falling from rest at infinity (the rain chart's t is its proper
// time, u = d/dt - sqrt(2M/r) d/dr), docs/PHYSICS.md "Falling through the horizon": its angular
// radius about the direction of the centre is the angle at which the critical photons with E > 0
// arrive in the observer's frame: moving out (r > r_c) or in (r <= r_c). For Kerr on the spin axis
// (kerr_rain), Sigma = r^2 + a^2 and g_tt = -Delta/Sigma, and a photon there has L_z = 0 and
// Sigma^2 (dr/dl)^2 = Sigma^2 E^2 - Delta K (Carter's R(r)): the same algebra with f = Delta/Sigma,
// beta^2 = 2Mr/Sigma and k = K_c/Sigma, K_c = 2 r_c (r_c^2 + a^2)/(r_c - M) of the L_z = 0 spherical
// photon orbit, r_c^3 - 3M r_c^2 + a^2 r_c + M a^2 = 0 (R = R' = 0). M = 1; a = 0 is
// Schwarzschild's r_c = 3, K_c = 27 (b = 3 sqrt3 M), exactly.
double rainDarkCapDegrees(double r, double a = 0) {
    double lo = 1, hi = 3;  // the cubic is 2a^2 - 2 < 0 at 1 and 4a^2 >= 0 at 3
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (mid * mid * mid - 3 * mid * mid + a * a * mid + a * a < 0 ? lo : hi) = mid;
    }
    const double rc = hi, Kc = 2 * rc * (rc * rc + a * a) / (rc - 1);
    const double sigma = r * r + a * a, f = (r * r - 2 * r + a * a) / sigma, beta = std::sqrt(2 * r / sigma);
    const double k = Kc / sigma, s = std::sqrt(1 - f * k);
    const double psi = r > rc ? std::atan2(std::sqrt(k) * f, s + beta) : std::atan2(std::sqrt(k) * (beta + s), k - 1);
    return psi * 180 / lc::kPi;
}

TEST(MetricCatalogue, RainObserverSeesTheClosedFormDarkCapOutsideOnAndInsideTheHorizon) {
    const auto st = catalogueMetric("schwarzschild_rain");
    lc::TraceOptions opt = accurateTrace();
    opt.maxAffine = 1e5;
    for (const double r : {6.0, 2.0, 1.0, 0.2}) {
        const lc::Vec4 x(0, r, 0, 0);
        const lc::LocalFrame frame = lc::LocalFrame::withVelocity(*st, x, lc::Vec4(1, -std::sqrt(2 / r), 0, 0));
        // Along two great circles from the direction of the centre (frame -x): towards y and z.
        for (const int side : {1, 2}) {
            const auto dark = [&](double degrees) {
                lc::Vec3 n(-std::cos(degrees * lc::kPi / 180), 0, 0);
                n(side) = std::sin(degrees * lc::kPi / 180);
                const lc::PhasePoint ray{x, frame.pastNullMomentum(*st, n)};
                return traceGeodesic(*st, ray, opt).reason == lc::StopReason::Horizon;
            };
            const double published = rainDarkCapDegrees(r), ours = bisectPredicate(dark, 1, 179, 1e-10);
            report("schwarzschild_rain r = " + std::to_string(r).substr(0, 3) + " M",
                   "dark cap radius of the falling observer, degrees", published, ours);
            EXPECT_NEAR(ours, published, 1e-9 * published) << "r = " << r << ", side " << side;
        }
    }
}

// The same fall in Kerr along the spin axis (kerr_rain, ingoing Kerr coordinates; rainDarkCapDegrees).
// kerr_rain's observer falling from rest at infinity, at Boyer-Lindquist r on the chart axis
// `radial` (0: x, in the equator; 2: z, the spin axis): its event and 4-velocity in the file's
// chart, R = (r + sqrt(r^2 + M^2))/2 (r = R - M^2/(4R)), u^v = 1/(1 + beta) (v = t + int (r^2 +
// a^2)/Delta dr: u^v = u^t + (r^2 + a^2)/Delta u^r), u^R = -beta/(1 + M^2/4R^2). M = 1.
std::pair<lc::Vec4, lc::Vec4> kerrRainFaller(double r, double a, int radial) {
    lc::Vec4 x = lc::Vec4::Zero(), u = lc::Vec4::Zero();
    const double R = 0.5 * (r + std::sqrt(r * r + 1)), beta = std::sqrt(2 * r / (r * r + a * a));
    x(1 + radial) = R;
    u(0) = 1 / (1 + beta);
    u(1 + radial) = -beta / (1 + 0.25 / (R * R));
    return {x, u};
}

TEST(MetricCatalogue, KerrRainObserverOnTheAxisSeesTheClosedFormDarkCapOutsideAndBetweenTheHorizons) {
    lc::TraceOptions opt = accurateTrace();
    opt.maxAffine = 1e5;
    struct Case {
        double a, r;
        int radial;  // the frame axis along which the observer falls: 0 (x, the equator) or 2 (z, the axis)
    };
    for (const Case c : {Case{0, 1, 0}, Case{0.9, 6, 2}, Case{0.9, 1, 2}}) {
        const auto st = catalogueMetric("kerr_rain", {{"a", c.a}});
        const auto [x, u] = kerrRainFaller(c.r, c.a, c.radial);
        const lc::LocalFrame frame = lc::LocalFrame::withVelocity(*st, x, u);
        for (const int side : {0, 1, 2}) {
            if (side == c.radial) continue;
            const auto dark = [&](double degrees) {
                lc::Vec3 n = lc::Vec3::Zero();
                n(c.radial) = -std::cos(degrees * lc::kPi / 180);
                n(side) = std::sin(degrees * lc::kPi / 180);
                const lc::PhasePoint ray{x, frame.pastNullMomentum(*st, n)};
                return traceGeodesic(*st, ray, opt).reason == lc::StopReason::Horizon;
            };
            const double published = rainDarkCapDegrees(c.r, c.a), ours = bisectPredicate(dark, 1, 179, 1e-10);
            char what[64];
            std::snprintf(what, sizeof what, "kerr_rain a = %.1f r = %.0f M%s", c.a, c.r,
                          c.radial ? " on the axis" : "");
            report(what, "dark cap radius of the falling observer, degrees", published, ours);
            EXPECT_NEAR(ours, published, 1e-7 * published) << what << ", side " << side;
        }
    }
}

// The shadow outline (`sweep --outline`) of an observer between the horizons (issue 50: "observers
// between the horizons get the dark region of their sky"): kerr_rain's faller on the spin axis at
// r = 1 M, a = 0.9, looking down the axis. Its dark region is the cap of the light from the past
// horizon, a circle of radius psi_c about the direction of fall (rainDarkCapDegrees, Teo 2003 in
// the rain frame): every outline point lies at psi_c from it, the solid angle is 2 pi (1 - cos psi_c).
// The built-in kerr (outgoing Kerr-Schild, a white hole inside) refuses a falling observer there and
// names this chart.
TEST(MetricCatalogue, KerrRainObserverBetweenTheHorizonsHasTheDarkCapAsItsShadowOutline) {
    const auto [x, u] = kerrRainFaller(1, 0.9, 2);
    const std::string file = ::testing::TempDir() + "kerr_rain_between_horizons.json";
    char text[1024];
    std::snprintf(text, sizeof text,
                  R"({"metric": {"file": "%skerr_rain.json", "a": 0.9},
                      "observer": {"position": [%.17g, %.17g, %.17g, %.17g], "velocity": [%.17g, %.17g, %.17g, %.17g]},
                      "camera": {"projection": "pinhole", "width": 64, "height": 48, "fov": [120, 90],
                                 "forward": [0, 0, -1], "up": [1, 0, 0]},
                      "render": {"stepper": "auto", "tolerance": 1e-10}})",
                  kCatalogue.c_str(), x(0), x(1), x(2), x(3), u(0), u(1), u(2), u(3));
    std::ofstream(file) << text;
    const lc::Scene scene = lc::io::readScene(file);
    const lc::ShadowOutline outline = lc::traceShadowOutline(scene, 24, 1e-9);
    const double psi = rainDarkCapDegrees(1, 0.9) * lc::kPi / 180;
    ASSERT_EQ(outline.points.size(), 24u);
    for (const lc::Vec3& n : outline.points) EXPECT_NEAR(std::acos(-n(2)), psi, 1e-7) << "edge point " << n.transpose();
    EXPECT_NEAR(outline.solidAngle, 2 * lc::kPi * (1 - std::cos(psi)), 1e-5);

    std::string kerr(text);
    kerr.replace(kerr.find("\"file\""), kerr.find("}") - kerr.find("\"file\""), "\"name\": \"kerr\", \"a\": 0.9");
    kerr.replace(kerr.find("\"velocity\": [") + 12,
                 kerr.find("]}", kerr.find("\"velocity\"")) + 1 - (kerr.find("\"velocity\": [") + 12), "\"free_fall\"");
    std::ofstream(file) << kerr;
    try {
        (void)lc::io::readScene(file);
        ADD_FAILURE() << "a falling observer inside the built-in Kerr's horizon was accepted:\n" << kerr;
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("metrics/kerr_rain.json"), std::string::npos) << e.what();
    }
}

// Below Kerr's inner horizon (a = 0.9: r- = 0.564 M), falling along the axis to the centre of the
// ring's disk, where u^r = 0: the chart crosses the disk r = 0 into the r < 0 sheet, whose infinity
// is the chart's origin. Light that comes up the axis through the disk from that sheet's infinity
// comes, by the axis' symmetry, from that sheet's own axis: the far-side direction +z (the
// inversion of the chart). Every pixel of a panorama ends for a reason: the r < 0 sheet's sky,
// this sheet's sky or the ring (singularity); none fails, and none is dark.
TEST(MetricCatalogue, KerrRainObserverBelowTheInnerHorizonSeesThroughTheRingsDiskIntoTheNegativeSheet) {
    const auto st = catalogueMetric("kerr_rain", {{"a", 0.9}});
    for (const double r : {0.3, 0.02}) {
        const auto [x, u] = kerrRainFaller(r, 0.9, 2);
        const lc::LocalFrame frame = lc::LocalFrame::withVelocity(*st, x, u);
        lc::TraceOptions opt = accurateTrace();
        opt.maxAffine = 1e5;
        const lc::TraceResult down = traceGeodesic(*st, {x, frame.pastNullMomentum(*st, lc::Vec3(0, 0, -1))}, opt);
        ASSERT_EQ(down.reason, lc::StopReason::OtherEnd) << r;
        const lc::Vec3 far = st->otherEndDirection(down.end);
        report("kerr_rain a = 0.9 r = " + std::to_string(r).substr(0, 4) + " M on the axis",
               "light from below: angle of its far-side direction from +z, rad", 0, std::acos(std::min(1.0, far.z())));
        EXPECT_NEAR(far.z(), 1, 1e-12) << r;

        lc::Scene scene;
        scene.camera = lc::test::testCamera(lc::Camera::Projection::Panorama, 32, 16, 360, 180, lc::Vec3(0, 0, -1),
                                            lc::Vec3(1, 0, 0));
        scene.spacetime = st;
        scene.observer = x;
        scene.observerVelocity = u;
        scene.settings.trace = lc::TraceOptions();
        scene.settings.progress = false;
        const lc::RenderResult image = lc::renderNumeric(scene);
        const auto& stops = image.stats.stopCounts;
        const auto count = [&](lc::StopReason reason) { return stops[static_cast<std::size_t>(reason)]; };
        std::printf("kerr_rain a = 0.9, r = %.2f M on the axis: %zu other end, %zu sky, %zu dark, %zu ring, %.2f s\n",
                    r, count(lc::StopReason::OtherEnd), count(lc::StopReason::Escaped), count(lc::StopReason::Horizon),
                    count(lc::StopReason::Singularity), image.stats.seconds);
        EXPECT_GT(count(lc::StopReason::OtherEnd), 0u) << r;
        // Traced back, outgoing rays go down through the disk, ingoing ones out through r- and r+ at
        // finite v: none is held near a past horizon (docs/PHYSICS.md section 9d).
        EXPECT_EQ(count(lc::StopReason::Horizon), 0u) << r;
        EXPECT_EQ(count(lc::StopReason::OtherEnd) + count(lc::StopReason::Escaped) + count(lc::StopReason::Horizon) +
                      count(lc::StopReason::Singularity),
                  image.pixels.size())
            << r;
    }
}

// Rays of a metric with a cosmological horizon stop at either horizon: captured ones inside the
// photon sphere.
bool endsInside(const lc::TraceResult& r) { return r.reason == lc::StopReason::Horizon && chartRadius(r.end) < 3; }

TEST(MetricCatalogue, SchwarzschildDeSitterAndAntiDeSitterShadowsOfStuchlikHledikAndCruz) {
    // Stuchlik and Hledik 1999: b_c^2 = 27 M^2/(1 - 27 y), y = Lambda M^2/3.
    for (const double Lambda : {1e-3, 1e-2}) {
        const auto st = catalogueMetric("schwarzschild_de_sitter", {{"Lambda", Lambda}});
        const double published = 3 * std::sqrt(3.0) / std::sqrt(1 - 9 * Lambda);
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published, 8, endsInside);
        report("schwarzschild_de_sitter Lambda M^2 = " + std::to_string(Lambda).substr(0, 5), "critical impact b_c / M",
               published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << Lambda;
    }
    // Cruz, Olivares and Villanueva 2005: 1/b_c^2 = 1/(27 M^2) + 1/l^2.
    for (const double l : {20.0, 5.0}) {
        const auto st = catalogueMetric("schwarzschild_anti_de_sitter", {{"l", l}});
        const double published = 1 / std::sqrt(1.0 / 27 + 1 / (l * l));
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published, 8);
        report("schwarzschild_anti_de_sitter l = " + std::to_string(l).substr(0, 4), "critical impact b_c / M",
               published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << l;
    }
}

TEST(MetricCatalogue, KerrDeSitterShadowEdgesAtCartersDoubleRoots) {
    const double a = 0.5, Lambda = 1e-3;
    const auto st = catalogueMetric("kerr_de_sitter", {{"a", a}, {"Lambda", Lambda}});
    const auto delta = [&](double r) { return (r * r + a * a) * (1 - Lambda * r * r / 3) - 2 * r; };
    const auto dDelta = [&](double r) {
        return 2 * r * (1 - Lambda * r * r / 3) - (r * r + a * a) * 2 * Lambda * r / 3 - 2;
    };
    expectKerrLikeShadowEdges(*st, "kerr_de_sitter a = 0.5, Lambda M^2 = 0.001", delta, dDelta, a, 8, endsInside);
}

TEST(MetricCatalogue, TaubNutShadowAtItsPhotonSphere) {
    for (const double n : {0.5, 1.0}) {  // Abdujabbarov et al. 2013 at a = 0 (M = 1)
        const auto st = catalogueMetric("taub_nut", {{"n", n}});
        const double r = 1 + 2 * std::sqrt(1 + n * n) * std::cos(std::acos(1 / std::sqrt(1 + n * n)) / 3);
        const double published = (r * r + n * n) / std::sqrt(r * r - 2 * r - n * n);
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
        report("taub_nut n = " + std::to_string(n).substr(0, 3), "critical impact b_c / M", published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << n;
    }
}

TEST(MetricCatalogue, MajumdarPapapetrouIsExtremalReissnerNordstromForOneHoleOrTwoTogether) {
    // Chandrasekhar 1983, section 5.40 at Q = M: photon sphere 2M, b_c = 4M; two holes at one
    // place (d = 0) are one of mass M1 + M2.
    for (const auto& [M1, M2] : {std::pair{1.0, 0.0}, std::pair{0.5, 0.5}}) {  // M2 per unit M1
        const auto st = catalogueMetric("majumdar_papapetrou", {{"M1", M1}, {"M2", M2}, {"d", 0}});
        const double published = 4 * M1 * (1 + M2);
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
        report("majumdar_papapetrou M1 = " + std::to_string(M1).substr(0, 4) +
                   ", M2/M1 = " + std::to_string(M2).substr(0, 4) + ", d = 0",
               "critical impact b_c", published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published);
    }
}

TEST(MetricCatalogue, DilatonBlackHoleShadowAtBhadrasPhotonSphere) {
    for (const double Q : {0.8, 1.3}) {  // M = 1, D = Q^2
        const auto st = catalogueMetric("gmghs_dilaton", {{"Q", Q}});
        const double D = Q * Q;
        const double r = ((D + 6) + std::sqrt((D + 6) * (D + 6) - 32 * D)) / 4;
        const double published = std::sqrt(r * (r - D) / (1 - 2 / r));
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published);
        report("gmghs_dilaton Q = " + std::to_string(Q).substr(0, 3), "critical impact b_c / M", published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << Q;
    }
}

}  // namespace
