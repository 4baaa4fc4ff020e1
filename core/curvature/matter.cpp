// SPDX-License-Identifier: BSD-3-Clause
#include "core/curvature/matter.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lc {

Mat4 stressEnergyTensor(const CurvatureAt& curvature, double cosmologicalConstant) {
    return (curvature.einstein - cosmologicalConstant * curvature.g) / (8 * kPi);
}

Mat4 inFrame(const Mat4& t, const LocalFrame& frame) {
    Eigen::Matrix4d e;
    for (int a = 0; a < 4; ++a) e.col(a) = frame.e[static_cast<std::size_t>(a)];
    return e.transpose() * t * e;
}

MatterSeen matterSeenBy(const Mat4& T) {
    MatterSeen m;
    m.energyDensity = T(0, 0);
    // Raising a spatial frame index flips its sign: T^(0)(i) = -T_(0)(i), T^(i)(j) = T_(i)(j).
    m.energyFlux = -T.block<1, 3>(0, 1).transpose();
    m.stress = T.block<3, 3>(1, 1);
    m.principalPressures = Eigen::SelfAdjointEigenSolver<Mat3>(m.stress, Eigen::EigenvaluesOnly).eigenvalues();
    return m;
}

const char* hawkingEllisName(HawkingEllisType type) {
    switch (type) {
        case HawkingEllisType::I: return "I";
        case HawkingEllisType::II: return "II";
        case HawkingEllisType::III: return "III";
        default: return "IV";
    }
}

namespace {
const Vec4 kEta(1, -1, -1, -1);

// Holds unless the quantity is below zero by more than round-off of T's components (`scale`):
// radiation and electromagnetic fields sit exactly on the null condition's boundary.
EnergyCondition condition(double lowest, double scale) {
    EnergyCondition c;
    c.holds = !(lowest < -1e-10 * scale);
    c.violation = c.holds ? 0.0 : -lowest;
    return c;
}

// The lowest value of f over unit directions: a Fibonacci lattice of 400, then a descent from
// the best of them with halving steps along two tangent directions (to about 1e-7 rad).
template <class F>
double lowestOnSphere(const F& f) {
    static const std::vector<Vec3> lattice = [] {
        std::vector<Vec3> d;
        const int n = 400;
        const double golden = kPi * (3 - std::sqrt(5.0));
        for (int i = 0; i < n; ++i) {
            const double z = 1 - (2 * i + 1.0) / n, s = std::sqrt(1 - z * z);
            d.emplace_back(s * std::cos(golden * i), s * std::sin(golden * i), z);
        }
        return d;
    }();
    Vec3 best = lattice[0];
    double lowest = f(best);
    for (const Vec3& n : lattice)
        if (const double v = f(n); v < lowest) {
            lowest = v;
            best = n;
        }
    for (double step = 0.1; step > 1e-7; step /= 2) {
        bool moved = true;
        while (moved) {
            moved = false;
            const Vec3 t1 = best.unitOrthogonal(), t2 = best.cross(t1);
            for (const Vec3& t : {t1, Vec3(-t1), t2, Vec3(-t2)}) {
                const Vec3 n = (best + step * t).normalized();
                if (const double v = f(n); v < lowest) {
                    lowest = v;
                    best = n;
                    moved = true;
                    break;
                }
            }
        }
    }
    return lowest;
}

// Types II-IV: every condition's quantity over null directions k = (1, n) and observers
// v = gamma (1, beta n), beta up to 0.99.
void sampledConditions(const Mat4& T, double scale, MatterClass& m) {
    const double trace = kEta.dot(T.diagonal());  // T = eta^ab T_ab
    const double nullLowest = std::min(0.0, lowestOnSphere([&](const Vec3& n) {
                                           const Vec4 k(1, n(0), n(1), n(2));
                                           return k.dot(T * k);
                                       }));
    double weakLowest = 0, strongLowest = 0, dominantLowest = 0;
    for (double beta : {0.0, 0.5, 0.9, 0.99}) {
        const double gamma = 1 / std::sqrt(1 - beta * beta);
        auto observer = [&](const Vec3& n) { return Vec4(gamma * Vec4(1, beta * n(0), beta * n(1), beta * n(2))); };
        const double density = lowestOnSphere([&](const Vec3& n) { return observer(n).dot(T * observer(n)); });
        weakLowest = std::min(weakLowest, density);
        // (T_ab - T g_ab / 2) v^a v^b with g(v, v) = 1.
        strongLowest = std::min(strongLowest, density - trace / 2);
        // Dominant: -T^a_b v^b future causal: its time component >= its spatial length.
        dominantLowest = std::min(dominantLowest, lowestOnSphere([&](const Vec3& n) {
                                      const Vec4 flux = kEta.cwiseProduct(T * observer(n));  // T^a_b v^b
                                      return flux(0) - flux.tail<3>().norm();
                                  }));
    }
    m.nullEnergy = condition(nullLowest, scale);
    m.weak = condition(std::min(weakLowest, nullLowest), scale);
    m.strong = condition(std::min(strongLowest, nullLowest), scale);
    m.dominant = condition(std::min(dominantLowest, weakLowest), scale);
    m.sampled = true;
}
}  // namespace

MatterClass classifyMatter(const Mat4& T) {
    MatterClass m;
    const double scale = T.cwiseAbs().maxCoeff();
    if (!(scale > 0)) return m;  // vacuum: type I with nothing in it
    // T^a_b = eta^aa T_ab in the orthonormal frame.
    const Mat4 mixed = kEta.asDiagonal() * T;
    Eigen::EigenSolver<Mat4> solver(mixed);
    const auto values = solver.eigenvalues();
    const auto vectors = solver.eigenvectors();
    const double tiny = 1e-9 * scale;
    bool complex = false;
    for (int i = 0; i < 4; ++i) complex = complex || std::abs(values(i).imag()) > tiny;
    if (complex) {
        m.type = HawkingEllisType::IV;
        sampledConditions(T, scale, m);
        return m;
    }
    int timelike = -1;
    double best = 1e-6;
    for (int i = 0; i < 4; ++i) {
        const Vec4 v = vectors.col(i).real().normalized();
        const double norm = v.dot(kEta.cwiseProduct(v));
        if (norm > best) {
            best = norm;
            timelike = i;
        }
    }
    if (timelike < 0) {
        // A null eigenvector k with eigenvalue lambda sits in a Jordan block of size 2 (type II)
        // or 3 (type III); N = T^a_b - lambda delta^a_b has rank(N^2) > rank(N^3) only for 3.
        int nullest = 0;
        double smallest = 1e300;
        for (int i = 0; i < 4; ++i) {
            const Vec4 v = vectors.col(i).real().normalized();
            const double norm = std::abs(v.dot(kEta.cwiseProduct(v)));
            if (norm < smallest) {
                smallest = norm;
                nullest = i;
            }
        }
        const Mat4 n = mixed - values(nullest).real() * Mat4::Identity();
        const Mat4 n2 = n * n, n3 = n2 * n;
        auto rank = [](const Mat4& a, double zero) {  // singular values above an absolute zero
            const Vec4 s = Eigen::JacobiSVD<Mat4>(a).singularValues();
            return (s.array() > zero).count();
        };
        const bool blockOfThree = rank(n2, 1e-7 * scale * scale) > rank(n3, 1e-7 * scale * scale * scale);
        m.type = blockOfThree ? HawkingEllisType::III : HawkingEllisType::II;
        sampledConditions(T, scale, m);
        return m;
    }
    // T^a_b u^b = rho u^a along the timelike eigenvector; T^a_b e^b = -p e^a along the others.
    m.restDensity = values(timelike).real();
    int k = 0;
    for (int i = 0; i < 4; ++i)
        if (i != timelike) m.restPressures(k++) = -values(i).real();
    std::sort(m.restPressures.data(), m.restPressures.data() + 3);
    const double rho = m.restDensity;
    const Vec3& p = m.restPressures;
    const double nullLowest = rho + p.minCoeff();
    m.nullEnergy = condition(nullLowest, scale);
    m.weak = condition(std::min(rho, nullLowest), scale);
    m.strong = condition(std::min(rho + p.sum(), nullLowest), scale);
    m.dominant = condition(rho - p.cwiseAbs().maxCoeff(), scale);
    return m;
}

Mat3 tidalTensor(const CurvatureAt& c, const LocalFrame& observer) {
    const Vec4& u = observer.e[0];
    // W_ac = R_abcd u^b u^d, then E_ij = -W(e_i, e_j).
    Mat4 w = Mat4::Zero();
    for (int a = 0; a < 4; ++a)
        for (int cc = 0; cc < 4; ++cc) {
            double s = 0;
            for (int b = 0; b < 4; ++b)
                for (int d = 0; d < 4; ++d) s += c.riemann(a, b, cc, d) * u(b) * u(d);
            w(a, cc) = s;
        }
    Mat3 e;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            e(i, j) = -observer.e[static_cast<std::size_t>(i + 1)].dot(w * observer.e[static_cast<std::size_t>(j + 1)]);
    return 0.5 * (e + e.transpose());
}

Vec3 tidalEigenvalues(const CurvatureAt& c, const LocalFrame& observer) {
    return Eigen::SelfAdjointEigenSolver<Mat3>(tidalTensor(c, observer), Eigen::EigenvaluesOnly).eigenvalues();
}

}  // namespace lc
