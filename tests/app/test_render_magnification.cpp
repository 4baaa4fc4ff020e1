// SPDX-License-Identifier: BSD-3-Clause
// `render --magnification`, `shade --show` and `sweep --point-source` as a user runs them: the
// per-pixel data gains the lensing channels, which for the Schwarzschild point lens in the weak
// field follow mu = 1/(1 - (theta_E/theta)^4) (docs/PHYSICS.md section 13a) on both images, and
// shade draws them (data without the channels is refused with the hint); a point source's two
// images add up to Paczynski's (u^2 + 2)/(u sqrt(u^2 + 4)) along a sweep of the lens's mass.
#include "readers/io/image_io.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <algorithm>
#include <map>
#include <sstream>

using namespace lc::test;

namespace {

// A unit mass 10^8 M ahead of a static observer, seen off the lens's axis: Einstein angle 2e-4 rad
// (the formula's own second order: up to 1.2e-3 in mu on the inner image).
const char* const kLensScene = R"({
  "metric": {"name": "schwarzschild", "M": 1},
  "observer": {"position": [0, -1e8, 0, 0]},
  "camera": {"projection": "pinhole", "width": 40, "height": 30, "fov": [0.05, 0.0375],
             "forward": [1, 0.0001, -0.00005], "up": [0, 0, 1]},
  "render": {"tolerance": 1e-10}
})";

class RenderMagnification : public ::testing::Test {
protected:
    void SetUp() override { std::ofstream(dir / "lens.json") << kLensScene; }
    // The lens scene's data with the lensing channels: lens.exr.
    void renderLensData() const {
        const CommandResult r = runCommand(lightcone() + " render " + dir / "lens.json" + " -o " + dir / "lens.png" +
                                           " --data " + dir / "lens.exr --magnification --quiet");
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const ScratchFolder dir{"magnification"};
};

TEST_F(RenderMagnification, TheDataFollowsThePointLensOnBothImages) {
    ASSERT_NO_FATAL_FAILURE(renderLensData());
    const lc::io::ImageChannels data = lc::io::readImageChannels(dir / "lens.exr");
    std::map<std::string, std::size_t> channel;
    for (std::size_t c = 0; c < data.names.size(); ++c) channel[data.names[c]] = c;
    ASSERT_TRUE(channel.count("magnification") && channel.count("shear") && channel.count("rotation"));
    const double thetaE = 2e-4, fx = std::tan(0.025 * lc::kPi / 180), fy = std::tan(0.01875 * lc::kPi / 180);
    const lc::Vec3 forward = lc::Vec3(1, 0.0001, -0.00005).normalized();
    const lc::Vec3 right = forward.cross(lc::Vec3::UnitZ()).normalized(), up = right.cross(forward);
    int outer = 0, inner = 0;
    for (int j = 0; j < data.height; ++j)
        for (int i = 0; i < data.width; ++i) {
            // The pinhole's direction through the pixel's centre (docs/SCENES.md's camera).
            const double sx = (2 * (i + 0.5) / data.width - 1) * fx, sy = (1 - 2 * (j + 0.5) / data.height) * fy;
            const lc::Vec3 n = (forward + sx * right + sy * up).normalized();
            const double x = thetaE / std::acos(n(0));
            if ((x > 1 / 1.3 && x < 1.6) || x > 3) continue;
            const float* px = &data.data[(static_cast<std::size_t>(j) * data.width + i) * data.names.size()];
            EXPECT_NEAR(px[channel["magnification"]] * (1 - std::pow(x, 4)), 1, 3e-3) << i << ", " << j;
            EXPECT_NEAR(px[channel["shear"]] / (x * x), 1, 3e-3) << i << ", " << j;
            (x > 1 ? inner : outer)++;
        }
    EXPECT_GT(outer, 500);
    EXPECT_GT(inner, 10);
}

TEST_F(RenderMagnification, ShadeDrawsTheChannelsAndRefusesDataWithoutThem) {
    ASSERT_NO_FATAL_FAILURE(renderLensData());
    const CommandResult r = runCommand(lightcone() + " shade " + dir / "lens.json " + dir / "lens.exr -o " +
                                       dir / "mu.png --show magnification");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const lc::io::ImageChannels mu = lc::io::readImageRgb(dir / "mu.png");
    const lc::io::ImageChannels data = lc::io::readImageChannels(dir / "lens.exr");
    std::size_t muChannel = 0;
    for (std::size_t c = 0; c < data.names.size(); ++c)
        if (data.names[c] == "magnification") muChannel = c;
    int mirrored = 0, kept = 0;
    for (std::size_t p = 0; p < mu.data.size() / 3; ++p) {
        const float m = data.data[p * data.names.size() + muChannel];
        const float red = mu.data[3 * p], blue = mu.data[3 * p + 2];
        if (std::abs(m) < 1.5) continue;  // dark below, where the colours cannot tell
        if (m < 0) {
            EXPECT_GT(blue, red + 0.05) << "a mirrored image is drawn blue, pixel " << p;
            ++mirrored;
        } else {
            EXPECT_NEAR(blue, red, 0.02) << "an image of kept parity is grey, pixel " << p;
            ++kept;
        }
    }
    EXPECT_GT(mirrored, 5);
    EXPECT_GT(kept, 5);

    ASSERT_EQ(runCommand(lightcone() + " render " + dir / "lens.json" + " -o " + dir / "plain.png --data " +
                         dir / "plain.exr --quiet")
                  .exitCode,
              0);
    const CommandResult refused =
        runCommand(lightcone() + " shade " + dir / "lens.json " + dir / "plain.exr -o " + dir / "no.png --show shear");
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("--magnification"), std::string::npos) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "no.png"));
}

// The source 1e-4 rad from the lens; the mass swept from 0.25 to 1, so u = beta / theta_E from 1
// to 0.5 (theta_E^2 = 4 M / D).
TEST_F(RenderMagnification, SweepAddsUpAPointSourcesImagesAsPaczynski) {
    const CommandResult r =
        runCommand(lightcone() + " sweep " + dir / "lens.json" + " --sweep metric.M=0.25:1:3 --table " +
                   dir / "images.csv --point-source 1,0.00008,0.00006 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream csv(dir / "images.csv");
    std::string header, line;
    std::getline(csv, header);
    std::vector<std::string> names;
    for (std::stringstream h(header); std::getline(h, line, ',');) names.push_back(line);
    auto column = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    ASSERT_LT(column("point_source_magnification"), names.size()) << header;
    int rows = 0;
    while (std::getline(csv, line)) {
        std::vector<double> v;
        for (std::stringstream l(line); std::getline(l, header, ',');)
            v.push_back(std::strtod(header.c_str(), nullptr));
        const double mass = v[0], u = 1e-4 / std::sqrt(4 * mass / 1e8);
        EXPECT_EQ(v[column("point_source_images")], 2) << line;
        EXPECT_NEAR(v[column("point_source_magnification")] / ((u * u + 2) / (u * std::sqrt(u * u + 4))), 1, 3e-3)
            << line;
        EXPECT_NEAR(v[column("point_source_signed_magnification")], 1, 3e-3) << line;
        ++rows;
    }
    EXPECT_EQ(rows, 3);
}

}  // namespace
