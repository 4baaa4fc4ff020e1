// SPDX-License-Identifier: BSD-3-Clause
// Curvature, matter and tides from exact second derivatives of the metric (core/curvature),
// each against a closed form from the literature (docs/PHYSICS.md section 13), in the charts the
// tracer uses (Kerr-Schild, the Goedel axis-regular chart, formula metrics' pull-backs) and at
// events off every symmetry axis.
#include "core/curvature/curvature.hpp"
#include "core/curvature/curvature_field.hpp"
#include "core/curvature/matter.hpp"
#include "core/curvature/observer_field.hpp"
#include "core/formula/formula_metric.hpp"
#include "core/metrics/alcubierre.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "tests/common/curvature_oracles.hpp"
#include "tests/common/test_metric.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {
using namespace lc;

// Events off the axis and off the equator, at Boyer-Lindquist radii from near the horizon out.
std::vector<Vec4> kerrSchildEvents() {
    return {Vec4(0.3, 5.0, -2.0, 1.5), Vec4(-1.0, 2.1, 0.4, -0.9), Vec4(2.0, -1.2, 1.9, 0.2),
            Vec4(0.0, 12.0, 7.0, -20.0)};
}

double relative(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

// Kerr-Newman's Boyer-Lindquist radius and cos(theta) at a Kerr-Schild event.
std::pair<double, double> boyerLindquist(const Vec4& x, double a) {
    const double r = kerrSchildRadius(x(1), x(2), x(3), a);
    return {r, x(3) / r};
}

TEST(Curvature, SchwarzschildKretschmannIs48MSquaredOverRToTheSixth) {
    const Schwarzschild bh(1.7);
    const CurvatureProbe probe(bh);
    for (const Vec4& x : kerrSchildEvents()) {
        const CurvatureAt c = probe.at(x);
        const double r = x.tail<3>().norm();
        const double K = 48 * 1.7 * 1.7 / std::pow(r, 6);  // e.g. MTW eq. 31.8 squared and summed
        EXPECT_LT(relative(c.kretschmann, K), 1e-10) << "r = " << r;
        // Vacuum: Ricci vanishes to round-off relative to the curvature's size, so Weyl = Riemann.
        EXPECT_LT(c.ricci.cwiseAbs().maxCoeff(), 1e-12 * std::sqrt(K));
        EXPECT_LT(relative(c.weylSquared, K), 1e-10);
    }
}

// Kerr's Kretschmann scalar (Henry 2000, ApJ 535, 350, eq. 9 with Q = 0, test::kerrNewmanKretschmann):
// K = 48 M^2 (r^2 - a^2 c^2)(r^4 - 14 a^2 r^2 c^2 + a^4 c^4) / (r^2 + a^2 c^2)^6, c = cos(theta).
TEST(Curvature, KerrKretschmannMatchesTheClosedFormInBoyerLindquistRAndTheta) {
    for (double a : {0.5, 0.9, 0.998}) {
        const KerrNewman bh(1.0, a, 0.0);
        const CurvatureProbe probe(bh);
        for (const Vec4& x : kerrSchildEvents()) {
            const auto [r, c] = boyerLindquist(x, a);
            const double K = test::kerrNewmanKretschmann(1.0, a, 0.0, r, c);
            const CurvatureAt cv = probe.at(x);
            EXPECT_LT(std::abs(cv.kretschmann - K), 1e-10 * std::abs(K) + 1e-14) << "a = " << a << " r = " << r;
            EXPECT_LT(cv.ricci.cwiseAbs().maxCoeff(), 1e-11 * std::sqrt(std::abs(K) + 1e-30));
        }
    }
}

// Reissner-Nordstrom (Henry 2000 eq. 9 with a = 0): K = (48 M^2 r^2 - 96 M Q^2 r + 56 Q^4) / r^8;
// its field's energy density for a static observer is E^2 / 8 pi = Q^2 / (8 pi r^4), with a
// radial tension and tangential pressures of the same size (e.g. Misner-Thorne-Wheeler
// eq. 5.23), which meets every energy condition; R = 0 (the field is traceless).
TEST(Curvature, ReissnerNordstromKretschmannAndTheFieldsEnergyDensity) {
    const double M = 1.0, Q = 0.6;
    const KerrNewman rn(M, 0.0, Q);
    const CurvatureProbe probe(rn);
    for (const Vec4& x : kerrSchildEvents()) {
        const double r = x.tail<3>().norm();
        const CurvatureAt c = probe.at(x);
        const double K = test::kerrNewmanKretschmann(M, 0.0, Q, r, 0.0);
        EXPECT_LT(relative(c.kretschmann, K), 1e-10);
        EXPECT_LT(std::abs(c.ricciScalar), 1e-12 * std::sqrt(K));

        const auto frame = observerFrameAt(c.g, c.gInverse, x, ObserverField::Static);
        ASSERT_TRUE(frame.has_value());
        const Mat4 T = inFrame(stressEnergyTensor(c, 0), *frame);
        const MatterSeen seen = matterSeenBy(T);
        const double rho = Q * Q / (8 * kPi * std::pow(r, 4));
        EXPECT_LT(relative(seen.energyDensity, rho), 1e-9);
        EXPECT_LT(seen.energyFlux.norm(), 1e-9 * rho);
        EXPECT_LT(relative(seen.principalPressures(0), -rho), 1e-9);  // radial tension
        EXPECT_LT(relative(seen.principalPressures(1), rho), 1e-9);
        EXPECT_LT(relative(seen.principalPressures(2), rho), 1e-9);
        const MatterClass m = classifyMatter(T);
        EXPECT_EQ(m.type, HawkingEllisType::I);
        EXPECT_FALSE(m.sampled);
        EXPECT_TRUE(m.nullEnergy.holds && m.weak.holds && m.strong.holds && m.dominant.holds);
    }
}

// Kerr-Newman with spin and charge together (Henry 2000, ApJ 535, 350, eq. 9: the full form in
// tests/common/curvature_oracles.hpp), and the electromagnetic field is traceless: R = 0.
TEST(Curvature, KerrNewmanKretschmannWithSpinAndChargeTogether) {
    for (const auto& [a, Q] : {std::pair{0.6, 0.5}, std::pair{0.3, 0.9}, std::pair{0.8, 0.59}}) {
        const double M = 1;
        const KerrNewman bh(M, a, Q);
        const CurvatureProbe probe(bh);
        for (const Vec4& x : kerrSchildEvents()) {
            const auto [r, c] = boyerLindquist(x, a);
            const double K = test::kerrNewmanKretschmann(M, a, Q, r, c);
            const CurvatureAt cv = probe.at(x);
            EXPECT_LT(std::abs(cv.kretschmann - K), 1e-10 * std::abs(K)) << "a = " << a << " Q = " << Q << " r = " << r;
            EXPECT_LT(std::abs(cv.ricciScalar), 1e-11 * std::sqrt(std::abs(K)));
        }
    }
}

// Goedel's solution (Goedel 1949, Rev. Mod. Phys. 21, 447) in the project's normalisation
// (docs/PHYSICS.md section 1, a = Goedel's a): R_ab = u_a u_b / a^2 with u = d/dt the dust;
// dust of density 1/(8 pi a^2) with Lambda = -1/(2 a^2), or, read without Lambda, a stiff fluid
// rho = p = 1/(16 pi a^2). Homogeneous: the same everywhere, inside and beyond the horizon 2a.
TEST(Curvature, GoedelIsDustWithANegativeCosmologicalConstantEverywhere) {
    const double a = 1.3;
    const GodelCartesian godel(a);
    const CurvatureProbe probe(godel);
    const std::vector<Vec4> events{Vec4(0, 0, 0, 0), Vec4(0.7, 0.4, -1.1, 2.0), Vec4(-3, 2 * a * 1.4, 0.3, -1),
                                   Vec4(5, -1.0, -3.5, 0.2)};
    double firstK = 0;
    for (const Vec4& x : events) {
        const CurvatureAt c = probe.at(x);
        const Vec4 uLower = c.g.col(0);  // u = d/dt, g_tt = 1
        const Mat4 expected = uLower * uLower.transpose() / (a * a);
        EXPECT_LT((c.ricci - expected).cwiseAbs().maxCoeff(), 1e-12);
        if (firstK == 0) firstK = c.kretschmann;
        EXPECT_LT(relative(c.kretschmann, firstK), 1e-10);
        EXPECT_LT(relative(c.ricciSquared, 1 / std::pow(a, 4)), 1e-10);

        const auto frame = observerFrameAt(c.g, c.gInverse, x, ObserverField::StaticElseNormal);
        ASSERT_TRUE(frame.has_value());
        const MatterClass dust = classifyMatter(inFrame(stressEnergyTensor(c, -1 / (2 * a * a)), *frame));
        EXPECT_EQ(dust.type, HawkingEllisType::I);
        EXPECT_LT(relative(dust.restDensity, 1 / (8 * kPi * a * a)), 1e-10);
        EXPECT_LT(dust.restPressures.cwiseAbs().maxCoeff(), 1e-12);
        const MatterClass stiff = classifyMatter(inFrame(stressEnergyTensor(c, 0), *frame));
        EXPECT_LT(relative(stiff.restDensity, 1 / (16 * kPi * a * a)), 1e-10);
        for (int i = 0; i < 3; ++i) EXPECT_LT(relative(stiff.restPressures(i), 1 / (16 * kPi * a * a)), 1e-10);
    }
}

formula::FormulaMetricSource deSitterSource() {
    formula::FormulaMetricSource s;
    s.name = "de-sitter-flat-slicing";
    s.lineElement = formula::FormulaText{"ds2", "-dt^2 + exp(2*H*t)*(dx^2 + dy^2 + dz^2)"};
    s.parameters = {{"H", 1, 1e-6, 1e6, ""}};
    return s;
}

// De Sitter space, typed as text: maximally symmetric, R_abcd = -H^2 (g_ac g_bd - g_ad g_bc) in
// this signature, so K = 24 H^4, Weyl = 0 and R = -12 H^2 (+12 H^2 in (-,+,+,+)). With
// Lambda = 3 H^2 it is vacuum; read without Lambda it is a fluid with p = -rho = -3 H^2 / 8 pi,
// which breaks the strong energy condition by rho + 3p = -2 rho.
TEST(Curvature, DeSitterTypedAsTextHasConstantCurvatureAndItsVacuumEnergy) {
    const double H = 0.7;
    const formula::FormulaMetric ds(deSitterSource(), {{"H", H}});
    const CurvatureProbe probe(ds);
    for (const Vec4& x : {Vec4(0, 1, 2, 3), Vec4(1.5, -4, 0.5, 0.1)}) {
        const CurvatureAt c = probe.at(x);
        EXPECT_LT(relative(c.kretschmann, 24 * std::pow(H, 4)), 1e-12);
        EXPECT_LT(relative(c.ricciScalar, -12 * H * H), 1e-12);
        EXPECT_LT(std::abs(c.weylSquared), 1e-10 * std::pow(H, 4));
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                for (int cc = 0; cc < 4; ++cc)
                    for (int d = 0; d < 4; ++d)
                        EXPECT_NEAR(c.riemann(a, b, cc, d), -H * H * (c.g(a, cc) * c.g(b, d) - c.g(a, d) * c.g(b, cc)),
                                    1e-11 * c.g.cwiseAbs().maxCoeff() * c.g.cwiseAbs().maxCoeff());
        const auto frame = observerFrameAt(c.g, c.gInverse, x, ObserverField::StaticElseNormal);
        ASSERT_TRUE(frame.has_value());
        EXPECT_LT(inFrame(stressEnergyTensor(c, 3 * H * H), *frame).cwiseAbs().maxCoeff(), 1e-12);
        const MatterClass vacuumEnergy = classifyMatter(inFrame(stressEnergyTensor(c, 0), *frame));
        const double rho = 3 * H * H / (8 * kPi);
        EXPECT_LT(relative(vacuumEnergy.restDensity, rho), 1e-12);
        EXPECT_TRUE(vacuumEnergy.nullEnergy.holds && vacuumEnergy.weak.holds && vacuumEnergy.dominant.holds);
        EXPECT_FALSE(vacuumEnergy.strong.holds);
        EXPECT_LT(relative(vacuumEnergy.strong.violation, 2 * rho), 1e-10);
    }
}

// The Ellis wormhole, typed as text in an isotropic chart as data/metrics/ellis_wormhole.json
// (ds^2 = -dt^2 + psi^2 (dx^2 + dy^2 + dz^2), psi = 1 + b^2/4R^2): Morris & Thorne
// (1988, Am. J. Phys. 56, 395, eqs. 14 with b(r) = b0^2/r, Phi = 0) give at areal radius r
// rho = -b^2/(8 pi r^4), radial pressure -b^2/(8 pi r^4) and tangential +b^2/(8 pi r^4): exotic
// matter, the null condition failing by b^2/(4 pi r^4), most at the throat.
TEST(Curvature, EllisWormholeNeedsExoticMatterAsMorrisAndThorneFound) {
    formula::FormulaMetricSource s;
    s.lineElement = formula::FormulaText{"ds2", "-dt^2 + psi^2*(dx^2 + dy^2 + dz^2)"};
    s.definitions = {{"define[0]", "R = sqrt(x^2 + y^2 + z^2)"}, {"define[1]", "psi = 1 + b^2/(4*R^2)"}};
    s.parameters = {{"b", 1, 1e-3, 1e3, ""}};
    const double b = 1.3;
    const formula::FormulaMetric ellis(s, {{"b", b}});
    const CurvatureProbe probe(ellis);
    for (const Vec4& x : {Vec4(0, 0.65, 0, 0), Vec4(0, 0.3, -0.5, 0.4), Vec4(2, 2.0, 1.0, -3.0)}) {
        const double R = x.tail<3>().norm(), r = R + b * b / (4 * R), q = b * b / (8 * kPi * std::pow(r, 4));
        const CurvatureAt c = probe.at(x);
        const auto frame = observerFrameAt(c.g, c.gInverse, x, ObserverField::Static);
        ASSERT_TRUE(frame.has_value());
        const Mat4 T = inFrame(stressEnergyTensor(c, 0), *frame);
        const MatterSeen seen = matterSeenBy(T);
        EXPECT_LT(relative(seen.energyDensity, -q), 1e-10) << "r = " << r;
        EXPECT_LT(relative(seen.principalPressures(0), -q), 1e-10);
        EXPECT_LT(relative(seen.principalPressures(2), q), 1e-10);
        const MatterClass m = classifyMatter(T);
        EXPECT_FALSE(m.nullEnergy.holds);
        EXPECT_LT(relative(m.nullEnergy.violation, 2 * q), 1e-10);
    }
}

// Alcubierre's warp bubble (Alcubierre 1994, Class. Quantum Grav. 11, L73, eq. 19): the Eulerian
// observers (normal to t = const) measure rho = -(1/8 pi) v^2 (y^2 + z^2) / (4 r_s^2) (df/dr_s)^2,
// negative in the wall, so the weak energy condition fails there by that amount at least.
TEST(Curvature, AlcubierreEulerianEnergyDensityIsNegativeAsAlcubierreFound) {
    const double v = 0.8, R = 1.0, sigma = 4.0;
    const Alcubierre warp(v, R, sigma);
    const CurvatureProbe probe(warp);
    for (const Vec4& x : {Vec4(0.5, 0.4 + 0.1, 0.8, 0.5), Vec4(0, 0.3, -0.2, 1.05), Vec4(2, 1.6, 0.9, 0.0)}) {
        const CurvatureAt c = probe.at(x);
        const double y = x(2), z = x(3), X = x(1) - v * x(0);
        const double rs = std::sqrt(X * X + y * y + z * z);
        const double rho = test::alcubierreEulerianDensity(v, R, sigma, X, y, z);
        const auto frame = observerFrameAt(c.g, c.gInverse, x, ObserverField::Normal);
        ASSERT_TRUE(frame.has_value());
        const Mat4 T = inFrame(stressEnergyTensor(c, 0), *frame);
        EXPECT_LT(relative(matterSeenBy(T).energyDensity, rho), 1e-9) << "r_s = " << rs;
        const MatterClass m = classifyMatter(T);
        EXPECT_FALSE(m.weak.holds);
        EXPECT_GE(m.weak.violation, -rho * (1 - 1e-9));
    }
}

// The tidal tensor of a static observer in Schwarzschild: -2M/r^3 radially, M/r^3 twice (MTW
// eq. 31.4b in the static orthonormal frame). A radial boost leaves it unchanged (MTW exercise
// 32.4: a radially falling observer feels the same tides), a test of the frame handling.
TEST(Curvature, SchwarzschildTidesAreMinusTwoMOverRCubedRadiallyForStaticAndFallingObservers) {
    const double M = 2.0;
    const Schwarzschild bh(M);
    const CurvatureProbe probe(bh);
    for (const Vec4& x : {Vec4(0, 9.0, -4.0, 3.0), Vec4(1, -3.0, 2.0, -2.5), Vec4(0, 100, 40, -60)}) {
        const double r = x.tail<3>().norm(), unit = M / std::pow(r, 3);
        const CurvatureAt c = probe.at(x);
        const auto fixed = observerFrameAt(c.g, c.gInverse, x, ObserverField::Static);
        ASSERT_TRUE(fixed.has_value());
        const Vec3 tides = tidalEigenvalues(c, *fixed);
        EXPECT_LT(relative(tides(0), -2 * unit), 1e-10);
        EXPECT_LT(relative(tides(1), unit), 1e-10);
        EXPECT_LT(relative(tides(2), unit), 1e-10);

        // Boost along the radial direction in the static frame: u' = gamma (e0 + beta n_r).
        const Mat4 g = c.g;
        Vec4 radial = Vec4::Zero();
        radial.tail<3>() = x.tail<3>() / r;
        radial -= radial.dot(g * fixed->e[0]) * fixed->e[0];
        radial /= std::sqrt(-radial.dot(g * radial));
        for (double beta : {-0.5, 0.9, -0.999}) {
            const Vec4 u = (fixed->e[0] + beta * radial) / std::sqrt(1 - beta * beta);
            const LocalFrame moving = LocalFrame::withVelocity(bh, x, u);
            const Vec3 boosted = tidalEigenvalues(c, moving);
            EXPECT_LT((boosted - tides).cwiseAbs().maxCoeff(), 1e-9 * unit) << "beta = " << beta;
        }
    }
}

// The tensors' own identities on a metric with no symmetry at all: pair symmetry and the first
// Bianchi identity of Riemann, a trace-free Weyl tensor, and C^2 = K - 2 R_ab R^ab + R^2 / 3.
TEST(Curvature, RiemannAndWeylKeepTheirSymmetriesOnAMetricWithoutAny) {
    const test::RippleMetric ripple;
    const CurvatureProbe probe(ripple);
    const CurvatureAt c = probe.at(Vec4(0.3, -0.4, 0.2, 1.1));
    const double size = std::sqrt(std::abs(c.kretschmann));
    ASSERT_GT(size, 1e-3);
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
            for (int cc = 0; cc < 4; ++cc)
                for (int d = 0; d < 4; ++d) {
                    EXPECT_NEAR(c.riemann(a, b, cc, d), c.riemann(cc, d, a, b), 1e-12 * size);
                    EXPECT_NEAR(c.riemann(a, b, cc, d) + c.riemann(a, cc, d, b) + c.riemann(a, d, b, cc), 0,
                                1e-12 * size);
                }
    for (int b = 0; b < 4; ++b)
        for (int d = 0; d < 4; ++d) {
            double trace = 0;
            for (int a = 0; a < 4; ++a)
                for (int cc = 0; cc < 4; ++cc) trace += c.gInverse(a, cc) * c.weyl(a, b, cc, d);
            EXPECT_NEAR(trace, 0, 1e-12 * size);
        }
    EXPECT_NEAR(c.weylSquared, c.kretschmann - 2 * c.ricciSquared + c.ricciScalar * c.ricciScalar / 3,
                1e-11 * size * size);
}

// Null dust T = mu k k (k null) is Hawking-Ellis type II; a pure energy flux with no density
// (T_01 = f) is type IV and breaks the null condition along -x by 2f.
TEST(Matter, HawkingEllisTypesOfNullDustAndOfAnEnergyFluxWithoutDensity) {
    const Vec4 kLower(1, -1, 0, 0);  // k = (1, 1, 0, 0) lowered with eta
    const MatterClass dust = classifyMatter(0.3 * kLower * kLower.transpose());
    EXPECT_EQ(dust.type, HawkingEllisType::II);
    EXPECT_TRUE(dust.nullEnergy.holds && dust.weak.holds && dust.dominant.holds);
    const MatterClass phantom = classifyMatter(-0.3 * kLower * kLower.transpose());
    EXPECT_EQ(phantom.type, HawkingEllisType::II);
    EXPECT_FALSE(phantom.nullEnergy.holds);

    Mat4 flux = Mat4::Zero();
    flux(0, 1) = flux(1, 0) = 0.25;
    const MatterClass iv = classifyMatter(flux);
    EXPECT_EQ(iv.type, HawkingEllisType::IV);
    EXPECT_TRUE(iv.sampled);
    EXPECT_FALSE(iv.nullEnergy.holds);
    // T(k, k) for k = (1, n): 2 f n_x, lowest -2f along n = -x (found by a descent to 1e-10).
    EXPECT_NEAR(iv.nullEnergy.violation, 0.5, 1e-10);
}

// Where the static observers stop (the ergoregion) the field says so, and "auto" falls back to
// the normal observers; a metric not written as expressions is refused with its name.
TEST(Curvature, ObserverFieldsEndWhereTheyMustAndAMetricWithoutExpressionsIsRefused) {
    const KerrNewman kerr(1.0, 0.9, 0.0);
    const Vec4 ergo(0, 1.8, 0.2, 0.1);  // inside the ergosphere r < 1 + sqrt(1 - a^2 cos^2)
    const Mat4 g = kerr.metric(ergo), gi = g.inverse();
    EXPECT_FALSE(observerFrameAt(g, gi, ergo, ObserverField::Static).has_value());
    const auto normal = observerFrameAt(g, gi, ergo, ObserverField::StaticElseNormal);
    ASSERT_TRUE(normal.has_value());
    EXPECT_NEAR(normal->e[0].dot(g * normal->e[0]), 1, 1e-12);

    class Opaque final : public Spacetime {
    public:
        std::string name() const override { return "opaque"; }
        std::map<std::string, double> parameters() const override { return {}; }
        std::array<std::string, 4> coordinateNames() const override { return {"t", "x", "y", "z"}; }
        Mat4 metric(const Vec4&) const override { return Vec4(1, -1, -1, -1).asDiagonal(); }
        void metricAndDerivatives(const Vec4& x, Mat4& g, std::array<Mat4, 4>& dg) const override {
            g = metric(x);
            for (auto& d : dg) d.setZero();
        }
    };
    try {
        const CurvatureProbe probe{Opaque()};
        FAIL() << "accepted a metric without expressions";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'opaque'"), std::string::npos);
    }
}

// The sampled field: VTK's point order (x fastest), the closed form at every point, NaN with a
// count at the singularity, observer quantities NaN where the static observers end (the
// ergoregion), and a stop asked by the progress callback honoured.
TEST(CurvatureField, SamplesInVtkOrderAndMarksSingularPointsAndMissingObservers) {
    const Schwarzschild bh(1.0);
    ChartGrid grid;
    grid.time = 0.5;
    grid.origin = Vec3(-2, -3, -4);
    grid.spacing = Vec3(1, 1.5, 2);
    grid.dimensions = {5, 5, 5};  // (2, 2, 2) is the origin: the singularity
    const CurvatureField field =
        sampleCurvatureField(bh, grid, {CurvatureQuantity::Kretschmann, CurvatureQuantity::TidalEigenvalues}, {});
    EXPECT_EQ(field.singularPoints, 1u);
    for (int k = 0; k < 5; ++k)
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 5; ++i) {
                const std::size_t p = static_cast<std::size_t>((k * 5 + j) * 5 + i);
                const double r = (grid.origin + grid.spacing.cwiseProduct(Vec3(i, j, k))).norm();
                if (r == 0) {
                    EXPECT_TRUE(std::isnan(field.values[0][p]));
                    continue;
                }
                EXPECT_LT(relative(field.values[0][p], 48 / std::pow(r, 6)), 1e-10) << i << j << k;
                // Inside the horizon (r < 2) d/dt is spacelike: no static observer, so the
                // default field falls back to the normal observers and tides stay defined.
                EXPECT_TRUE(std::isfinite(field.values[1][3 * p])) << "r = " << r;
            }

    const KerrNewman kerr(1.0, 0.9, 0.0);
    ChartGrid equator;
    equator.origin = Vec3(1.5, 0, 0.05);
    equator.spacing = Vec3(0.5, 1, 1);
    // Kerr-Schild x from 1.5 to 5 M: Boyer-Lindquist r = sqrt(x^2 - a^2) near the equator, inside
    // the ergoregion (r < 2 M) for x = 1.5 and 2 only.
    equator.dimensions = {8, 1, 1};
    CurvatureReading staticOnly;
    staticOnly.observers = ObserverField::Static;
    const CurvatureField ergo = sampleCurvatureField(kerr, equator, {CurvatureQuantity::EnergyDensity}, staticOnly);
    EXPECT_EQ(ergo.pointsWithoutObserver, 2u);
    EXPECT_TRUE(std::isnan(ergo.values[0][0]) && std::isnan(ergo.values[0][1]));
    for (std::size_t i = 2; i < 8; ++i) EXPECT_NEAR(ergo.values[0][i], 0, 1e-12);

    ChartGrid big;
    big.dimensions = {64, 64, 8};
    big.origin = Vec3(3, 3, 3);
    int calls = 0;
    const CurvatureField stopped = sampleCurvatureField(bh, big, {CurvatureQuantity::Kretschmann}, {}, [&](double f) {
        ++calls;
        return f < 0.25;
    });
    EXPECT_TRUE(stopped.stopped);
    EXPECT_GE(calls, 2);
    EXPECT_TRUE(std::isfinite(stopped.values[0].front()));
    EXPECT_TRUE(std::isnan(stopped.values[0].back()));
}

}  // namespace
