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
#include "core/accretion/thin_disk.hpp"
#include "core/spacetime/scattering.hpp"
#include "readers/io/metric_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

const std::string kMetrics = std::string(LIGHTCONE_SOURCE_DIR) + "/data/metrics/";

// The impact parameter between rays that fall in (|b| = captured) and rays that escape
// (|b| = escapes), bisected to 1e-9 relative; rays sent from 10^4 M along +x in the equator.
double criticalImpact(const lc::Spacetime& st, double captured, double escapes) {
    lc::TraceOptions opt;
    opt.stepper = lc::StepperKind::Dopri87;
    opt.absTol = opt.relTol = 1e-11;
    const auto fallsIn = [&](double b) {
        return lc::traceGeodesic(st, lc::impactParameterRay(st, b, 1e4), opt).reason == lc::StopReason::Horizon;
    };
    EXPECT_TRUE(fallsIn(captured)) << captured;
    EXPECT_FALSE(fallsIn(escapes)) << escapes;
    while (std::abs(escapes - captured) > 1e-9 * std::abs(captured)) {
        const double mid = 0.5 * (captured + escapes);
        (fallsIn(mid) ? captured : escapes) = mid;
    }
    return 0.5 * (captured + escapes);
}

void report(const char* metric, const char* quantity, double published, double ours) {
    // Relative difference, or the absolute one where the published value is zero.
    std::printf("| %s | %s | %.10g | %.10g | %.1e |\n", metric, quantity, published, ours,
                std::abs(ours - published) / (published == 0 ? 1 : std::abs(published)));
}

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

TEST(MetricCatalogue, SchwarzschildInIsotropicPainleveGullstrandAndIngoingChartsHasTheShadowOf3Sqrt3) {
    // Synge (1966): b_c = 3 sqrt3 M whatever the chart; each file's photon sphere and horizon
    // sit at its own coordinate radius.
    const double published = 3 * std::sqrt(3.0);
    for (const char* file : {"schwarzschild_isotropic", "schwarzschild_painleve_gullstrand",
                             "schwarzschild_ingoing_eddington_finkelstein"}) {
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

}  // namespace
