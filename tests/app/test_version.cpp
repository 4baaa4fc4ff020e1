// SPDX-License-Identifier: BSD-3-Clause
// `lightcone --version` (issue #45): the version of CMake's project(), the commit the programs
// were built from (a commit git knows) and the libraries' versions, at once,
// before any command or module is loaded.
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <regex>

using namespace lc::test;

namespace {

TEST(Version, NamesTheVersionTheCommitAndTheLibraries) {
    const CommandResult r = runCommand(lightcone() + " --version");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string cmake = fileBytes(sourcePath("CMakeLists.txt"));
    std::smatch project;
    ASSERT_TRUE(std::regex_search(cmake, project, std::regex(R"(project\(Lightcone VERSION ([0-9.]+))")));
    EXPECT_EQ(r.output.rfind("lightcone " + project[1].str() + " (commit ", 0), 0u) << r.output;
    // The commit is one of this repository's (HEAD at the last build, so not always HEAD now: a
    // commit made since without building), as git itself says; "unknown" outside a git checkout.
    std::smatch commit;
    ASSERT_TRUE(std::regex_search(r.output, commit, std::regex(R"(\(commit ([0-9a-f]+|unknown), )"))) << r.output;
    if (runCommand("git -C " + sourcePath("") + " rev-parse --git-dir").exitCode == 0) {
        EXPECT_EQ(runCommand("git -C " + sourcePath("") + " cat-file -e " + commit[1].str() + "^{commit}").exitCode, 0)
            << commit[1];
    }
    for (const char* library : {"VTK ", "Qt ", "OpenImageIO ", "Eigen 3.4", "Boost 1.", "licence BSD-3-Clause"})
        EXPECT_NE(r.output.find(library), std::string::npos) << library << "\n" << r.output;
    EXPECT_EQ(runCommand(lightcone() + " -V").output, r.output);
}

}  // namespace
