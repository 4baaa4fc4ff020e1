// SPDX-License-Identifier: BSD-3-Clause
// Local frames (core/spacetime/frame): orthonormal for static and moving observers, a viewing
// direction's null momentum maps back to the direction.
#include "core/spacetime/frame.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace lc;

namespace {

TEST(Frames, OrthonormalForStaticAndMovingObservers) {
    const Mat4 eta = Eigen::Vector4d(1, -1, -1, -1).asDiagonal();
    const auto check = [&](const Spacetime& st, const Vec4& x, const Vec4& u) {
        const LocalFrame f = LocalFrame::withVelocity(st, x, u);
        const Mat4 g = st.metric(x);
        Mat4 gram;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) gram(i, j) = f.e[i].dot(g * f.e[j]);
        EXPECT_LT((gram - eta).cwiseAbs().maxCoeff(), 1e-12) << st.name();
        // A viewing direction gives a null momentum that the frame maps back to the direction.
        const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
        const Vec4 p = f.pastNullMomentum(st, n);
        EXPECT_NEAR(st.hamiltonian(x, p), 0, 1e-13);
        EXPECT_LT((f.directionOf(st, p) - n).norm(), 1e-12);
    };
    const KerrNewman kerr(1.0, 0.9, 0.2);
    check(kerr, Vec4(0, 6, 2, 1), Vec4::Unit(0));
    check(kerr, Vec4(0, 6, 2, 1), Vec4(1.3, 0.2, 0.5, -0.1));
    const GodelCartesian godel(1.0);
    check(godel, Vec4(0, 1.2, -0.7, 0.3), Vec4::Unit(0));
    check(godel, Vec4(0, 0.4, 0.1, 0), Vec4(1.2, 0.3, 0.1, 0.2));
    EXPECT_THROW(LocalFrame::withVelocity(godel, Vec4::Zero(), Vec4(1, 2, 0, 0)), std::invalid_argument);
}

}  // namespace
