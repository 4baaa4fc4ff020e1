// SPDX-License-Identifier: BSD-3-Clause
// PNG through libpng (io/png_encoder, the command line's PNG without OpenImageIO): read back by
// OpenImageIO, an independent decoder, every pixel is the nearest 8-bit level of what was given
// (clamped to [0, 1]); the attributes are tEXt chunks; a size that disagrees with the data is
// refused.
#include "readers/io/image_io.hpp"
#include "readers/io/png_encoder.hpp"
#include "temp_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

TEST(PngEncoder, OpenImageIoReadsBackTheNearestLevelOfEveryPixel) {
    lc::io::ImageChannels image;
    image.width = 7;
    image.height = 5;
    image.names = {"R", "G", "B", "object"};  // an extra channel is dropped
    for (int p = 0; p < image.width * image.height; ++p)
        for (int c = 0; c < 4; ++c) image.data.push_back(static_cast<float>(((p * 37 + c * 11) % 101) / 90.0 - 0.05));
    image.attributes = {{"Software", "Lightcone test"}, {"Comment", "levels"}};
    const std::string bytes = lc::io::encodePng(image);
    EXPECT_NE(bytes.find(std::string("tEXtSoftware") + '\0' + "Lightcone test"), std::string::npos);
    EXPECT_NE(bytes.find(std::string("tEXtComment") + '\0' + "levels"), std::string::npos);
    EXPECT_NE(bytes.find("sRGB"), std::string::npos);
    const auto file = lc::test::writeFile("levels.png", bytes);
    const lc::io::ImageChannels back = lc::io::readImageChannels(file.string());
    std::filesystem::remove(file);
    ASSERT_EQ(back.width, image.width);
    ASSERT_EQ(back.height, image.height);
    ASSERT_EQ(back.names.size(), 3u);
    for (int p = 0; p < image.width * image.height; ++p)
        for (int c = 0; c < 3; ++c) {
            const double given = std::clamp(image.data[4 * p + c], 0.0f, 1.0f);
            EXPECT_EQ(std::lround(back.data[3 * p + c] * 255.0), std::lround(given * 255.0)) << p << " " << c;
        }
}

TEST(PngEncoder, RefusesDataThatDisagreesWithTheSize) {
    lc::io::ImageChannels image;
    image.width = 2;
    image.height = 2;
    image.names = {"R", "G", "B"};
    image.data.assign(11, 0.5f);
    EXPECT_THROW(lc::io::encodePng(image), std::invalid_argument);
    image.data.assign(12, 0.5f);
    image.names = {"R", "G"};
    EXPECT_THROW(lc::io::encodePng(image), std::invalid_argument);
}

}  // namespace
