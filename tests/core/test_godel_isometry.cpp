// SPDX-License-Identifier: BSD-3-Clause
// Killing fields and finite isometries of the Goedel universe. Oracles: the metric of
// core/metrics/godel.hpp (with its exact autodiff derivatives), finite differences taken here in
// the test, and numeric integration of the geodesic equation.
#include "core/godel/geodesic.hpp"
#include "core/godel/isometry.hpp"
#include "core/spacetime/integrator.hpp"
#include "core/metrics/godel.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace lc;
using namespace lc::godel;

namespace {

const KillingField kAll[] = {KillingField::T, KillingField::Phi, KillingField::Z, KillingField::Xi4, KillingField::Xi5};

// Random event with r < 3a (inside and beyond the Goedel radius).
Vec4 randomEvent(std::mt19937& rng, double a, double rmax = 3.0) {
    std::uniform_real_distribution<double> u(-1, 1);
    const double r = rmax * a * std::abs(u(rng)), ph = 3.2 * u(rng);
    return Vec4(5 * u(rng), r * std::cos(ph), r * std::sin(ph), 4 * u(rng));
}

// (L_xi g)_{mn} = xi^k d_k g_mn + g_kn d_m xi^k + g_mk d_n xi^k, with d xi by central differences.
template <class Metric, class Field>
double lieResidual(const Metric& st, const Field& xi, const Vec4& x) {
    Mat4 g;
    std::array<Mat4, 4> dg;
    st.metricAndDerivatives(x, g, dg);
    const Vec4 v = xi(x);
    Mat4 dxi;  // dxi(k, m) = d_m xi^k
    const double h = 1e-6;
    for (int m = 0; m < 4; ++m) {
        Vec4 e = Vec4::Zero();
        e(m) = h;
        dxi.col(m) = (xi(x + e) - xi(x - e)) / (2 * h);
    }
    Mat4 L = Mat4::Zero();
    for (int k = 0; k < 4; ++k) L += v(k) * dg[k];
    L += dxi.transpose() * g + g * dxi;
    return L.cwiseAbs().maxCoeff();
}

Mat4 numericJacobian(const Isometry& I, const Vec4& x) {
    Mat4 J;
    const double h = 1e-6;
    for (int m = 0; m < 4; ++m) {
        Vec4 e = Vec4::Zero();
        e(m) = h;
        J.col(m) = (I.apply(x + e) - I.apply(x - e)) / (2 * h);
    }
    return J;
}

std::vector<Isometry> sampleIsometries(double a) {
    std::vector<Isometry> v;
    v.push_back(Isometry::rotation(a, 0.7));
    v.push_back(Isometry::diskAutomorphism(a, 0.4));
    v.push_back(Isometry::diskAutomorphism(a, -0.93));
    v.push_back(Isometry::timeShift(a, 1.3) * Isometry::zShift(a, -0.4));
    v.push_back(Isometry::movingToOrigin(a, Vec4(0.3, 1.1 * a, -0.6 * a, 0.2)));
    v.push_back(Isometry::movingToOrigin(a, Vec4(-2.0, -3.5 * a, 0.4 * a, 1.0)));  // beyond the horizon
    v.push_back(Isometry::movingToOrigin(a, Vec4(1.0, 0.5 * a, 0.2 * a, 0.0)) * Isometry::diskAutomorphism(a, 0.6) *
                Isometry::rotation(a, -2.0));
    return v;
}

}  // namespace

TEST(GodelKilling, AllFiveSatisfyKillingEquationCartesian) {
    std::mt19937 rng(7);
    for (double a : {1.0, 0.5, 2.0}) {
        const GodelCartesian st(a);
        for (int i = 0; i < 40; ++i) {
            const Vec4 x = randomEvent(rng, a);
            for (KillingField k : kAll) {
                const double res = lieResidual(
                    st, [&](const Vec4& y) { return killingCartesian(k, a, y); }, x);
                EXPECT_LT(res, 1e-7) << "field " << int(k) << " a=" << a << " at " << x.transpose();
            }
        }
    }
}

TEST(GodelKilling, AllFiveSatisfyKillingEquationCylindrical) {
    std::mt19937 rng(11);
    const double a = 1.3;
    const GodelCylindrical st(a);
    for (int i = 0; i < 40; ++i) {
        Vec4 x = toCylindrical(randomEvent(rng, a));
        x(1) = std::max(x(1), 0.1);
        for (KillingField k : kAll) {
            const double res = lieResidual(
                st, [&](const Vec4& y) { return killingCylindrical(k, a, y); }, x);
            EXPECT_LT(res, 1e-7) << "field " << int(k);
            // Both charts describe the same vector field.
            const Vec4 vc = vectorToCartesian(x, killingCylindrical(k, a, x));
            EXPECT_LT((vc - killingCartesian(k, a, toCartesian(x))).cwiseAbs().maxCoeff(), 1e-12);
        }
    }
}

TEST(GodelKilling, NonKillingFieldFailsTheCheck) {
    // The check can fail: d/dX is not a Killing field of the Goedel metric.
    const GodelCartesian st(1.0);
    const double res = lieResidual(
        st, [](const Vec4&) { return Vec4(0, 1, 0, 0); }, Vec4(0, 0.5, 0.3, 0));
    EXPECT_GT(res, 1e-2);
}

TEST(GodelIsometry, PreservesTheMetric) {
    std::mt19937 rng(3);
    for (double a : {1.0, 0.7}) {
        const GodelCartesian st(a);
        for (const Isometry& I : sampleIsometries(a)) {
            for (int i = 0; i < 50; ++i) {
                const Vec4 x = randomEvent(rng, a);
                const Mat4 J = I.jacobian(x);
                const Mat4 pulled = J.transpose() * st.metric(I.apply(x)) * J;
                EXPECT_LT((pulled - st.metric(x)).cwiseAbs().maxCoeff(), 1e-10) << "at " << x.transpose();
                // Hand-derived Jacobian against finite differences of apply().
                EXPECT_LT((J - numericJacobian(I, x)).cwiseAbs().maxCoeff(), 1e-7);
            }
        }
    }
}

TEST(GodelIsometry, WrongTimeShiftSignIsNotAnIsometry) {
    // Flipping the sign of the t-shift must break the pull-back check (so the check has teeth).
    const double a = 1.0;
    const GodelCartesian st(a);
    const double s = 0.5;
    auto flipped = [&](const Vec4& x) {
        const Isometry I = Isometry::diskAutomorphism(a, s);
        Vec4 y = I.apply(x);
        y(0) = 2 * x(0) - y(0);  // t + 2 sqrt2 a arg(...) instead of t - ...
        return y;
    };
    const Vec4 x(0.0, 0.4, 0.9, 0.0);
    Mat4 J;
    for (int m = 0; m < 4; ++m) {
        Vec4 e = Vec4::Zero();
        e(m) = 1e-6;
        J.col(m) = (flipped(x + e) - flipped(x - e)) / 2e-6;
    }
    EXPECT_GT((J.transpose() * st.metric(flipped(x)) * J - st.metric(x)).cwiseAbs().maxCoeff(), 1e-2);
}

TEST(GodelIsometry, MovesChosenEventToOrigin) {
    std::mt19937 rng(5);
    const double a = 1.0;
    for (int i = 0; i < 100; ++i) {
        const Vec4 P = randomEvent(rng, a, 4.0);
        const Isometry I = Isometry::movingToOrigin(a, P);
        EXPECT_LT(I.apply(P).cwiseAbs().maxCoeff(), 1e-12) << P.transpose();
        const Isometry Ii = Isometry::movingOriginTo(a, P);
        EXPECT_LT((Ii.apply(Vec4::Zero()) - P).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, P.norm()));
        const Vec4 x = randomEvent(rng, a);
        EXPECT_LT((I.inverse().apply(I.apply(x)) - x).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, x.norm()));
        EXPECT_LT((I.apply(I.inverse().apply(x)) - x).cwiseAbs().maxCoeff(), 1e-12 * std::max(1.0, x.norm()));
    }
    // On the axis the rotation is the identity.
    const Isometry I0 = Isometry::movingToOrigin(a, Vec4(2.0, 0, 0, -1.0));
    EXPECT_LT((I0.apply(Vec4(2.5, 0.3, 0.1, 0.0)) - Vec4(0.5, 0.3, 0.1, 1.0)).norm(), 1e-14);
}

TEST(GodelIsometry, CompositionMatchesSuccessiveApplication) {
    std::mt19937 rng(9);
    const double a = 1.2;
    const auto v = sampleIsometries(a);
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t j = 0; j < v.size(); ++j) {
            const Isometry C = v[i] * v[j];
            for (int k = 0; k < 5; ++k) {
                const Vec4 x = randomEvent(rng, a);
                EXPECT_LT((C.apply(x) - v[i].apply(v[j].apply(x))).cwiseAbs().maxCoeff(), 1e-11);
                const Vec4 w(0.3, -1.0, 0.5, 2.0);
                EXPECT_LT((C.pushForward(x, w) - v[i].pushForward(v[j].apply(x), v[j].pushForward(x, w))).norm(),
                          1e-10);
            }
        }
}

TEST(GodelIsometry, GeneratorsAreTheKillingFields) {
    // d/ds of the disk map at s = 0 is -xi5, d/dangle of the rotation is d/dphi: ties the finite
    // maps (and the sign of the time shift) to the Killing fields of docs/PHYSICS.md section 4.
    std::mt19937 rng(13);
    const double a = 0.9, h = 1e-6;
    for (int i = 0; i < 30; ++i) {
        const Vec4 x = randomEvent(rng, a);
        const Vec4 ds =
            (Isometry::diskAutomorphism(a, h).apply(x) - Isometry::diskAutomorphism(a, -h).apply(x)) / (2 * h);
        EXPECT_LT((ds + killingCartesian(KillingField::Xi5, a, x)).cwiseAbs().maxCoeff(), 1e-7);
        const Vec4 dr = (Isometry::rotation(a, h).apply(x) - Isometry::rotation(a, -h).apply(x)) / (2 * h);
        EXPECT_LT((dr - killingCartesian(KillingField::Phi, a, x)).cwiseAbs().maxCoeff(), 1e-7);
    }
}

TEST(GodelIsometry, MappedGeodesicIsAGeodesic) {
    // A closed-form geodesic through the origin, moved by an isometry, against numeric
    // integration started from the moved initial state.
    const double a = 1.0;
    const GodelCartesian st(a);
    const Isometry I = Isometry::movingOriginTo(a, Vec4(0.5, 0.8, -0.4, 0.3)) * Isometry::rotation(a, 0.4);
    for (const OriginGeodesic& g :
         {OriginGeodesic::null(a, 1.1, 0.3, -1), OriginGeodesic::timelike(a, 1.4, 0.2, -0.5)}) {
        PhasePoint s0;
        s0.x = I.apply(g.cartesian(0));
        s0.p = I.pushForwardCovector(g.cartesian(0), g.momentumCartesian(0));
        for (double th : {0.8, 2.5, 5.0, 9.6}) {
            const double l = th / g.omega();
            TraceOptions opt;
            opt.absTol = opt.relTol = 1e-13;
            opt.maxAffine = l;
            opt.maxSteps = 10000000;
            opt.constraintTolerance = 1.0;
            const TraceResult r = traceGeodesic(st, s0, opt);
            ASSERT_EQ(r.reason, StopReason::MaxAffine);
            const Vec4 x = I.apply(g.cartesian(l));
            EXPECT_LT((x - r.end.x).cwiseAbs().maxCoeff(), 1e-9 * std::max(1.0, std::abs(x(0)))) << th;
            const Vec4 p = I.pushForwardCovector(g.cartesian(l), g.momentumCartesian(l));
            EXPECT_LT((p - r.end.p).cwiseAbs().maxCoeff(), 1e-9) << th;
        }
    }
}
