// SPDX-License-Identifier: BSD-3-Clause
#include "core/spacetime/constants_of_motion.hpp"

#include "core/metrics/kerr_newman.hpp"

#include <cmath>

namespace lc {

namespace {

// The least change d (Euclidean in the chart's components) with rows.col(i) . d = rhs(i) for the
// first n rows, by Gram-Schmidt on the rows: J = L Q, d = Q^T y, L y = rhs. A row left with
// little of its length once the kept ones are taken out is (nearly) dependent on them: its
// condition follows from theirs (a third rotation), or would need a large change; it is dropped.
Vec4 leastChange(const Eigen::Matrix<double, 4, 5>& rows, const Eigen::Matrix<double, 5, 1>& rhs, int n) {
    constexpr double kIndependent = 1e-3;
    Mat4 basis;
    Vec4 y;
    int kept = 0;
    for (int i = 0; i < n && kept < 4; ++i) {
        Vec4 r = rows.col(i);
        double b = rhs(i);
        const double length = r.norm();
        for (int j = 0; j < kept; ++j) {
            const double c = r.dot(basis.col(j));
            r -= c * basis.col(j);
            b -= c * y(j);
        }
        const double rest = r.norm();
        if (!(rest > kIndependent * length)) continue;
        basis.col(kept) = r / rest;
        y(kept) = b / rest;
        ++kept;
    }
    Vec4 d = Vec4::Zero();
    for (int j = 0; j < kept; ++j) d += y(j) * basis.col(j);
    return d;
}

}  // namespace

ConstantsOfMotion::ConstantsOfMotion(const Spacetime& spacetime, const PhasePoint& start) : spacetime_(spacetime) {
    const Spacetime::Symmetries symmetries = spacetime.symmetries();
    if (symmetries.stationary) axes_[killingCount_++] = Vec3::Zero();
    if (symmetries.axisymmetric || symmetries.spherical) axes_[killingCount_++] = Vec3::UnitZ();
    if (symmetries.spherical) {
        axes_[killingCount_++] = Vec3::UnitX();
        axes_[killingCount_++] = Vec3::UnitY();
    }
    for (int i = 0; i < killingCount_; ++i) killingValues_(i) = killingField(i, start.x).dot(start.p);
    hamiltonian_ = spacetime.hamiltonian(start.x, start.p);
    const auto kerrNewman = spacetime.kerrNewmanParameters();
    if (kerrNewman && kerrNewman->spin != 0)
        if (const auto q = carterConstant(kerrNewman->spin, hamiltonian_, start)) {
            carterSpin_ = kerrNewman->spin;
            carter_ = *q;
        }
}

std::optional<double> ConstantsOfMotion::carterConstant(double a, double H0, const PhasePoint& q, Vec4* gradient) {
    const double x = q.x(1), y = q.x(2), z = q.x(3);
    const double r = kerrSchildRadius(x, y, z, a), cosTheta = z / r, sin2 = 1 - cosTheta * cosTheta;
    constexpr double kAxis = 1e-6;  // sin^2 of 1e-3 rad
    if (!(r > 0) || !(sin2 > kAxis)) return std::nullopt;
    const double sinTheta = std::sqrt(sin2), cot = cosTheta / sinTheta;
    const Vec4 dTheta(0, x * cot, y * cot, -r * sinTheta);  // d p_theta / d p
    const Vec4 dLz(0, -y, x, 0);
    const double pTheta = dTheta.dot(q.p), Lz = dLz.dot(q.p), E = q.p(0), cos2 = cosTheta * cosTheta;
    if (gradient) {
        *gradient = 2 * pTheta * dTheta + (2 * cos2 * Lz / sin2) * dLz;
        (*gradient)(0) -= 2 * cos2 * a * a * E;
    }
    return pTheta * pTheta + cos2 * (a * a * (2 * H0 - E * E) + Lz * Lz / sin2);
}

Vec4 ConstantsOfMotion::killingField(int i, const Vec4& x) const {
    const Vec3& axis = axes_[static_cast<std::size_t>(i)];
    if (axis.isZero(0)) return Vec4(1, 0, 0, 0);  // d/dt
    Vec4 xi = Vec4::Zero();
    xi.tail<3>() = axis.cross(x.tail<3>());
    return xi;
}

bool ConstantsOfMotion::restore(PhasePoint& q, const Vec4& v) const {
    if (spacetime_.asymptoticallyFlat()) {
        const FarField far = spacetime_.farField(q.x);
        const double d = (q.x.tail<3>() - far.centre).norm();
        if (d > kOrbitRegion * far.captureRadius || d <= far.size) return false;
    }
    // The conditions linearised in p: d(p . xi)/dp = xi, dH/dp = v = g^-1 p.
    Eigen::Matrix<double, 4, 5> rows;
    Eigen::Matrix<double, 5, 1> rhs;
    for (int i = 0; i < killingCount_; ++i) {
        rows.col(i) = killingField(i, q.x);
        rhs(i) = killingValues_(i) - rows.col(i).dot(q.p);
    }
    int n = killingCount_;
    Vec4 carterGradient;
    if (carterSpin_ != 0)
        if (const auto carter = carterConstant(carterSpin_, hamiltonian_, q, &carterGradient)) {
            rows.col(n) = carterGradient;
            rhs(n++) = carter_ - *carter;
        }
    rows.col(n) = v;
    rhs(n++) = hamiltonian_ - 0.5 * q.p.dot(v);
    const Vec4 dp = leastChange(rows, rhs, n);
    // A change beyond a drift's size means the conditions are ill-posed here: left alone.
    if (!dp.allFinite() || dp.isZero(0) || dp.norm() > kLargestChange * q.p.norm()) return false;
    q.p += dp;
    return true;
}

}  // namespace lc
