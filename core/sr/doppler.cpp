#include "core/sr/doppler.hpp"

#include "core/sr/lorentz.hpp"

namespace lc::sr {

double dopplerFactor(const Vec3& beta, const Vec3& n) { return 1.0 / (lorentzGamma(beta) * (1.0 - beta.dot(n))); }

namespace {
Vec3 boostDirection(const Vec3& beta, const Vec3& k) {
    const Vec4 out = boost(beta) * Vec4(1.0, k.x(), k.y(), k.z());
    return out.tail<3>() / out[0];  // a null vector: |spatial| = time component
}
}  // namespace

Vec3 aberrateToObserver(const Vec3& beta, const Vec3& kRest) { return boostDirection(beta, kRest.normalized()); }
Vec3 aberrateToRest(const Vec3& beta, const Vec3& k) { return boostDirection(-beta, k.normalized()); }

double reflectionFrequencyRatio(const Vec3& beta, const Vec3& vIn, const Vec3& vOut) {
    // nu' = nu_in gamma (1 - beta.vIn) in S'; the mirror keeps nu'; nu_out = nu' / (gamma (1 - beta.vOut)).
    return (1.0 - beta.dot(vIn)) / (1.0 - beta.dot(vOut));
}

}  // namespace lc::sr
