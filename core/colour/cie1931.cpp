// SPDX-License-Identifier: BSD-3-Clause
#include "core/colour/cie1931.hpp"

#include <cmath>

namespace lc::colour {
namespace {
// One asymmetric Gaussian lobe: different widths left and right of the centre.
double lobe(double w, double centre, double invWidthLeft, double invWidthRight) {
    const double t = (w - centre) * (w < centre ? invWidthLeft : invWidthRight);
    return std::exp(-0.5 * t * t);
}
}  // namespace

Vec3 cie1931Cmf(double w) {
    const double x = 0.362 * lobe(w, 442.0, 0.0624, 0.0374) + 1.056 * lobe(w, 599.8, 0.0264, 0.0323) -
                     0.065 * lobe(w, 501.1, 0.0490, 0.0382);
    const double y = 0.821 * lobe(w, 568.8, 0.0213, 0.0247) + 0.286 * lobe(w, 530.9, 0.0613, 0.0322);
    const double z = 1.217 * lobe(w, 437.0, 0.0845, 0.0278) + 0.681 * lobe(w, 459.0, 0.0385, 0.0725);
    return Vec3(x, y, z);
}

}  // namespace lc::colour
