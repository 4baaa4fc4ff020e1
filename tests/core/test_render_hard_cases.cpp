// SPDX-License-Identifier: BSD-3-Clause
// Hard cases of the CPU renderers: an observer at gamma = 1000, an exception inside the parallel
// render loop, and a world line of 10^5 events. Oracles: special-relativistic aberration and
// Doppler (exact in the observer's local frame, whatever the curvature), the rest image.
#include "core/colour/blackbody.hpp"
#include "core/colour/srgb.hpp"
#include "core/godel/images.hpp"
#include "core/scene/godel_placement.hpp"
#include "core/metrics/godel.hpp"
#include "core/metrics/kerr_newman.hpp"
#include "core/metrics/minkowski.hpp"
#include "core/scene/frame_camera.hpp"
#include "core/spacetime/named_observer.hpp"
#include "core/render/render.hpp"

#include "tests/common/test_camera.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace lc;

namespace {

// A ball at distance 1 from the observer on the axis, turned about the axis so that its nearest
// image (Goedel rays curve) lies straight ahead, along +x of the observer's frame.
Scene godelBallScene() {
    const double a = 1;
    const godel::ImageSet set = godel::ObserverView(a, Vec4::Zero()).images(Vec3(1, 0, 0), 0, -1);
    const godel::Image* nearest = nullptr;
    for (const auto& im : set.images)
        if (!nearest || im.lambda < nearest->lambda) nearest = &im;
    const double azimuth = nearest ? std::atan2(nearest->direction(1), nearest->direction(0)) : 0;
    Scene s;
    s.spacetime = std::make_shared<GodelCartesian>(a);
    SphereObject ball;
    ball.name = "ball";
    ball.centre = Vec4(0, std::cos(-azimuth), std::sin(-azimuth), 0);
    ball.radius = 0.25;
    ball.placement = std::make_shared<GodelPlacement>(a, ball.centre);
    s.spheres.push_back(ball);
    s.settings.windings = 0;
    s.settings.trace.maxAffine = 2 * kPi;
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-10;
    s.settings.method = RenderSettings::Method::Numeric;
    s.settings.threads = 2;
    s.camera.projection = Camera::Projection::Pinhole;
    s.camera.height = 1;
    return s;
}

// Where the ball's edges are on the camera's middle row (signed angles from +x, radians), and
// the frequency ratio at the centre pixel.
struct Seen {
    double left = 0, right = 0, centreRatio = 0;
};

Seen look(Scene s, double fovDeg, int width) {
    s.camera.width = width;
    s.camera.fovXDeg = fovDeg;
    s.camera.fovYDeg = fovDeg;  // one row: it is the horizon whatever the vertical extent
    const RenderResult r = renderNumeric(s);
    int first = -1, last = -1;
    for (int i = 0; i < width; ++i)
        if (r.pixels[i].kind == PixelRecord::Object) {
            if (first < 0) first = i;
            last = i;
        }
    EXPECT_GT(first, 0) << "the ball is not inside the view";
    EXPECT_LT(last, width - 1) << "the ball is not inside the view";
    // Angle of a pixel edge from the optical axis (pinhole: tan is linear in the image).
    auto angleAt = [&](double x) { return std::atan((2 * x / width - 1) * std::tan(0.5 * fovDeg * kPi / 180)); };
    Seen seen;
    seen.left = angleAt(first);
    seen.right = angleAt(last + 1);
    seen.centreRatio = r.pixels[(first + last) / 2].frequencyRatio;
    return seen;
}

}  // namespace

TEST(RenderHardCases, ObserverAtGammaThousandSeesTheAberratedAndBlueshiftedBall) {
    const Seen rest = look(godelBallScene(), 60, 2400);
    EXPECT_NEAR(rest.centreRatio, 1.0, 1e-6);  // static emitter and observer: no shift in Goedel
    for (const double gamma : {224.0, 1000.0}) {
        const double v = std::sqrt(1 - 1 / (gamma * gamma));
        Scene moving = godelBallScene();
        // On the axis the chart is Minkowskian: u = gamma (1, v, 0, 0), towards the ball's image.
        moving.observerVelocity = Vec4(gamma, gamma * v, 0, 0);
        // Aberration, exact in the local frame: tan(theta'/2) = sqrt((1-v)/(1+v)) tan(theta/2).
        const double k = std::sqrt((1 - v) / (1 + v));
        auto aberrated = [k](double theta) { return 2 * std::atan(k * std::tan(0.5 * theta)); };
        const double span = aberrated(rest.right) - aberrated(rest.left);
        const Seen fast =
            look(moving,
                 2 * std::max(std::abs(aberrated(rest.left)), std::abs(aberrated(rest.right))) * 1.5 * 180 / kPi, 2400);
        EXPECT_NEAR(fast.left, aberrated(rest.left), 0.01 * span) << "gamma " << gamma;
        EXPECT_NEAR(fast.right, aberrated(rest.right), 0.01 * span) << "gamma " << gamma;
        // Doppler towards the source: nu_observed / nu_emitted = gamma (1 + v cos theta), theta ~ 0.
        EXPECT_NEAR(fast.centreRatio / (1 / k), 1.0, 1e-3) << "gamma " << gamma;
    }
}

namespace {
// A placement that fails for points on one side: stands for any per-ray failure.
class FailingPlacement final : public Placement {
public:
    Vec3 toLocal(const Vec4& x) const override {
        if (std::abs(x(2)) > 0.05) throw std::runtime_error("placement failed on purpose");
        return x.tail<3>() - Vec3(1, 0, 0);
    }
};
}  // namespace

TEST(RenderHardCases, ExceptionInsideTheParallelLoopIsReportedNotFatal) {
    Scene s = godelBallScene();
    s.spheres[0].placement = std::make_shared<FailingPlacement>();
    s.camera.width = 64;
    s.camera.height = 16;
    s.camera.fovXDeg = 60;
    s.camera.fovYDeg = 30;
    s.settings.threads = 2;
    try {
        renderNumeric(s);
        FAIL() << "expected the placement's error";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "placement failed on purpose");
    }
}

// A GUI's Cancel: renders `s` with a progress callback that throws RenderCancelled on its third
// call, and reports whether the render stopped with it, how often progress was called and the
// fraction it had reached.
namespace {
struct CancelledRender {
    bool cancelled = false;
    int calls = 0;
    double lastFraction = 0;
};
CancelledRender renderCancelledAtThirdProgressCall(const Scene& s) {
    CancelledRender r;
    try {
        render(s, [&](double f) {
            ++r.calls;
            r.lastFraction = f;
            if (r.calls == 3) throw RenderCancelled();
        });
    } catch (const RenderCancelled&) {
        r.cancelled = true;
    }
    return r;
}
}  // namespace

// A GUI's Cancel: a progress callback that throws RenderCancelled stops both per-pixel renderers
// after a few rows (not the whole image) and reaches the caller as that exception, not abort().
TEST(RenderHardCases, ProgressCallbackThatThrowsCancelsTheRenderEarly) {
    Scene s = godelBallScene();
    s.camera.width = 32;
    s.camera.height = 200;
    s.camera.fovXDeg = 60;
    s.camera.fovYDeg = 30;
    for (auto method : {RenderSettings::Method::Numeric, RenderSettings::Method::ClosedForm}) {
        s.settings.method = method;
        const CancelledRender r = renderCancelledAtThirdProgressCall(s);
        EXPECT_TRUE(r.cancelled) << "the render was not cancelled (" << renderMethodName(method) << ")";
        EXPECT_EQ(r.calls, 3) << "progress was called after the cancel (" << renderMethodName(method) << ")";
        EXPECT_LT(r.lastFraction, 0.5) << renderMethodName(method);  // a busy machine may starve thread 0
    }
}

// The per-vertex renderer of a freely falling body solves each vertex's emission event: the
// same Cancel stops that loop within a few vertices.
TEST(RenderHardCases, ProgressCallbackThatThrowsCancelsThePerVertexRenderEarly) {
    Scene s = godelBallScene();
    s.spheres[0].motion.kind = Motion::Kind::FreeFall;
    s.spheres[0].motion.k0 = 1.2;
    s.camera.projection = Camera::Projection::Panorama;
    s.camera.width = 64;
    s.camera.height = 16;
    s.settings.method = RenderSettings::Method::PerVertex;
    s.settings.meshLatitudes = 24;
    s.settings.meshLongitudes = 48;
    const CancelledRender r = renderCancelledAtThirdProgressCall(s);
    EXPECT_TRUE(r.cancelled) << "the per-vertex render was not cancelled";
    EXPECT_EQ(r.calls, 3);
    EXPECT_LT(r.lastFraction, 0.5);
}

TEST(RenderHardCases, WorldLineOfHundredThousandEventsMatchesTheBodyAtRest) {
    Scene rest = godelBallScene();
    rest.camera.projection = Camera::Projection::Panorama;
    rest.camera.width = 180;
    rest.camera.height = 60;
    rest.camera.fovXDeg = 360;
    rest.camera.fovYDeg = 120;
    rest.settings.threads = 2;
    Scene line = rest;
    // The same static body, given as 10^5 events of a world line (a binary search per lookup).
    line.spheres[0].motion.kind = Motion::Kind::WorldLine;
    Vec4 event = rest.spheres[0].centre;
    for (int k = 0; k < 100000; ++k) {
        event(0) = -20 + 40.0 * k / 99999;
        line.spheres[0].motion.points.push_back(event);
    }
    const RenderResult a = renderGodelPerVertex(rest, 24, 48);
    const RenderResult b = renderGodelPerVertex(line, 24, 48);
    std::size_t differ = 0;
    for (std::size_t n = 0; n < a.pixels.size(); ++n) differ += a.pixels[n].kind != b.pixels[n].kind;
    EXPECT_GT(a.stats.hits, 50u);
    EXPECT_LE(differ, a.stats.hits / 50) << "of " << a.stats.hits << " object pixels";
}

// A small ball far away, seen at a narrow field of view so that many pixels graze it: the numeric
// tracer takes long steps far from the ball (TraceOptions::balls). Oracle: straight rays in
// Minkowski space hit iff their distance of closest approach is below the radius.
TEST(RenderHardCases, GrazingRaysOfAFarSmallBallAreNotSteppedAcross) {
    Scene s;
    s.spacetime = std::make_shared<Minkowski>();
    SphereObject ball;
    ball.name = "ball";
    ball.centre = Vec4(0, 30, 0, 0);
    ball.radius = 0.05;
    ball.placement = std::make_shared<TranslationPlacement>(ball.centre.tail<3>());
    s.spheres.push_back(ball);
    s.settings.method = RenderSettings::Method::Numeric;
    s.settings.threads = 2;
    s.camera.projection = Camera::Projection::Pinhole;
    s.camera.width = 96;
    s.camera.height = 48;
    s.camera.fovXDeg = 0.4;  // the ball's angular radius is asin(0.05 / 30) = 0.095 degrees
    s.camera.fovYDeg = 0.2;
    s.camera.forward = Vec3(1, 0, 0);
    s.camera.up = Vec3(0, 0, 1);
    const RenderResult r = renderNumeric(s);
    const Camera cam = frameCamera(s);
    int hits = 0, compared = 0;
    for (int j = 0; j < s.camera.height; ++j)
        for (int i = 0; i < s.camera.width; ++i) {
            const Vec3 n = cam.direction(i, j).normalized();
            const Vec3 c = ball.centre.tail<3>();
            const double b = (c - c.dot(n) * n).norm();
            if (std::abs(b - ball.radius) < 1e-6 * ball.radius) continue;  // on the edge to rounding
            const bool hit = r.pixels[static_cast<std::size_t>(j) * s.camera.width + i].kind == PixelRecord::Object;
            EXPECT_EQ(hit, b < ball.radius) << "pixel (" << i << ", " << j << "), closest approach " << b;
            hits += hit;
            ++compared;
        }
    EXPECT_GT(hits, 200);
    EXPECT_GT(compared, s.camera.width * s.camera.height - 10);
    // Far from the ball the steps stay long: 30 units to go with a radius of 0.05.
    EXPECT_LT(r.stats.meanSteps, 100) << "steps held to radius / 2 all the way would take 1200";
}

// The same with strongly bent rays: a ball beside and behind a Schwarzschild hole, seen partly
// through the lens. Oracle: the render whose steps are held to radius / 2 everywhere (the rule
// before TraceOptions::balls), i.e. the same rays integrated with a far finer step control.
TEST(RenderHardCases, BallBehindAHoleIsSeenAsWithShortStepsEverywhere) {
    Scene s;
    s.spacetime = std::make_shared<Schwarzschild>(1.0);
    s.observer = Vec4(0, 20, 0, 0);
    SphereObject ball;
    ball.name = "ball";
    ball.centre = Vec4(0, -8, 2.5, 0);
    ball.radius = 0.5;
    ball.placement = std::make_shared<TranslationPlacement>(ball.centre.tail<3>());
    s.spheres.push_back(ball);
    s.settings.method = RenderSettings::Method::Numeric;
    s.settings.threads = 2;
    s.settings.trace.absTol = s.settings.trace.relTol = 1e-10;
    s.camera = test::testCamera(Camera::Projection::Pinhole, 80, 40, 50, 25, Vec3(-1, 0, 0), Vec3(0, 0, 1));
    const RenderResult longSteps = renderNumeric(s);
    s.settings.trace.maxStep = 0.5 * ball.radius;
    const RenderResult shortSteps = renderNumeric(s);
    int objects = 0, differing = 0;
    for (std::size_t k = 0; k < longSteps.pixels.size(); ++k) {
        objects += shortSteps.pixels[k].kind == PixelRecord::Object;
        differing += longSteps.pixels[k].kind != shortSteps.pixels[k].kind;
    }
    EXPECT_GT(objects, 20) << "the ball and its lensed images are in view";
    EXPECT_EQ(differing, 0);
    EXPECT_LT(longSteps.stats.meanSteps, 0.5 * shortSteps.stats.meanSteps);
}

// The sky's shift (docs/SCENES.md, per-pixel data): a static observer beside a Kerr hole
// (a = 0.9, Boyer-Lindquist r = 6 M, on the equator and at 60 degrees from the spin axis) sees the
// light of sources at rest far away blueshifted by nu_obs / nu_inf = 1 / sqrt(g_tt) in every
// direction (g_tt = 1 - 2 M r / Sigma, the same in Kerr-Schild and Boyer-Lindquist time);
// horizon pixels receive no light and record 0, never 1.
TEST(SkyShift, StaticObserverSeesEverySourceAtInfinityBlueshiftedByOneOverSqrtGtt) {
    const double a = 0.9, r = 6;
    for (const double theta : {90.0, 60.0}) {
        SCOPED_TRACE("theta = " + std::to_string(theta));
        const double th = theta * kPi / 180;
        Scene s;
        s.source = "static observer beside Kerr";
        s.spacetime = std::make_shared<KerrNewman>(1.0, a, 0.0);
        s.observer = Vec4(0, std::sqrt(r * r + a * a) * std::sin(th), 0, r * std::cos(th));
        // The whole sky.
        s.camera = test::testCamera(Camera::Projection::Panorama, 36, 18, 360, 170, Vec3(-1, 0, 0), Vec3(0, 0, 1));
        s.settings.progress = false;
        const double sigma = r * r + a * a * std::cos(th) * std::cos(th);
        const double expected = 1 / std::sqrt(1 - 2 * r / sigma);
        const RenderResult out = render(s);
        int sky = 0, horizon = 0;
        for (const PixelRecord& px : out.pixels) {
            if (px.kind == PixelRecord::Sky) {
                ++sky;
                EXPECT_NEAR(px.frequencyRatio, expected, 2e-6 * expected);
            } else if (px.kind == PixelRecord::Horizon) {
                ++horizon;
                EXPECT_EQ(px.frequencyRatio, 0.0f);
            }
        }
        EXPECT_GT(sky, 300);
        EXPECT_GT(horizon, 10);
    }
}

// A ZAMO beside Kerr a = 0.9 (named observer "zamo"): a ray of E and L = xi E arrives with
// nu_obs = E (1 - omega xi) / alpha; with xi = R n_phi nu_obs / E (R = sqrt(A / rho^2) sin theta,
// n_phi the propagation's component along the ZAMO's e_phi, minus the pixel's viewing direction's)
// nu_obs / E = 1 / (alpha - omega R d_phi), d_phi the documented pixel direction's e_phi component.
// Closed forms (Bardeen, Press & Teukolsky 1972): alpha^2 = rho^2 Delta / A, omega = 2 M a r / A.
TEST(SkyShift, ZamoSeesTheSkyShiftedByItsLapseAndFrameDragging) {
    const double a = 0.9, r = 3, th = 70 * kPi / 180;
    Scene s;
    s.source = "ZAMO beside Kerr";
    s.spacetime = std::make_shared<KerrNewman>(1.0, a, 0.0);
    s.observer = Vec4(0, r * std::sin(th), -a * std::sin(th), r * std::cos(th));  // BL (r, theta, phi = 0)
    s.observerVelocity = namedObserverVelocity(*s.spacetime, s.observer, NamedObserver::Zamo);
    s.camera = test::testCamera(Camera::Projection::Panorama, 36, 18, 360, 170, Vec3(-1, 0, 0), Vec3(0, 0, 1));
    s.settings.progress = false;
    const double rho2 = r * r + a * a * std::cos(th) * std::cos(th), delta = r * r - 2 * r + a * a;
    const double A = std::pow(r * r + a * a, 2) - delta * a * a * std::sin(th) * std::sin(th);
    const double alpha = std::sqrt(rho2 * delta / A), omega = 2 * a * r / A, R = std::sqrt(A / rho2) * std::sin(th);
    // e_phi = d/dphi / |d/dphi| in the observer's frame components.
    const LocalFrame frame = observerFrame(s);
    const Mat4 g = s.spacetime->metric(s.observer);
    const Vec4 phi(0, -s.observer(2), s.observer(1), 0);
    const Vec4 ePhi = phi / std::sqrt(-phi.dot(g * phi));
    const Vec3 ePhiFrame(-ePhi.dot(g * frame.e[1]), -ePhi.dot(g * frame.e[2]), -ePhi.dot(g * frame.e[3]));
    const Camera cam = frameCamera(s);
    const RenderResult out = render(s);
    int sky = 0;
    double lo = 1e9, hi = 0;
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i) {
            const PixelRecord& px = out.pixels[std::size_t(j) * out.width + i];
            if (px.kind != PixelRecord::Sky) continue;
            ++sky;
            const double expected = 1 / (alpha - omega * R * cam.direction(i, j).normalized().dot(ePhiFrame));
            EXPECT_NEAR(px.frequencyRatio, expected, 2e-6 * expected) << "pixel " << i << "," << j;
            lo = std::min(lo, expected), hi = std::max(hi, expected);
        }
    EXPECT_GT(sky, 200);
    EXPECT_GT(hi / lo, 1.2);  // the sky is bluer on one side: a test that the direction matters
}

// An observer falling from rest at infinity (named observer "free_fall") into Schwarzschild at
// radius r on the x axis, a whole-sky panorama looking at the hole; and the closed-form frequency
// ratio of the sky it sees along frame direction d: the static 1 / sqrt(1 - 2M/r) Doppler-shifted
// by the infall speed beta = sqrt(2M/r), 1 / (gamma (1 - beta cos theta')), theta' from forward.
Scene fallingIntoSchwarzschild(double r) {
    Scene s;
    s.source = "falling into Schwarzschild";
    s.spacetime = std::make_shared<KerrNewman>(1.0, 0.0, 0.0);
    s.observer = Vec4(0, r, 0, 0);
    s.observerVelocity = namedObserverVelocity(*s.spacetime, s.observer, NamedObserver::FreeFall);
    s.camera = test::testCamera(Camera::Projection::Panorama, 36, 18, 360, 170, Vec3(-1, 0, 0), Vec3(0, 0, 1));
    s.settings.progress = false;
    return s;
}

double fallingSkyShift(double r, const Camera& cam, const Vec3& d) {
    const double beta = std::sqrt(2 / r), gamma = 1 / std::sqrt(1 - beta * beta), still = 1 / std::sqrt(1 - 2 / r);
    return still / (gamma * (1 - beta * d.normalized().dot(cam.forward.normalized())));
}

// A black-body sky (sky.temperature = 5800 K, a grey sky of luminance 0.5) seen falling into
// Schwarzschild at r = 4 M: each sky pixel is the Planck colour at g T (Planck's law integrated
// directly, colour::blackbodySrgb, not the renderer's table) times g^4 times 0.5, with g the
// closed-form Doppler-shifted static shift below: blue and bright ahead, red and dim behind.
TEST(SkyShift, BlackBodySkyIsDrawnAtTheShiftedTemperatureAndBrightness) {
    const double r = 4, T = 5800;
    Scene s = fallingIntoSchwarzschild(r);
    s.sky = std::make_shared<SolidTexture>(Vec3(0.5, 0.5, 0.5));
    s.skyTemperature = T;
    const Camera cam = frameCamera(s);
    const RenderResult out = render(s);
    const std::vector<float> rgb = shadePixels(s, out);
    int sky = 0;
    double bluest = 0, reddest = 1e9;
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i) {
            const std::size_t n = std::size_t(j) * out.width + i;
            if (out.pixels[n].kind != PixelRecord::Sky) continue;
            ++sky;
            const double g = fallingSkyShift(r, cam, cam.direction(i, j));
            const Vec3 srgb = colour::blackbodySrgb(g * T, colour::ToneMap::ColourOnly);
            for (int c = 0; c < 3; ++c) {
                const double expected = colour::srgbDecode(srgb(c)) * g * g * g * g * 0.5;
                EXPECT_NEAR(rgb[3 * n + c], expected, 5e-3 * std::max(1.0, expected)) << i << "," << j << " c" << c;
            }
            bluest = std::max(bluest, double(rgb[3 * n + 2]) / std::max(1e-9, double(rgb[3 * n])));
            reddest = std::min(reddest, double(rgb[3 * n + 2]) / std::max(1e-9, double(rgb[3 * n])));
        }
    EXPECT_GT(sky, 300);
    EXPECT_GT(bluest, 1.2);   // ahead: bluer than white
    EXPECT_LT(reddest, 0.8);  // behind: redder
}

// The 2.725 K cosmic background as a black-body sky, seen by static observers beside Schwarzschild
// (docs/SCENES.md, sky "temperature"): every sky pixel at g T, g = 1 / sqrt(1 - 2M/r) (Planck's law
// integrated directly, not the table), brightness g^4 times the texture's luminance. Hovering
// 6.25e-6 M above the horizon (g = 400) the background glows at 1090 K; at 10 M (g = 1.118) it is
// 3.05 K, below the Planck table, and drawn in its reddest colour (500 K).
TEST(SkyShift, TheCosmicBackgroundHoveringAboveTheHorizonGlowsAtGTimes2725K) {
    const double T = 2.725;
    for (const double g : {400.0, 1 / std::sqrt(0.8)}) {
        SCOPED_TRACE("g = " + std::to_string(g));
        const double r = 2 / (1 - 1 / (g * g)), luminance = 0.5 / (g * g * g * g);
        Scene s;
        s.source = "the cosmic background near Schwarzschild's horizon";
        s.spacetime = std::make_shared<KerrNewman>(1.0, 0.0, 0.0);
        s.observer = Vec4(0, r, 0, 0);
        // Looking straight out: so near the horizon the sky is a cap of 0.37 degrees about it.
        s.camera = test::testCamera(Camera::Projection::Pinhole, 12, 12, 0.6, 0.6, Vec3(1, 0, 0), Vec3(0, 0, 1));
        s.settings.progress = false;
        s.sky = std::make_shared<SolidTexture>(Vec3(luminance, luminance, luminance));
        s.skyTemperature = T;
        const RenderResult out = render(s);
        const std::vector<float> rgb = shadePixels(s, out);
        const Vec3 hue = colour::blackbodySrgb(std::max(g * T, 500.0), colour::ToneMap::ColourOnly);
        int sky = 0;
        for (std::size_t n = 0; n < out.pixels.size(); ++n) {
            if (out.pixels[n].kind != PixelRecord::Sky) continue;
            ++sky;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(rgb[3 * n + c], colour::srgbDecode(hue(c)) * 0.5, 3e-3) << n << " c" << c;
        }
        EXPECT_GT(sky, 20);
    }
}

// Falling from rest at infinity (named observer "free_fall") into Schwarzschild, r = 4 M: the
// static observer's 1 / sqrt(1 - 2M/r) Doppler-shifted by the infall speed beta = sqrt(2M/r):
// nu' / nu = 1 / (gamma (1 - beta cos theta')), theta' the pixel direction's angle from the
// direction of motion (forward): blue ahead, red behind.
TEST(SkyShift, FallingObserverSeesTheStaticShiftDopplerShifted) {
    const double r = 4;
    const Scene s = fallingIntoSchwarzschild(r);
    const Camera cam = frameCamera(s);
    const RenderResult out = render(s);
    int sky = 0;
    for (int j = 0; j < out.height; ++j)
        for (int i = 0; i < out.width; ++i) {
            const PixelRecord& px = out.pixels[std::size_t(j) * out.width + i];
            if (px.kind != PixelRecord::Sky) continue;
            ++sky;
            const double expected = fallingSkyShift(r, cam, cam.direction(i, j));
            EXPECT_NEAR(px.frequencyRatio, expected, 2e-6 * expected) << "pixel " << i << "," << j;
        }
    EXPECT_GT(sky, 300);
}
