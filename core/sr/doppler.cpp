// SPDX-License-Identifier: BSD-3-Clause
#include "core/sr/doppler.hpp"

#include "core/sr/lorentz.hpp"

namespace lc::sr {

double dopplerFactor(const Vec3& beta, const Vec3& n) {
    (void)lorentzGamma(beta);  // |beta| < 1, or std::invalid_argument
    return restRayDoppler<double>(beta, -n);
}

Vec3 aberrateToObserver(const Vec3& beta, const Vec3& kRest) {
    return boostDirection<double>(beta, kRest.normalized());
}
Vec3 aberrateToRest(const Vec3& beta, const Vec3& k) { return boostDirection<double>(-beta, k.normalized()); }

}  // namespace lc::sr
