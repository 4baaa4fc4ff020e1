// SPDX-License-Identifier: BSD-3-Clause
// The catalogue's metric files that are not asymptotically flat black holes (issue #43), each
// traced from its file and compared with a closed form published for it, typed here:
//  - photon orbits found by tangent launches: the C-metric's photon sphere (Grenzebach, Perlick and
//    Lammerzahl 2015), the Ernst black hole's equatorial orbit and Melvin's stable one at
//    rho = 2/(sqrt3 B)
//    (where g_phiphi/g_tt is extremal);
//  - cosmologies by the distance light covers: de Sitter (flat slicing and static patch), anti-de
//    Sitter (Hawking and Ellis' open slicing and the static form), Einstein-de Sitter and flat
//    Lambda-CDM (comoving distance against redshift, Hogg 1999 eq. 15), Einstein's static universe
//    (light meets at the antipode after pi R), Bertotti-Kasner (round its 2-sphere);
//  - flat and conical spaces: Minkowski in Cartesian and cylindrical charts, Rindler (straight
//    lines in Minkowski coordinates), the global monopole and the cosmic string (the cone's swept
//    angle), the plane gravitational wave (focusing, Penrose 1965);
//  - warp drives: Natario's without expansion against Alcubierre's published expansion, light's
//    speed at the centre of Natario's and Van den Broeck's bubbles.
// docs/METRICS.md's catalogue table quotes the figures these tests print.
#include "catalogue_oracles.hpp"
#include "core/curvature/curvature.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <tuple>

namespace {

using namespace lc::catalogue_test;
using lc::PhasePoint;
using lc::Vec3;
using lc::Vec4;

std::string decimals(double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

// ---- photon orbits ----

TEST(MetricCatalogueBeyond, CMetricPhotonSphereOfGrenzebachPerlickLammerzahl) {
    for (const double A : {0.05, 0.2}) {  // m = 1
        const auto st = catalogueMetric("c_metric", {{"A", A}});
        const double published = 6 / (1 + std::sqrt(1 + 12 * A * A));
        const double ours = photonOrbitByTangentLaunch(*st, published - 0.15, published + 0.3);
        report("c_metric A m = " + decimals(A, 2), "photon sphere r / m", published, ours);
        EXPECT_NEAR(ours, published, 2e-8 * published) << A;
    }
}

TEST(MetricCatalogueBeyond, ErnstEquatorialPhotonOrbitWhereGphiphiOverGttIsLeast) {
    for (const double B : {0.02, 0.05}) {  // M = 1, Lambda = 1 + B^2 r^2 in the equator
        const auto st = catalogueMetric("ernst", {{"B", B}});
        const auto condition = [&](double r) {
            return 2 / r - 8 * B * B * r / (1 + B * B * r * r) - 2 / (r * (r - 2));
        };
        double lo = 2.5, hi = 2.5;
        while (condition(hi) < 0) hi += 1e-3;  // the first root outwards: the unstable orbit
        lo = hi - 1e-3;
        for (int k = 0; k < 200; ++k) {
            const double mid = 0.5 * (lo + hi);
            (condition(mid) < 0 ? lo : hi) = mid;
        }
        const double published = 0.5 * (lo + hi);
        const double ours = photonOrbitByTangentLaunch(*st, published - 0.15, published + 0.15);
        report("ernst B M = " + decimals(B, 2), "equatorial photon orbit r / M", published, ours);
        EXPECT_NEAR(ours, published, 2e-8 * published) << B;
    }
}

TEST(MetricCatalogueBeyond, MelvinUniverseHoldsLightOnAStableCircleAtTwoOverRoot3B) {
    for (const double B : {0.1, 1.0}) {
        const auto st = catalogueMetric("melvin", {{"B", B}});
        const double published = 2 / (std::sqrt(3.0) * B);  // rho^2/Lambda^4 largest: Lambda = B^2 rho^2
        const double ours = photonOrbitByTangentLaunch(*st, 0.75 * published, 1.25 * published, cylinderRadius);
        report("melvin B = " + decimals(B, 1), "circular photon orbit rho", published, ours);
        EXPECT_NEAR(ours, published, 2e-8 * published) << B;
    }
}

TEST(MetricCatalogueBeyond, GodelLightFromTheAxisTurnsBackAtTheGodelRadius2a) {
    // Goedel (1949), Hawking and Ellis section 5.7: light from the axis (p_phi = 0) reaches r = 2a
    // exactly and turns back (docs/PHYSICS.md section 2). Launched outwards at r = a/2 with p_y = 0.
    for (const double a : {1.0, 3.0}) {
        const auto st = catalogueMetric("godel", {{"a", a}});
        const auto radialVelocity = [&](const PhasePoint& q) {
            const Vec4 k = st->inverseMetric(q.x) * q.p;
            return q.x[1] * k[1] + q.x[2] * k[2];
        };
        const auto turn = traceUntil(*st, nullRayAt(*st, Vec4(0, a / 2, 0, 0), Vec3(-1, 0, 0)), radialVelocity);
        ASSERT_TRUE(turn.has_value());
        report("godel a = " + decimals(a, 0), "radius where light from the axis turns back", 2 * a,
               cylinderRadius(*turn));
        EXPECT_NEAR(cylinderRadius(*turn), 2 * a, 1e-9 * a) << a;
    }
}

// ---- cosmologies: where light gets to ----

// A null ray from `at` moving along `direction` (unit, in the chart's Cartesian coordinates),
// future-directed, or past-directed when `past`.
PhasePoint rayFrom(const lc::Spacetime& st, const Vec4& at, const Vec3& direction, bool past = false) {
    PhasePoint ray = nullRayAt(st, at, -direction);
    if (past) ray.p = -ray.p;
    return ray;
}

TEST(MetricCatalogueBeyond, DeSitterFlatSliceComovingDistanceOfLight) {
    const double alpha = 10, t1 = 5;
    const auto st = catalogueMetric("de_sitter", {{"alpha", alpha}});
    const auto end = traceUntil(*st, rayFrom(*st, Vec4(0, 0, 0, 0), Vec3(1, 0, 0)),
                                [&](const PhasePoint& q) { return q.x[0] - t1; });
    ASSERT_TRUE(end.has_value());
    const double published = alpha * (1 - std::exp(-t1 / alpha));  // Hawking and Ellis, section 5.2
    report("de_sitter alpha = 10", "comoving distance light covers in t = 0..5", published, end->x[1]);
    EXPECT_NEAR(end->x[1], published, 1e-9 * published);
}

TEST(MetricCatalogueBeyond, DeSitterStaticPatchRadialLightTime) {
    const double l = 10, r0 = 1, r1 = 9;
    const auto st = catalogueMetric("de_sitter_static", {{"l", l}});
    const auto end = traceUntil(*st, rayFrom(*st, Vec4(0, r0, 0, 0), Vec3(1, 0, 0)),
                                [&](const PhasePoint& q) { return chartRadius(q) - r1; });
    ASSERT_TRUE(end.has_value());
    const double published = l * (std::atanh(r1 / l) - std::atanh(r0 / l));
    report("de_sitter_static l = 10", "time for radial light r = 1..9", published, end->x[0]);
    EXPECT_NEAR(end->x[0], published, 1e-9 * published);
}

TEST(MetricCatalogueBeyond, AntiDeSitterOpenSlicingRadialLight) {
    for (const double l : {1.0, 2.0}) {
        const double chi0 = 0.5, t1 = 0.5 * l;
        const auto st = catalogueMetric("anti_de_sitter", {{"l", l}});
        const auto end = traceUntil(*st, rayFrom(*st, Vec4(0, chi0, 0, 0), Vec3(1, 0, 0)),
                                    [&](const PhasePoint& q) { return q.x[0] - t1; });
        ASSERT_TRUE(end.has_value());
        const double published = chi0 + std::asinh(std::tan(t1 / l));
        report("anti_de_sitter l = " + decimals(l, 0), "chi reached by radial light at t = l/2", published,
               chartRadius(*end));
        EXPECT_NEAR(chartRadius(*end), published, 1e-9 * published) << l;
    }
}

TEST(MetricCatalogueBeyond, AntiDeSitterStaticLightNearsTheBoundaryAtHalfPiL) {
    const double l = 10;
    const auto st = catalogueMetric("anti_de_sitter_static", {{"l", l}});
    const auto gd = [](double x) { return 2 * std::atan(std::tanh(0.5 * x)); };  // Gudermannian
    for (const double r1 : {20.0, 60.0}) {
        const auto end = traceUntil(*st, rayFrom(*st, Vec4(0, 1e-3, 0, 0), Vec3(1, 0, 0)),
                                    [&](const PhasePoint& q) { return chartRadius(q) - r1; });
        ASSERT_TRUE(end.has_value());
        const double published = l * (gd(r1 / l) - gd(1e-3 / l));
        report("anti_de_sitter_static l = 10", "time for radial light to r = " + decimals(r1, 0), published, end->x[0]);
        EXPECT_NEAR(end->x[0], published, 1e-9 * published) << r1;
    }
}

// Comoving distance to redshift z in a flat FLRW universe (Hogg 1999, eq. 15), by Simpson's rule
// on 20000 intervals (converged to 1e-15 here): an independent integral of the Friedmann equation.
double comovingDistance(double z, double H0, double Om) {
    const int n = 20000;
    const auto integrand = [&](double zz) { return 1 / (H0 * std::sqrt(Om * std::pow(1 + zz, 3) + 1 - Om)); };
    double sum = integrand(0) + integrand(z);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * integrand(z * k / n);
    return sum * z / (3 * n);
}

TEST(MetricCatalogueBeyond, EinsteinDeSitterAndLambdaCdmComovingDistanceAgainstRedshift) {
    const double H0 = 0.1;
    const auto eds = catalogueMetric("flrw_einstein_de_sitter", {{"H0", H0}});
    const auto eds_a = [&](double t) { return std::pow(1 + 1.5 * H0 * t, 2.0 / 3); };
    const double Om = 0.3, OL = 0.7;
    const auto lcdm = catalogueMetric("flrw_lambda_cdm", {{"H0", H0}, {"Om", Om}});
    const double age = 2 * std::asinh(std::sqrt(OL / Om)) / (3 * std::sqrt(OL) * H0);  // Weinberg eq. 1.5.42
    const auto lcdm_a = [&](double t) {
        return std::cbrt(Om / OL) * std::pow(std::sinh(1.5 * std::sqrt(OL) * H0 * (t + age)), 2.0 / 3);
    };
    for (const double z : {1.0, 5.0}) {
        // Past-directed rays from the observer at the origin today, stopped where a = 1/(1 + z).
        const auto edsEnd = traceUntil(*eds, rayFrom(*eds, Vec4(0, 0, 0, 0), Vec3(1, 0, 0), true),
                                       [&](const PhasePoint& q) { return eds_a(q.x[0]) * (1 + z) - 1; });
        ASSERT_TRUE(edsEnd.has_value());
        const double edsPublished = 2 / H0 * (1 - 1 / std::sqrt(1 + z));
        report("flrw_einstein_de_sitter H0 = 0.1", "comoving distance to z = " + decimals(z, 0), edsPublished,
               chartRadius(*edsEnd));
        EXPECT_NEAR(chartRadius(*edsEnd), edsPublished, 1e-9 * edsPublished) << z;
        EXPECT_NEAR(comovingDistance(z, H0, 1), edsPublished, 1e-12 * edsPublished);  // the quadrature itself

        const auto lcdmEnd = traceUntil(*lcdm, rayFrom(*lcdm, Vec4(0, 0, 0, 0), Vec3(1, 0, 0), true),
                                        [&](const PhasePoint& q) { return lcdm_a(q.x[0]) * (1 + z) - 1; });
        ASSERT_TRUE(lcdmEnd.has_value());
        const double lcdmPublished = comovingDistance(z, H0, Om);
        report("flrw_lambda_cdm H0 = 0.1, Om = 0.3", "comoving distance to z = " + decimals(z, 0), lcdmPublished,
               chartRadius(*lcdmEnd));
        EXPECT_NEAR(chartRadius(*lcdmEnd), lcdmPublished, 1e-9 * lcdmPublished) << z;
    }
}

TEST(MetricCatalogueBeyond, DavidsonUniverseIsRadiationAndRadialLightKeepsItsClosedForm) {
    // Davidson (1991): a perfect fluid of radiation at rest in the chart, p = mu/3, with
    // mu = 12/(5 T^(4/3) (1 + rho^2)^(12/5)) (8 pi G = 1, Davidson's time T = 1 + t), read off
    // G_ab u^a u^b and G_ab e^a e^b for the fluid's velocity u and unit vectors e along rho, phi, z.
    const auto st = catalogueMetric("davidson");
    const lc::CurvatureProbe probe(*st);
    double worstDensity = 0, worstRatio = 0, worstScalar = 0;
    for (const auto& [T, rho] : {std::pair{1.0, 0.5}, std::pair{2.5, 1.7}, std::pair{0.3, 3.0}}) {
        const Vec4 x(T - 1, rho, 0, 0);  // on the chart's x axis: e_rho = e_x, e_phi = e_y
        const lc::CurvatureAt c = probe.at(x);
        const auto along = [&](int k) { return c.einstein(k, k) / std::abs(c.g(k, k)); };
        const double mu = along(0), published = 12 / (5 * std::pow(T, 4.0 / 3) * std::pow(1 + rho * rho, 2.4));
        worstDensity = std::max(worstDensity, std::abs(mu / published - 1));
        for (const int k : {1, 2, 3}) worstRatio = std::max(worstRatio, std::abs(along(k) / mu - 1.0 / 3));
        worstScalar = std::max(worstScalar, std::abs(c.ricciScalar) / mu);
    }
    report("davidson", "density mu (G_ab u^a u^b) / 12/(5 T^(4/3) (1+rho^2)^(12/5)), worst of 3 events", 1,
           1 + worstDensity);
    report("davidson", "pressure / density along rho, phi, z, worst of 3 events", 1.0 / 3, 1.0 / 3 + worstRatio);
    report("davidson", "Ricci scalar / density (radiation: traceless)", 0, worstScalar);
    EXPECT_LT(worstDensity, 1e-12);
    EXPECT_LT(worstRatio, 1e-12);
    EXPECT_LT(worstScalar, 1e-12);

    // Radial light: d rho/dT = (1 + rho^2)^(2/5) T^(-2/3), so 3 (T^(1/3) - T0^(1/3)) is
    // int (1 + s^2)^(-2/5) ds (Simpson's rule, 20 000 intervals).
    const double T0 = 1, rho0 = 0.5, rho1 = 2;
    const int n = 20000;
    double integral = 0;
    for (int i = 0; i <= n; ++i) {
        const double s = rho0 + (rho1 - rho0) * i / n, weight = i == 0 || i == n ? 1 : i % 2 ? 4 : 2;
        integral += weight * std::pow(1 + s * s, -0.4);
    }
    integral *= (rho1 - rho0) / (3.0 * n);
    const double published = std::pow(std::cbrt(T0) + integral / 3, 3);
    const auto end = traceUntil(*st, rayFrom(*st, Vec4(T0 - 1, rho0, 0, 0), Vec3(1, 0, 0)),
                                [&](const PhasePoint& q) { return cylinderRadius(q) - rho1; });
    ASSERT_TRUE(end.has_value());
    report("davidson", "T at which radial light from rho = 0.5 at T = 1 reaches rho = 2", published, 1 + end->x[0]);
    EXPECT_NEAR(1 + end->x[0], published, 1e-9 * published);
}

TEST(MetricCatalogueBeyond, EinsteinStaticUniverseLightMeetsAtTheAntipodeAndComesBack) {
    const double R = 5, s0 = 2;
    const auto st = catalogueMetric("einstein_static", {{"R", R}});
    const PhasePoint start = rayFrom(*st, Vec4(0, s0, 0, 0), Vec3(0, 1, 0));
    const auto half = traceUntil(*st, start, [&](const PhasePoint& q) { return q.x[0] - M_PI * R; });
    const auto whole = traceUntil(*st, start, [&](const PhasePoint& q) { return q.x[0] - 2 * M_PI * R; });
    ASSERT_TRUE(half && whole);
    const Vec3 antipode(-R * R / s0, 0, 0);
    report("einstein_static R = 5", "chart distance from the antipode at t = pi R", 0,
           (half->x.tail<3>() - antipode).norm());
    report("einstein_static R = 5", "chart distance from the start at t = 2 pi R", 0,
           (whole->x.tail<3>() - Vec3(s0, 0, 0)).norm());
    EXPECT_LT((half->x.tail<3>() - antipode).norm(), 1e-8 * R);
    EXPECT_LT((whole->x.tail<3>() - Vec3(s0, 0, 0)).norm(), 1e-8 * R);
}

TEST(MetricCatalogueBeyond, BertottiKasnerLightCirclesItsTwoSphereInTwoPiOverRootLambda) {
    const double Lambda = 0.04, r0 = 3;
    const auto st = catalogueMetric("bertotti_kasner", {{"Lambda", Lambda}});
    // Along the sphere (no momentum in r), half way round at t = pi/sqrt(Lambda): phi = pi.
    const auto half = traceUntil(*st, rayFrom(*st, Vec4(0, r0, 0, 0), Vec3(0, 1, 0)),
                                 [&](const PhasePoint& q) { return q.x[0] - M_PI / std::sqrt(Lambda); });
    ASSERT_TRUE(half.has_value());
    report("bertotti_kasner Lambda = 0.04", "chart distance from phi = pi at t = pi/sqrt(Lambda)", 0,
           (half->x.tail<3>() - Vec3(-r0, 0, 0)).norm());
    EXPECT_LT((half->x.tail<3>() - Vec3(-r0, 0, 0)).norm(), 1e-8 * r0);
}

// ---- flat and conical spaces ----

TEST(MetricCatalogueBeyond, MinkowskiInCartesianAndCylindricalChartsBendsNoLight) {
    lc::TraceOptions opt;
    opt.absTol = opt.relTol = 1e-12;
    for (const char* stem : {"minkowski", "minkowski_cylindrical"}) {
        const auto st = catalogueMetric(stem);
        for (const double b : {0.5, 3.0, 40.0}) {
            const lc::DeflectionResult d = lc::measureDeflection(*st, lc::impactParameterRay(*st, b, 1e3), opt);
            report(stem, "deflection at b = " + decimals(b, 1), 0, d.deflection);
            EXPECT_EQ(d.trace.reason, lc::StopReason::Escaped) << stem << " " << b;
            EXPECT_NEAR(d.deflection, 0, 1e-10) << stem << " " << b;
        }
    }
}

TEST(MetricCatalogueBeyond, RindlerRaysAreStraightNullLinesInMinkowskiCoordinates) {
    const double g = 0.1;
    const auto st = catalogueMetric("rindler", {{"g", g}});
    lc::TraceOptions opt = accurateTrace();
    opt.maxAffine = 40;
    const auto samples = lc::sampleGeodesic(*st, rayFrom(*st, Vec4(0, 1 / g, 0, 0), Vec3(0.6, 0.8, 0)), opt);
    ASSERT_GT(samples.size(), 5u);
    // Rindler 1960: T = x sinh(g t), X = x cosh(g t), Y = y, Z = z.
    const auto minkowski = [&](const PhasePoint& q) {
        return Vec4(q.x[1] * std::sinh(g * q.x[0]), q.x[1] * std::cosh(g * q.x[0]), q.x[2], q.x[3]);
    };
    const Vec4 first = minkowski(samples.front().second), last = minkowski(samples.back().second);
    const Vec4 chord = last - first;
    double offLine = 0;
    for (const auto& [affine, q] : samples) {
        const Vec4 d = minkowski(q) - first;
        offLine = std::max(offLine, (d - chord * (d.dot(chord) / chord.squaredNorm())).norm());
    }
    const double nullness = (chord[0] * chord[0] - chord.tail<3>().squaredNorm()) / chord.squaredNorm();
    report("rindler g = 0.1", "largest distance from the Minkowski chord / chord", 0, offLine / chord.norm());
    report("rindler g = 0.1", "chord's (dT^2 - dX^2)/|chord|^2", 0, nullness);
    EXPECT_LT(offLine, 1e-8 * chord.norm());
    EXPECT_NEAR(nullness, 0, 1e-9);
}

TEST(MetricCatalogueBeyond, MisnerSpaceIsMinkowskiAndItsHorizonGeneratorWindsForEverWithinAffineLength2) {
    // Misner (1967), Hawking and Ellis section 5.8: with phi = x + T, t + X = 2 T exp(phi/2) and
    // t - X = -2 exp(-phi/2) map the chart onto Minkowski space.
    const auto st = catalogueMetric("misner");
    const auto minkowski = [](const PhasePoint& q) {
        const double phi = q.x[1] + q.x[0], u = 2 * q.x[0] * std::exp(phi / 2), v = -2 * std::exp(-phi / 2);
        return Vec4((u + v) / 2, (u - v) / 2, q.x[2], q.x[3]);
    };
    lc::TraceOptions opt = accurateTrace();
    opt.maxAffine = 3;
    // A ray the observer at T = 0.5 (among the closed timelike curves) sees, traced back across
    // the chronology horizon T = 0.
    const auto samples =
        lc::sampleGeodesic(*st, nullRayAt(*st, Vec4(0.5, 0, 0, 0), Vec3(-0.6, -0.48, -0.64), true), opt);
    ASSERT_GT(samples.size(), 5u);
    EXPECT_LT(samples.back().second.x[0], 0);  // it crossed T = 0
    const Vec4 first = minkowski(samples.front().second), chord = minkowski(samples.back().second) - first;
    double offLine = 0;
    for (const auto& [affine, q] : samples) {
        const Vec4 d = minkowski(q) - first;
        offLine = std::max(offLine, (d - chord * (d.dot(chord) / chord.squaredNorm())).norm());
    }
    const double nullness = (chord[0] * chord[0] - chord.tail<3>().squaredNorm()) / chord.squaredNorm();
    report("misner", "largest distance from the Minkowski chord / chord, a ray across T = 0", 0,
           offLine / chord.norm());
    report("misner", "chord's (dt^2 - dX^2)/|chord|^2", 0, nullness);
    EXPECT_LT(offLine, 1e-8 * chord.norm());
    EXPECT_NEAR(nullness, 0, 1e-9);

    // The horizon's generator T = 0, k = d/dphi at phi = 0: affine length 2 (1 - exp(-phi/2)), so
    // it winds round the identified circle for ever within affine length 2 (incomplete).
    PhasePoint generator{Vec4::Zero(), Vec4::Zero()};
    generator.p = st->metric(generator.x) * Vec4(0, 1, 0, 0);
    opt.maxAffine = 1.99;
    double worstT = 0, worstAffine = 0, phi = 0;
    for (const auto& [affine, q] : lc::sampleGeodesic(*st, generator, opt)) {
        phi = q.x[1] + q.x[0];
        worstT = std::max(worstT, std::abs(q.x[0]));
        worstAffine = std::max(worstAffine, std::abs(affine - 2 * (1 - std::exp(-phi / 2))));
    }
    report("misner", "generator of T = 0: turns made within affine length 1.99 (2 ln 200 / 2 pi)",
           std::log(200.0) / M_PI, phi / (2 * M_PI));
    report("misner", "generator: |affine - 2 (1 - exp(-phi/2))|, worst sample", 0, worstAffine);
    EXPECT_LT(worstT, 1e-12);
    EXPECT_LT(worstAffine, 1e-9);
    EXPECT_NEAR(phi, 2 * std::log(200.0), 1e-8);
}

// The angle a ray sweeps about the z axis from its start until it reaches radius r2 (beyond its
// start) on its way out: wrapped angle steps summed, the last one cut at the crossing. Steps are
// held to unit length, so none sweeps more than pi.
double sweptAngle(const lc::Spacetime& st, const PhasePoint& start, double r2) {
    const auto angleOf = [](const PhasePoint& q) { return std::atan2(q.x[2], q.x[1]); };
    lc::TraceOptions opt = accurateTrace();
    opt.maxAffine = 1e5;
    opt.maxStep = 1;
    double swept = 0, last = angleOf(start);
    bool reached = false;
    traceGeodesic(st, start, opt, [&](const lc::Segment& s) {
        PhasePoint q = s.s1;
        if (chartRadius(s.s1) >= r2) {
            double lo = s.l0, hi = s.l1;
            for (int k = 0; k < 100; ++k) {
                const double mid = 0.5 * (lo + hi);
                (chartRadius(s.at(mid)) < r2 ? lo : hi) = mid;
            }
            q = s.at(0.5 * (lo + hi));
            reached = true;
        }
        swept += std::remainder(angleOf(q) - last, 2 * M_PI);
        last = angleOf(q);
        return reached;
    });
    EXPECT_TRUE(reached);
    return swept;
}

TEST(MetricCatalogueBeyond, GlobalMonopoleAndCosmicStringConesSweepPiOverK) {
    // On a cone dr^2 + k^2 r^2 dphi^2 a ray is straight in psi = k phi, with closest approach
    // d = b/k: from r1 in to d and out to r2 it sweeps (acos(d/r1) + acos(d/r2))/k; far away,
    // pi/k (Barriola and Vilenkin 1989; Vilenkin 1981 with k = 1 - 4 mu, deficit 8 pi mu).
    const double b = 5, D = 100, r2 = 200;
    for (const auto& [stem, parameter, value, k] :
         {std::tuple{"barriola_vilenkin", "k", 0.8, 0.8}, std::tuple{"cosmic_string", "mu", 0.05, 0.8}}) {
        const auto st = catalogueMetric(stem, {{parameter, value}});
        const PhasePoint start = lc::impactParameterRay(*st, b, D);
        const double r1 = chartRadius(start), d = b / k;
        const double published = (std::acos(d / r1) + std::acos(d / r2)) / k;
        const double ours = std::abs(sweptAngle(*st, start, r2));
        report(std::string(stem) + " " + parameter + " = " + decimals(value, 2),
               "angle swept, b = 5, from r = 100 to r = 200 (asymptotically pi/k = " + decimals(M_PI / k, 4) + ")",
               published, ours);
        EXPECT_NEAR(ours, published, 1e-9 * published) << stem;
    }
}

TEST(MetricCatalogueBeyond, PlaneWaveFocusesRaysAtPenrosesFocalLength) {
    // Rays entering along -z, against the wave: x'' = A x, y'' = -A y in u = t - z.
    const double A = 0.01, x0 = 1, y0 = 2, u1 = 4;
    const auto st = catalogueMetric("plane_wave", {{"A", A}});
    const auto at = traceUntil(*st, rayFrom(*st, Vec4(0, x0, y0, 0), Vec3(0, 0, -1)),
                               [&](const PhasePoint& q) { return q.x[0] - q.x[3] - u1; });
    ASSERT_TRUE(at.has_value());
    const double x = x0 * std::cosh(std::sqrt(A) * u1), y = y0 * std::cos(std::sqrt(A) * u1);
    report("plane_wave A = 0.01", "x at u = 4 (spreading)", x, at->x[1]);
    report("plane_wave A = 0.01", "y at u = 4 (focusing)", y, at->x[2]);
    EXPECT_NEAR(at->x[1], x, 1e-9 * x);
    EXPECT_NEAR(at->x[2], y, 1e-9 * y);

    const double strong = 0.1;  // the focus within the sandwich
    const auto st2 = catalogueMetric("plane_wave", {{"A", strong}});
    const auto focus = traceUntil(*st2, rayFrom(*st2, Vec4(0, x0, y0, 0), Vec3(0, 0, -1)),
                                  [&](const PhasePoint& q) { return q.x[2]; });
    ASSERT_TRUE(focus.has_value());
    const double focal = M_PI / (2 * std::sqrt(strong));
    report("plane_wave A = 0.1", "focal length in u", focal, focus->x[0] - focus->x[3]);
    EXPECT_NEAR(focus->x[0] - focus->x[3], focal, 1e-7 * focal);
}

// ---- wormholes ----

// A ray that crossed the throat and reached the far side's sky (the file's other_end).
bool reachesTheFarSide(const lc::TraceResult& r) { return r.reason == lc::StopReason::OtherEnd; }

TEST(MetricCatalogueBeyond, EllisDrainholeShadowAtItsPhotonSphereRhoEquals3m) {
    // Ellis (1973): F = exp(-(2m/a)(pi/2 - atan((rho - m)/a))), r^2 = ((rho - m)^2 + a^2)/F. The
    // photon sphere is the least r^2/F: d/drho ln(r^2/F) = (2(rho - m) - 4m)/((rho - m)^2 + a^2)
    // vanishes at rho = 3m, and b_c = r/sqrt(F) there. Rays inside it cross the throat (rho = 2m)
    // to the far side's sky; m = 0 is the Ellis wormhole, b_c = n.
    for (const double mu : {0.0, 0.3, 0.5}) {  // n = 1
        const auto st = catalogueMetric("ellis_drainhole", {{"mu", mu}});
        const double m = mu, a = std::sqrt(1 - m * m);
        const double published = std::sqrt(1 + 3 * m * m) * std::exp(2 * m / a * (M_PI / 2 - std::atan(2 * m / a)));
        const double ours = criticalImpact(*st, 0.98 * published, 1.02 * published, 1e4, reachesTheFarSide);
        report("ellis_drainhole m/n = " + decimals(mu, 1), "critical impact b_c / n", published, ours);
        EXPECT_NEAR(ours, published, 1e-8 * published) << mu;
    }
}

TEST(MetricCatalogueBeyond, EllisWormholeLetsThroughExactlyTheRaysInsideItsThroat) {
    // Ellis (1973) without gravity: r(l)^2 = l^2 + b^2, so a ray crosses iff its impact parameter
    // is below the throat's radius b (Chetouani and Clement 1984).
    for (const double b : {1.0, 1.3}) {
        const auto st = catalogueMetric("ellis_wormhole", {{"b", b}});
        const double ours = criticalImpact(*st, 0.98 * b, 1.02 * b, 1e4, reachesTheFarSide);
        report("ellis_wormhole b = " + decimals(b, 1), "critical impact b_c", b, ours);
        EXPECT_NEAR(ours, b, 1e-8 * b) << b;
    }
}

TEST(MetricCatalogueBeyond, InterstellarWormholeLetsThroughExactlyTheRaysInsideItsThroat) {
    // Morris and Thorne (1988) with Phi = 0, James et al. (2015)'s shape: a ray of impact
    // parameter b turns where r(l) = b, so it crosses to the far side if and only if b < rho, the
    // least r, whatever the throat's length 2a and lensing width M.
    for (const auto& [a, M] : {std::pair{0.0, 0.2}, std::pair{0.0, 0.05}, std::pair{0.02, 0.2}}) {  // rho = 1
        const auto st = catalogueMetric("morris_thorne_dneg", {{"a", a}, {"M", M}});
        const double ours = criticalImpact(*st, 0.98, 1.02, 1e4, reachesTheFarSide);
        report("morris_thorne_dneg a = " + decimals(a, 2) + ", M = " + decimals(M, 2), "critical impact b_c / rho", 1,
               ours);
        EXPECT_NEAR(ours, 1, 1e-8) << a << " " << M;
    }
}

TEST(MetricCatalogueBeyond, BesselGravitationalWaveIsVacuum) {
    // Kramer (1999): an exact vacuum solution, R_ab = 0, though curved (an Einstein-Rosen wave).
    // Ricci's largest component in the observer's orthonormal frame, against the size of the
    // curvature, sqrt(R_abcd R^abcd); and g_tt on the axis, -exp(-2C cos t).
    for (const double C : {0.5, 1.5}) {
        const auto st = catalogueMetric("bessel_gravitational_wave", {{"C", C}});
        const lc::CurvatureProbe probe(*st);
        double worst = 0, smallestCurvature = 1e300;
        for (const Vec4& x :
             {Vec4(0.7, 1.3, 0, 0.2), Vec4(2.0, 0.4, 2.1, -1), Vec4(-1.1, 0.02, -0.01, 0), Vec4(0.3, 3.5, 3.4, 0)}) {
            const lc::CurvatureAt c = probe.at(x);
            const double size = std::sqrt(std::abs(c.kretschmann));
            smallestCurvature = std::min(smallestCurvature, size);
            // R_ab e_i^a e_j^b with e_i = d_i / sqrt|g_ii| (g is diagonal on the x axis; off it,
            // bounded by the coordinate components over the diagonal's scale).
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b)
                    worst =
                        std::max(worst, std::abs(c.ricci(a, b)) / std::sqrt(std::abs(c.g(a, a) * c.g(b, b))) / size);
        }
        report("bessel_gravitational_wave C = " + decimals(C, 1),
               "largest Ricci component / sqrt(Kretschmann), 4 events", 0, worst);
        EXPECT_GT(smallestCurvature, 1e-3) << C;  // curved: the test is not of flat space
        EXPECT_LT(worst, 1e-10) << C;
        for (const double t : {0.0, 1.0, 2.5}) {
            const double gtt = st->metric(Vec4(t, 0, 0, 0.5))(0, 0);  // Lightcone's (+,-,-,-)
            EXPECT_NEAR(gtt, std::exp(-2 * C * std::cos(t)), 1e-14) << C << " " << t;
        }
    }
}

// ---- warp drives ----

// dx/dt of light moving along +x and along -x at an event (k = g^-1 p).
std::pair<double, double> lightSpeedsAlongX(const lc::Spacetime& st, const Vec4& x) {
    const lc::Mat4 gi = st.inverseMetric(x);
    const PhasePoint ahead = nullRayAt(st, x, Vec3(-1, 0, 0)), behind = nullRayAt(st, x, Vec3(1, 0, 0));
    const Vec4 ka = gi * ahead.p, kb = gi * behind.p;
    return {ka[1] / ka[0], kb[1] / kb[0]};
}

TEST(MetricCatalogueBeyond, NatarioBubbleHasNoExpansionWhereAlcubierresHasThePublishedOne) {
    const double v = 1.1, R = 1, sigma = 8;
    const auto natario = catalogueMetric("natario", {{"v", v}, {"R", R}, {"sigma", sigma}});
    const auto alcubierre = catalogueMetric("alcubierre", {{"v", v}, {"R", R}, {"sigma", sigma}});
    // div X of the shift: in the signature (+,-,-,-), g_ti = X^i, so div X = sum_i d_i g_ti.
    const auto divergence = [](const lc::Spacetime& st, const Vec4& x) {
        lc::Mat4 g;
        std::array<lc::Mat4, 4> dg;
        st.metricAndDerivatives(x, g, dg);
        return dg[1](0, 1) + dg[2](0, 2) + dg[3](0, 3);
    };
    // Alcubierre 1994, eq. 12: theta = v (x_s/r_s) df/dr_s.
    const auto dfdr = [&](double r) {
        const auto sech2 = [](double q) { return 1 / (std::cosh(q) * std::cosh(q)); };
        return sigma * (sech2(sigma * (r + R)) - sech2(sigma * (r - R))) / (2 * std::tanh(sigma * R));
    };
    double worstNatario = 0, worstAlcubierre = 0, largest = 0;
    for (const Vec3& p : {Vec3(1.0, 0.2, 0.1), Vec3(0.7, -0.6, 0.3), Vec3(-0.9, 0.1, 0.5), Vec3(0.2, 1.05, -0.1)}) {
        const double rs = p.norm();
        const double published = v * p.x() / rs * dfdr(rs);
        largest = std::max(largest, std::abs(published));
        worstAlcubierre =
            std::max(worstAlcubierre, std::abs(divergence(*alcubierre, Vec4(0, p.x(), p.y(), p.z())) - published));
        worstNatario = std::max(worstNatario, std::abs(divergence(*natario, Vec4(0, p.x(), p.y(), p.z()))));
    }
    report("alcubierre v = 1.1", "expansion in the wall, worst of 4 events (largest " + decimals(largest, 2) + ")", 0,
           worstAlcubierre);
    report("natario v = 1.1", "expansion in the wall, worst of 4 events", 0, worstNatario);
    EXPECT_GT(largest, 1);  // the events sit in the wall
    EXPECT_LT(worstAlcubierre, 1e-12 * largest);
    EXPECT_LT(worstNatario, 1e-12 * largest);

    const auto [ahead, behind] = lightSpeedsAlongX(*natario, Vec4(0, 0, 0, 0));
    report("natario v = 1.1", "light's dx/dt at the centre, ahead", v + 1, ahead);
    report("natario v = 1.1", "light's dx/dt at the centre, behind", v - 1, behind);
    EXPECT_NEAR(ahead, v + 1, 1e-12);
    EXPECT_NEAR(behind, v - 1, 1e-12);
}

TEST(MetricCatalogueBeyond, VanDenBroeckPocketSlowsLightByItsBlowUp) {
    const double v = 1.1, alpha = 3;
    const auto st = catalogueMetric("van_den_broeck", {{"v", v}, {"alpha", alpha}});
    const auto [ahead, behind] = lightSpeedsAlongX(*st, Vec4(0, 0, 0, 0));
    report("van_den_broeck v = 1.1, alpha = 3", "light's dx/dt at the centre, ahead", v + 1 / (1 + alpha), ahead);
    report("van_den_broeck v = 1.1, alpha = 3", "light's dx/dt at the centre, behind", v - 1 / (1 + alpha), behind);
    EXPECT_NEAR(ahead, v + 1 / (1 + alpha), 1e-7);  // B's smooth step is 1 - 2e-9 short of 1 + alpha
    EXPECT_NEAR(behind, v - 1 / (1 + alpha), 1e-7);
}

TEST(MetricCatalogueBeyond, KrasnikovTubeBringsLightHomeBackwardsInTime) {
    // Everett and Roman (1997): inside the tube k = delta - 1, and of the two null directions along
    // x, -(dt - dx)(dt + k dx) = 0, the one going home, dt = -k dx, is future-directed
    // (g(k, d/dt) = -delta/2 < 0 in (-,+,+,+)): light comes home earlier by (1 - delta) per unit
    // of x. Started at x = D - 1 once the tube has formed there (t - x > rmax + eps), traced home
    // along the axis to x = 1.
    for (const double delta : {0.2, 0.05}) {
        const double D = 10, ts = 14, xs = D - 1, xe = 1;
        const auto st = catalogueMetric("krasnikov_tube", {{"D", D}, {"delta", delta}});
        // The null directions along x from the file's g: g_tt + 2 g_tx s + g_xx s^2 = 0 for s = dx/dt
        // has the roots 1 (light going out) and 1/(1 - delta) (light coming home, dt < 0).
        const lc::Mat4 g = st->metric(Vec4(ts, xs, 0, 0));
        const double disc = std::sqrt(g(0, 1) * g(0, 1) - g(0, 0) * g(1, 1));
        const double s1 = (-g(0, 1) - disc) / g(1, 1), s2 = (-g(0, 1) + disc) / g(1, 1);
        EXPECT_NEAR(std::min(s1, s2), 1, 1e-12) << delta;
        EXPECT_NEAR(std::max(s1, s2), 1 / (1 - delta), 1e-12) << delta;
        PhasePoint home{Vec4(ts, xs, 0, 0), Vec4::Zero()};
        const Vec4 k(-(1 - delta), -1, 0, 0);
        home.p = st->metric(home.x) * k;
        EXPECT_LT(std::abs(home.p.dot(st->inverseMetric(home.x) * home.p)), 1e-12);
        EXPECT_GT(home.p[0], 0) << "future-directed: k.d/dt > 0 in (+,-,-,-)";
        const auto end = traceUntil(*st, home, [&](const PhasePoint& q) { return q.x[1] - xe; });
        ASSERT_TRUE(end.has_value());
        const double published = ts - (1 - delta) * (xs - xe);
        report("krasnikov_tube delta = " + decimals(delta, 2),
               "time light sent home at t = 14 from x = 9 reaches x = 1", published, end->x[0]);
        EXPECT_NEAR(end->x[0], published, 1e-9 * published) << delta;
    }
}

}  // namespace
