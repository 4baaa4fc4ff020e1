// SPDX-License-Identifier: BSD-3-Clause
// The atomic writer: files appear complete or not at all, failures replace nothing, names never
// leave the chosen folder, and no temporary name is left behind.
#include "readers/io/atomic_output.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace lc::io;

namespace {

fs::path freshFolder(const std::string& name) {
    const fs::path p = fs::temp_directory_path() / ("lightcone_atomic_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

std::string contents(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::size_t temporaries(const fs::path& folder) {
    std::size_t n = 0;
    for (const auto& e : fs::recursive_directory_iterator(folder))
        n += e.path().filename().string().rfind(temporaryPrefix(), 0) == 0;
    return n;
}

}  // namespace

TEST(AtomicOutput, ReplacesTheFileAndLeavesNoTemporaryName) {
    const fs::path dir = freshFolder("replace");
    writeFileAtomically((dir / "a.txt").string(), "old");
    writeFileAtomically((dir / "a.txt").string(), "new contents");
    EXPECT_EQ(contents(dir / "a.txt"), "new contents");
    EXPECT_EQ(temporaries(dir), 0u);
}

TEST(AtomicOutput, AFailingFileReplacesNoneOfTheSet) {
    const fs::path dir = freshFolder("set");
    writeFileAtomically((dir / "image.png").string(), "old image");
    OutputSet set;
    set.add((dir / "image.png").string(), "new image", "-o");
    set.add((dir / "missing-folder" / "data.exr").string(), "data", "--data");
    try {
        set.commit();
        FAIL() << "expected an error for the missing folder";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("--data"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("nothing was replaced"), std::string::npos) << e.what();
    }
    EXPECT_EQ(contents(dir / "image.png"), "old image");
    EXPECT_EQ(temporaries(dir), 0u);
}

TEST(AtomicOutput, AFolderTargetIsRefusedBeforeAnyWork) {
    const fs::path dir = freshFolder("folder");
    EXPECT_THROW(checkOutputPath(dir.string(), {".png"}, "-o"), std::invalid_argument);
    EXPECT_THROW(checkOutputPath((dir / "nope" / "x.png").string(), {".png"}, "-o"), std::invalid_argument);
    EXPECT_THROW(checkOutputPath((dir / "x.bmpx").string(), {".png"}, "-o"), std::invalid_argument);
    EXPECT_THROW(checkOutputPath("/proc/x.exr", {".exr"}, "--data"), std::invalid_argument);
    EXPECT_NO_THROW(checkOutputPath((dir / "x.png").string(), {".png"}, "-o"));
    EXPECT_THROW(writeFileAtomically(dir.string(), "bytes"), std::runtime_error);
}

TEST(AtomicOutput, NewFolderAppearsWholeAndNamesCannotEscapeIt) {
    const fs::path dir = freshFolder("export");
    const fs::path out = dir / "export";
    writeFolderAtomically(out, {{"a.vtp", "A"}, {"photo_0_ball/photo_0_ball_0.vtp", "B"}});
    EXPECT_EQ(contents(out / "a.vtp"), "A");
    EXPECT_EQ(contents(out / "photo_0_ball" / "photo_0_ball_0.vtp"), "B");
    // Into an existing folder: replaced file by file; escaping or hidden names refused up front.
    writeFolderAtomically(out, {{"a.vtp", "A2"}});
    EXPECT_EQ(contents(out / "a.vtp"), "A2");
    EXPECT_THROW(writeFolderAtomically(out, {{"b.vtp", "x"}, {"../../escaped.vtp", "x"}}), std::invalid_argument);
    EXPECT_THROW(writeFolderAtomically(out, {{"/tmp/escaped.vtp", "x"}}), std::invalid_argument);
    EXPECT_THROW(writeFolderAtomically(out, {{".hidden/x.vtp", "x"}}), std::invalid_argument);
    EXPECT_FALSE(fs::exists(out / "b.vtp"));  // nothing of a refused set is written
    EXPECT_FALSE(fs::exists(dir / "escaped.vtp"));
    EXPECT_EQ(temporaries(dir), 0u);
}

TEST(AtomicOutput, StaleTemporariesOfDeadProcessesAreRemoved) {
    const fs::path dir = freshFolder("stale");
    // pid 2^22 + 1 is above Linux's pid_max: no such process.
    const fs::path stale = dir / (std::string(temporaryPrefix()) + "4194305-0-image.png");
    std::ofstream(stale) << "left by a killed run";
    writeFileAtomically((dir / "image.png").string(), "fresh");
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_EQ(temporaries(dir), 0u);
}

TEST(AtomicOutput, FileNamesFromObjectNamesAreSafe) {
    EXPECT_EQ(sanitizeFileName("ball"), "ball");
    EXPECT_EQ(sanitizeFileName("../../../../tmp/escaped"), "_.._.._.._.._tmp_escaped");
    EXPECT_EQ(sanitizeFileName(".hidden"), "_.hidden");
    EXPECT_EQ(sanitizeFileName(""), "_");
    EXPECT_EQ(sanitizeFileName("Earth (day)"), "Earth__day_");
    EXPECT_LE(sanitizeFileName(std::string(500, 'x')).size(), 64u);
    for (const std::string s : {"a/b", "a\\b", "..", "x\ny"})
        EXPECT_EQ(sanitizeFileName(s).find_first_of("/\\\n"), std::string::npos) << s;
}
