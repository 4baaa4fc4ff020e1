// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Sky texture coordinates of a unit escape direction d: u = 1/2 + atan2(y, x) / 2 pi across,
// v = acos(z) / pi down (v = 0 at the north pole). For every scalar: the CPU renderers call it
// in double (lc::toSkyUv), the GPU tracer's lcSkyUv is generated from it (codegen::Expr).
#include "core/numerics/types.hpp"

#include <algorithm>
#include <cmath>

namespace lc {

template <class S>
Eigen::Matrix<S, 2, 1> skyUv(const Eigen::Matrix<S, 3, 1>& d) {
    using std::acos;
    using std::atan2;
    using std::max;
    using std::min;
    return {S(0.5) + atan2(d(1), d(0)) / S(2 * kPi), acos(min(max(d(2), S(-1.0)), S(1.0))) / S(kPi)};
}

}  // namespace lc
