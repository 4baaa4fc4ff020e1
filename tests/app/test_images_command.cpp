// SPDX-License-Identifier: BSD-3-Clause
// `lightcone images --observer`: every image's direction in the observer's documented frame (the
// static observer's Gram-Schmidt frame of d/dx, d/dy, d/dz, docs/PHYSICS.md section 8, the
// camera's), checked by the numeric tracer (an independent oracle): launched from the observer in
// the world chart along the printed direction, at unit observed frequency, it reaches the point at
// the printed affine distance and emission time. Before, the command printed the direction in the
// chart the isometry moved the observer into (145.5 degrees off for the observer below).
#include "run_command.hpp"

#include "core/metrics/godel.hpp"
#include "core/spacetime/frame.hpp"
#include "core/spacetime/integrator.hpp"

#include <gtest/gtest.h>
#include <json/json.h>

#include <sstream>

namespace {

TEST(ImagesCommand, DirectionsAreInTheMovedObserversOwnFrame) {
    const lc::test::CommandResult r = lc::test::runCommand(
        lc::test::lightcone() + " images --a 1 --observer 0,-0.3,0.2,0 --point 1,0,0.2 --windings 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Json::Value out;
    Json::CharReaderBuilder b;
    std::string errors;
    std::istringstream in(r.output);
    ASSERT_TRUE(Json::parseFromStream(b, in, &out, &errors)) << errors << "\n" << r.output;
    ASSERT_GE(out["images"].size(), 2u);
    const lc::GodelCartesian st(1.0);
    const lc::Vec4 observer(0, -0.3, 0.2, 0);
    const lc::LocalFrame frame = lc::LocalFrame::staticObserver(st, observer);
    for (const Json::Value& im : out["images"]) {
        const lc::Vec3 d(im["direction"][0].asDouble(), im["direction"][1].asDouble(), im["direction"][2].asDouble());
        EXPECT_NEAR(std::acos(d.z()), im["psi"].asDouble(), 1e-12);
        EXPECT_NEAR(std::atan2(d.y(), d.x()), im["phi0"].asDouble(), 1e-12);
        lc::PhasePoint s0;
        s0.x = observer;
        s0.p = frame.pastNullMomentum(st, d);
        lc::TraceOptions to;
        to.absTol = to.relTol = 1e-13;
        to.maxAffine = im["affine"].asDouble();
        to.maxSteps = 10000000;
        const lc::TraceResult ray = lc::traceGeodesic(st, s0, to);
        EXPECT_LT((ray.end.x.segment<3>(1) - lc::Vec3(1, 0, 0.2)).norm(), 1e-7) << im;
        EXPECT_NEAR(ray.end.x(0), im["emission_time"].asDouble(), 1e-7);
    }
}

}  // namespace
