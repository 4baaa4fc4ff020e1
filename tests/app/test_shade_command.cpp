// SPDX-License-Identifier: BSD-3-Clause
// `lightcone shade` as a user runs it: post-rendering from stored per-pixel data, one image or a
// sequence (--sweep), checked against physics and symmetry rather than captured output: a hotter
// black body looks bluer, a u offset of one whole turn gives the same image back, each frame of
// a sweep is the single image of its value, and a time window shows fewer object pixels.
#include "app/commands/commands.hpp"
#include "core/render/post_render.hpp"
#include "readers/io/image_io.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>

using namespace lc::test;

namespace {

class ShadeCommand : public ::testing::Test {
protected:
    void SetUp() override {
        const CommandResult r = runCommand(lightcone() + " render " + scene + " -o " + dir / "plain.png" + " --data " +
                                           dir / "data.exr --width 120 --height 48 --quiet");
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    CommandResult shade(const std::string& options) const {
        return runCommand(lightcone() + " shade " + scene + " " + dir / "data.exr " + options);
    }
    // Mean blue over mean red of the object pixels (the object is the only non-black colour here).
    static double blueOverRed(const lc::io::ImageChannels& img, const lc::RenderResult& data) {
        double red = 0, blue = 0;
        for (std::size_t p = 0; p < data.pixels.size(); ++p)
            if (data.pixels[p].kind == lc::PixelRecord::Object) {
                red += img.data[3 * p];
                blue += img.data[3 * p + 2];
            }
        return blue / red;
    }
    const std::string scene = sourcePath("data/godel_many_images.json");
    const ScratchFolder dir{"shade"};
};

TEST_F(ShadeCommand, TemperatureSweepWritesOneFramePerValueAndHotterIsBluer) {
    const CommandResult r = shade("-o " + dir / "t_%02d.png --sweep temperature=3000:9000:3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("wrote 3 frames"), std::string::npos) << r.output;
    const lc::Scene s = lc::io::readScene(scene);
    const lc::RenderResult data = lc::cli::readPixelData(dir / "data.exr", s);
    double previous = 0;
    for (int k = 0; k < 3; ++k) {
        const auto frame = lc::io::readImageRgb(dir / ("t_0" + std::to_string(k) + ".png"));
        // The frame is the single image of its temperature, 3000 + 3000 k K.
        ASSERT_EQ(shade("-o " + dir / "single.png --temperature " + std::to_string(3000 + 3000 * k)).exitCode, 0);
        EXPECT_TRUE(fileBytes(dir / ("t_0" + std::to_string(k) + ".png")) == fileBytes(dir / "single.png")) << k;
        const double ratio = blueOverRed(frame, data);
        EXPECT_GT(ratio, previous) << "T = " << 3000 + 3000 * k << " K should look bluer than the one before";
        previous = ratio;
    }
}

// The help's own example writes into window/%03d.png: the sweep makes the pattern's folder as
// animate does, when its parent exists (issue #47: it refused the missing folder).
TEST_F(ShadeCommand, SweepMakesItsFramesFolderAsAnimateDoes) {
    const CommandResult r = shade("-o " + dir / "window/%03d.png --time-window -2,0 --sweep time-window=-6:0:3");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* frame : {"window/000.png", "window/001.png", "window/002.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / frame)) << frame;
    const CommandResult deeper = shade("-o " + dir / "no/such/%03d.png --sweep temperature=3000:9000:2");
    EXPECT_EQ(deeper.exitCode, 2);
    EXPECT_NE(deeper.output.find("parent folder"), std::string::npos) << deeper.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "no"));
}

// The scene's checker has 16 cells around: a u offset of 1/16 swaps its colours, one of 1 (a
// whole turn) gives the image back.
TEST_F(ShadeCommand, AUOffsetOfOneTurnGivesTheSameImageAndOneCellAnother) {
    ASSERT_EQ(shade("-o " + dir / "u_%02d.png --sweep u-offset=0:1:17").exitCode, 0);
    EXPECT_TRUE(fileBytes(dir / "u_00.png") == fileBytes(dir / "u_16.png"));
    EXPECT_FALSE(fileBytes(dir / "u_00.png") == fileBytes(dir / "u_01.png"));
    // Nothing moved: the unshaded data give the image render wrote.
    ASSERT_EQ(shade("-o " + dir / "again.png").exitCode, 0);
    EXPECT_TRUE(fileBytes(dir / "again.png") == fileBytes(dir / "plain.png"));
}

TEST_F(ShadeCommand, ATimeWindowHidesTheLightEmittedOutsideIt) {
    const lc::Scene s = lc::io::readScene(scene);
    const lc::RenderResult data = lc::cli::readPixelData(dir / "data.exr", s);
    std::size_t objects = 0, inside = 0;
    for (const auto& p : data.pixels)
        if (p.kind == lc::PixelRecord::Object) {
            ++objects;
            inside += p.emissionTime >= -6 && p.emissionTime <= 0;
        }
    ASSERT_GT(objects, inside);
    ASSERT_GT(inside, 0u);
    const CommandResult r = shade("-o " + dir / "w.png --time-window -6,0");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(std::to_string(objects - inside) + " object pixels outside"), std::string::npos)
        << r.output;
    // Over a second texture the hidden images come back, in its colours.
    ASSERT_EQ(shade("-o " + dir / "w2.png --time-window -6,0 --outside-texture checker").exitCode, 0);
    EXPECT_FALSE(fileBytes(dir / "w.png") == fileBytes(dir / "w2.png"));
}

TEST_F(ShadeCommand, RefusesATextureItCannotLoadAndAnObjectTheSceneLacks) {
    CommandResult r = shade("-o " + dir / "x.png --texture no_such_texture.png");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("option --texture 'no_such_texture.png'"), std::string::npos) << r.output;
    r = shade("-o " + dir / "x.png --texture moon=checker");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("no object 'moon'"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// A wormhole's two skies (data/ellis_wormhole.json): the data keep which end each sky pixel's ray
// reached, so shade draws the far side's sky through the throat as render did, and a file whose
// pixels claim the far side is refused for a scene with one end.
TEST(ShadeCommandTwoSkies, TheEndChannelBringsBackTheFarSidesSky) {
    const ScratchFolder dir{"shade_two_skies"};
    const std::string scene = sourcePath("data/ellis_wormhole.json");
    const CommandResult r = runCommand(lightcone() + " render " + scene + " -o " + dir / "plain.png" + " --data " +
                                       dir / "data.exr --width 96 --height 48 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const lc::io::ImageChannels data = lc::io::readImageChannels(dir / "data.exr");
    std::size_t endChannel = data.names.size(), farPixels = 0;
    for (std::size_t c = 0; c < data.names.size(); ++c)
        if (data.names[c] == "end") endChannel = c;
    ASSERT_LT(endChannel, data.names.size());
    for (std::size_t n = 0; n < static_cast<std::size_t>(data.width) * data.height; ++n)
        farPixels += data.data[n * data.names.size() + endChannel] == 1;
    EXPECT_GT(farPixels, 50u);  // the throat's disc, about 10.6 degrees across in a 60 degree view
    const CommandResult again =
        runCommand(lightcone() + " shade " + scene + " " + dir / "data.exr -o " + dir / "again.png");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_TRUE(fileBytes(dir / "again.png") == fileBytes(dir / "plain.png"));
    const CommandResult wrong = runCommand(lightcone() + " shade " + sourcePath("data/kerr.json") + " " +
                                           dir / "data.exr -o " + dir / "wrong.png");
    EXPECT_NE(wrong.exitCode, 0);
    EXPECT_NE(wrong.output.find("reached a far end"), std::string::npos) << wrong.output;
}

}  // namespace
