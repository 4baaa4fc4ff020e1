// readers/io/image_io: an image with extra channels round-trips through EXR, and a failing write
// leaves the existing file untouched.
#include "readers/io/image_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

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

}  // namespace
