// SPDX-License-Identifier: BSD-3-Clause
#include "core/colour/planck.hpp"

#include <cmath>

namespace lc::colour {

double planckRadiance(double lambda, double T) {
    if (lambda <= 0.0 || T <= 0.0) return 0.0;
    const double x = kPlanck * kLightSpeed / (lambda * kBoltzmann * T);
    // expm1 keeps the Rayleigh-Jeans tail accurate; beyond ~700 the value underflows to 0.
    if (x > 700.0) return 0.0;
    const double l5 = lambda * lambda * lambda * lambda * lambda;
    return 2.0 * kPlanck * kLightSpeed * kLightSpeed / (l5 * std::expm1(x));
}

}  // namespace lc::colour
