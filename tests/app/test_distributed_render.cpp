// SPDX-License-Identifier: BSD-3-Clause
// mpirun -np 2 and -np 3 on this machine make the same files as one process (images byte for
// byte, per-pixel data EXRs value for value: their headers hold the time of writing):
// Goedel (closed form in bands of rows, per vertex as whole frames) and Kerr (numeric), a single
// image and a sequence; one failing rank fails the whole run and nothing is written.
#include "app/distributed/distributed_tasks.hpp"
#include "readers/io/image_io.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <regex>

using namespace lc::test;
namespace fs = std::filesystem;

namespace {

// The launcher with this machine's settings: ranks beyond the cores (3 on 2), no core binding
// (each rank's OpenMP threads may use every core), root allowed (CI containers).
std::string mpirun(int ranks) {
#ifdef LIGHTCONE_MPIEXEC
    return std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") + LIGHTCONE_MPIEXEC +
           " --oversubscribe --bind-to none -np " + std::to_string(ranks) + " ";
#else
    (void)ranks;
    return "";
#endif
}

class DistributedRender : public ::testing::Test {
protected:
    void SetUp() override {
#ifndef LIGHTCONE_MPIEXEC
        GTEST_SKIP() << "no MPI launcher was found at configure time (Debian: openmpi-bin, libopenmpi-dev)";
#endif
        if (!lc::dist::Processes::builtWithMpi())
            GTEST_SKIP() << "this build has no MPI (LIGHTCONE_WITH_MPI off or MPI not found)";
    }
    // Runs `args` (writing into dir) on one process and on `ranks`, and expects identical files.
    void expectSameFiles(const std::string& args, const std::vector<std::string>& files, int ranks) {
        const ScratchFolder one("mpi-one"), many("mpi-many");
        auto in = [](const ScratchFolder& d, const std::string& a) {
            return std::regex_replace(a, std::regex("OUT/"), d / "");
        };
        const CommandResult single = runCommand(lightcone() + " " + in(one, args));
        ASSERT_EQ(single.exitCode, 0) << single.output;
        const CommandResult distributed = runCommand(mpirun(ranks) + lightcone() + " " + in(many, args));
        ASSERT_EQ(distributed.exitCode, 0) << distributed.output;
        EXPECT_NE(distributed.output.find(std::to_string(ranks) + " processes"), std::string::npos)
            << distributed.output;
        for (const std::string& f : files) {
            ASSERT_TRUE(fs::exists(many / f)) << f;
            if (fs::path(f).extension() == ".exr") {  // OpenEXR headers carry the time of writing
                const lc::io::ImageChannels a = lc::io::readImageChannels(one / f),
                                            b = lc::io::readImageChannels(many / f);
                EXPECT_EQ(a.names, b.names);
                EXPECT_TRUE(a.data == b.data) << f << " differs on " << ranks << " ranks";
            } else {
                EXPECT_EQ(fileBytes(one / f), fileBytes(many / f)) << f << " differs on " << ranks << " ranks";
            }
        }
    }
};

TEST_F(DistributedRender, GodelClosedFormImageAndDataAreTheSameOnTwoAndThreeRanks) {
    const std::string args =
        "render " + sourcePath("data/default.json") + " -o OUT/g.png --data OUT/g.exr --width 180 --height 60 --quiet";
    expectSameFiles(args, {"g.png", "g.exr"}, 2);
    expectSameFiles(args, {"g.png", "g.exr"}, 3);
}

TEST_F(DistributedRender, KerrNumericImageIsTheSameOnThreeRanks) {
    expectSameFiles(
        "render " + sourcePath("data/kerr.json") + " -o OUT/k.png --data OUT/k.exr --width 60 --height 30 --quiet",
        {"k.png", "k.exr"}, 3);
}

TEST_F(DistributedRender, SequencesAreTheSameOnThreeRanks) {
    expectSameFiles(
        "animate " + sourcePath("data/kerr.json") + " -o OUT/%d.png --pan 0:40:3 --width 40 --height 20 --quiet",
        {"0.png", "1.png", "2.png"}, 3);
    // Moving bodies: whole frames per task (photo-objects per vertex).
    expectSameFiles("animate " + sourcePath("data/godel_free_fall_earth.json") +
                        " -o OUT/e%d.png --proper-time 0:1:2 --width 110 --height 13 --quiet",
                    {"e0.png", "e1.png"}, 2);
}

TEST_F(DistributedRender, OneFailingRankFailsTheRunWithItsMessageAndWritesNothing) {
    for (const char* rank : {"2", "0"}) {
        const ScratchFolder dir("mpi-fail");
        const CommandResult r =
            runCommand("LIGHTCONE_TEST_FAIL_RANK=" + std::string(rank) + " " + mpirun(3) +
                       "-x LIGHTCONE_TEST_FAIL_RANK " + lightcone() + " render " + sourcePath("data/kerr.json") +
                       " -o " + dir / "k.png" + " --width 40 --height 20 --quiet");
        EXPECT_NE(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("rank " + std::string(rank)), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("failure injected by LIGHTCONE_TEST_FAIL_RANK"), std::string::npos) << r.output;
        EXPECT_TRUE(fs::is_empty(dir.path())) << "a failed run left files";
    }
}

}  // namespace
