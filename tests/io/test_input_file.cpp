// SPDX-License-Identifier: BSD-3-Clause
// readers/io/input_file: files that are not regular (devices, FIFOs, folders), empty, missing or
// over their size limit are refused with a message, also when a scene names one as a texture.
#include "readers/io/input_file.hpp"
#include "readers/io/scene_reader.hpp"
#include "tests/io/temp_file.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace lc;
using lc::test::writeFile;

TEST(InputFiles, DevicesFifosFoldersAndHugeFilesAreRefused) {
    auto error = [](const std::string& path, const input::Range& r) {
        try {
            io::checkInputFile(path, r);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error("/dev/zero", input::kTextureFileBytes).find("not a regular file"), std::string::npos);
    EXPECT_NE(error(fs::temp_directory_path().string(), input::kSceneFileBytes).find("is a directory"),
              std::string::npos);
    const fs::path fifo = fs::temp_directory_path() / ("lightcone_fifo_" + std::to_string(::getpid()));
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(error(fifo.string(), input::kSceneFileBytes).find("not a regular file"), std::string::npos);
    fs::remove(fifo);
    const input::Range tiny{"test file size", 1, 4, true, "bytes", ""};
    EXPECT_NE(error(writeFile("five.txt", "12345").string(), tiny).find("over the limit of 4 bytes"),
              std::string::npos);
    EXPECT_NE(error(writeFile("empty.txt", "").string(), tiny).find("is empty"), std::string::npos);
    EXPECT_NE(error("/nonexistent/file", tiny).find("does not exist"), std::string::npos);
}

TEST(InputFiles, TextureFromADeviceIsAnErrorNotAHang) {
    const std::string scene = R"({"metric": {"name": "godel"}, "objects": [{"type": "sphere", "centre": [0,1,0,0],
        "radius": 0.2, "texture": "/dev/zero"}]})";
    try {
        io::parseScene(scene, "scene.json", ".");
        FAIL();
    } catch (const io::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("objects[0].texture"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
    }
}
