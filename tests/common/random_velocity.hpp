// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A random velocity of speed below maxSpeed (uniform in the ball, not too close to rest), for
// the special-relativity tests.
#include "core/numerics/types.hpp"

#include <random>

namespace lc::test {

inline Vec3 randomBeta(std::mt19937& rng, double maxSpeed) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec3 v;
    do v = Vec3(u(rng), u(rng), u(rng));
    while (v.norm() > 1.0 || v.norm() < 1e-3);
    return v * maxSpeed;
}

}  // namespace lc::test
