// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include "core/spacetime/spacetime.hpp"

namespace lc {

// Flat spacetime, Cartesian chart (t, x, y, z).
class Minkowski final : public CodedMetric<Minkowski> {
public:
    std::string name() const override { return "minkowski"; }
    std::map<std::string, double> parameters() const override { return {}; }
    std::array<std::string, 4> coordinateNames() const override { return {"t", "x", "y", "z"}; }
    bool asymptoticallyFlat() const override { return true; }
    FarField farField(const Vec4& /*x*/) const override { return {}; }  // no field anywhere

    template <class S>
    Eigen::Matrix<S, 4, 4> g(const Eigen::Matrix<S, 4, 1>& /*x*/) const {
        Eigen::Matrix<S, 4, 4> m = Eigen::Matrix<S, 4, 4>::Zero();
        m(0, 0) = S(1.0);
        m(1, 1) = m(2, 2) = m(3, 3) = S(-1.0);
        return m;
    }
};

}  // namespace lc
