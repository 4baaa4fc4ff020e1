// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include "core/spacetime/spacetime.hpp"

#include <stdexcept>

namespace lc {

// Alcubierre warp bubble moving along +x with speed v (seed 002), chart (t, x, y, z):
//   ds^2 = dt^2 - (dx - v f(r_s) dt)^2 - dy^2 - dz^2,  r_s = |(x - v t, y, z)|,
//   f(r) = [tanh(sigma (r + R)) - tanh(sigma (r - R))] / (2 tanh(sigma R)).
class Alcubierre final : public CodedMetric<Alcubierre> {
public:
    Alcubierre(double speed, double bubbleRadius, double sigma) : v_(speed), R_(bubbleRadius), sigma_(sigma) {
        if (!(bubbleRadius > 0)) throw std::invalid_argument("Alcubierre: bubble radius R must be > 0");
        if (!(sigma > 0)) throw std::invalid_argument("Alcubierre: wall sharpness sigma must be > 0");
    }
    std::string name() const override { return "alcubierre"; }
    std::map<std::string, double> parameters() const override { return {{"v", v_}, {"R", R_}, {"sigma", sigma_}}; }
    std::array<std::string, 4> coordinateNames() const override { return {"t", "x", "y", "z"}; }
    bool asymptoticallyFlat() const override { return true; }
    // Flat (to e^-40) beyond 20 wall widths 1/sigma outside the bubble, which moves along +x.
    FarField farField(const Vec4& x) const override {
        FarField f;
        f.centre = Vec3(v_ * x(0), 0, 0);
        f.velocity = Vec3(v_, 0, 0);
        f.size = R_ + 20 / sigma_;
        f.captureRadius = f.size;
        return f;
    }

    template <class S>
    Eigen::Matrix<S, 4, 4> g(const Eigen::Matrix<S, 4, 1>& X) const {
        using std::sqrt;
        using std::tanh;
        const S dx = X(1) - S(v_) * X(0);
        // The tiny offset keeps d(sqrt)/dr finite on the bubble centre line.
        const S rs = sqrt(dx * dx + X(2) * X(2) + X(3) * X(3) + S(1e-300));
        const S f = (tanh(S(sigma_) * (rs + S(R_))) - tanh(S(sigma_) * (rs - S(R_)))) / S(2.0 * std::tanh(sigma_ * R_));
        const S vf = S(v_) * f;
        Eigen::Matrix<S, 4, 4> m = Eigen::Matrix<S, 4, 4>::Zero();
        m(0, 0) = S(1.0) - vf * vf;
        m(0, 1) = m(1, 0) = vf;
        m(1, 1) = m(2, 2) = m(3, 3) = S(-1.0);
        return m;
    }

private:
    double v_, R_, sigma_;
};

}  // namespace lc
