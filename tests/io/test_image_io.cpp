// SPDX-License-Identifier: BSD-3-Clause
// readers/io/image_io: an image with extra channels round-trips through EXR, and a failing write
// leaves the existing file untouched; PNG stores the sRGB curve (IEC 61966-2-1); OpenImageIO's
// module (readers/io/oiio_codec) is loaded only by the first image read or written.
#include "readers/io/image_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

using namespace lc;

namespace {

TEST(ImageIo, WriteIsAtomicAndRoundTrips) {
    const std::string path = (std::filesystem::temp_directory_path() / "lightcone_io_test.exr").string();
    io::ImageChannels img;
    img.width = 3;
    img.height = 2;
    img.names = {"R", "G", "B", "affine"};
    for (int i = 0; i < 24; ++i) img.data.push_back(0.1f * i);
    io::writeImage(path, img);
    const io::ImageChannels back = io::readImageRgb(path);
    ASSERT_EQ(back.width, 3);
    EXPECT_FLOAT_EQ(back.data[3], img.data[4]);  // second pixel's R
    // A failing write leaves the existing file untouched.
    img.data.pop_back();
    EXPECT_THROW(io::writeImage(path, img), std::invalid_argument);
    EXPECT_EQ(io::readImageRgb(path).width, 3);
    std::filesystem::remove(path);
}

bool openImageIoIsLoaded() {
    std::ifstream maps("/proc/self/maps");
    for (std::string line; std::getline(maps, line);)
        if (line.find("libOpenImageIO") != std::string::npos) return true;
    return false;
}

// The libraries the dynamic loader maps when this test program starts (ld.so's trace mode:
// listed, not run), whatever earlier tests of this process have loaded since.
std::string librariesLoadedAtStart() {
    const std::string command = "LD_TRACE_LOADED_OBJECTS=1 " + std::filesystem::read_symlink("/proc/self/exe").string();
    std::string listing;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[4096];
        for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) listing.append(buffer, n);
        pclose(pipe);
    }
    return listing;
}

// IEC 61966-2-1, written here from the standard (the oracle for core's srgb.hpp).
double srgbEncoded(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// Text attributes travel in EXR headers (named "lightcone:..." when read back); PNG has none.
TEST(ImageIo, ExrKeepsLightconeAttributes) {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("lightcone_attributes_" + std::to_string(::getpid()) + ".exr"))
            .string();
    lc::io::ImageChannels img;
    img.width = 2;
    img.height = 1;
    img.names = {"R", "G", "B"};
    img.data = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
    img.attributes = {{"lightcone:report", "line one\nline two\n"}};
    lc::io::writeImage(path, img);
    const lc::io::ImageChannels back = lc::io::readImageChannels(path);
    std::filesystem::remove(path);
    ASSERT_EQ(back.attributes.size(), 1u);
    EXPECT_EQ(back.attributes[0].first, "lightcone:report");
    EXPECT_EQ(back.attributes[0].second, "line one\nline two\n");
}

TEST(ImageIo, OpenImageIoIsLoadedByTheFirstImageNotPngAndPngHoldsTheSrgbCurve) {
    const std::string atStart = librariesLoadedAtStart();
    ASSERT_NE(atStart.find("libjsoncpp"), std::string::npos) << atStart;  // the listing worked
    EXPECT_EQ(atStart.find("libOpenImageIO"), std::string::npos)
        << "a program that never reads or writes an image pays for OpenImageIO's libraries";
    io::ImageChannels img;
    img.width = 4;
    img.height = 1;
    img.names = {"R", "G", "B"};
    const float linear[4] = {0.0f, 0.002f, 0.18f, 1.0f};
    for (float v : linear) img.data.insert(img.data.end(), {v, v, v});
    const std::string path = (std::filesystem::temp_directory_path() / "lightcone_io_srgb_test.png").string();
    const bool loadedBefore = openImageIoIsLoaded();  // by an earlier test in this process
    io::writeImage(path, img);
    // PNG is written by libpng (io/png_encoder): OpenImageIO waits for the first other image.
    if (!loadedBefore) {
        EXPECT_FALSE(openImageIoIsLoaded());
    }
    io::writeImage(path + ".exr", img);
    EXPECT_TRUE(openImageIoIsLoaded());
    std::filesystem::remove(path + ".exr");
    const io::ImageChannels back = io::readImageChannels(path);  // the stored 8-bit values, as 0..1
    ASSERT_EQ(back.width, 4);
    ASSERT_EQ(back.names.size(), 3u);
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(back.data[3 * i] * 255.0, std::round(255.0 * srgbEncoded(linear[i])), 1e-3) << "pixel " << i;
    // readImageRgb decodes the curve again: within half an 8-bit step of the linear value.
    const io::ImageChannels rgb = io::readImageRgb(path);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(rgb.data[3 * i], linear[i], 0.5 / 255.0 / 0.3) << "pixel " << i;
    std::filesystem::remove(path);
}

TEST(ImageIo, LabelsAreDrawnNearTheirBaselineOnly) {
    io::ImageChannels img;
    img.width = 64;
    img.height = 32;
    img.names = {"R", "G", "B"};
    img.data.assign(64 * 32 * 3, 0.25f);
    io::drawLabels(img, {{4, 20, "Hi"}}, 13);
    int changedNear = 0, changedFar = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            const bool changed = img.data[(y * 64 + x) * 3] != 0.25f;
            (x < 30 && y > 4 && y < 24 ? changedNear : changedFar) += changed;
        }
    EXPECT_GT(changedNear, 20);  // two glyphs and their shadow
    EXPECT_EQ(changedFar, 0);
    io::ImageChannels grey = img;
    grey.names = {"Y"};
    EXPECT_THROW(io::drawLabels(grey, {{0, 10, "x"}}), std::invalid_argument);
}

}  // namespace
