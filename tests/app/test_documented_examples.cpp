// SPDX-License-Identifier: BSD-3-Clause
// Every example a newcomer copies runs as written (issue #47): the examples of each command's
// help (docs/CLI.md) and the command lines README.md gives, in order, in a fresh folder where
// `data` is the repository's, each ending with exit code 0 and the files it names. Renders and
// animations get a smaller size and two frames appended (a later option wins), which changes
// the cost but not what can fail as written: inputs, folders, options, order. Two frames make no
// movie, so an animation's --movie is left out here (AnimateCommand's tests encode movies).
#include "app/cli/command_line.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

namespace lc::cli {
namespace {

using namespace lc::test;
namespace fs = std::filesystem;

// The command lines of README.md's indented blocks that run the built binary.
std::vector<std::string> readmeCommandLines() {
    std::istringstream lines(fileBytes(sourcePath("README.md")));
    std::vector<std::string> out;
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("    ./build/app/lightcone ", 0) == 0)
            out.push_back(line.substr(std::string("    ./build/app/").size()));
    return out;
}

// What the example writes: the values of -o, --data, --table, --plot, --spectrum, --image, --tides,
// --movie (a frame pattern: its folder must hold a file).
std::vector<std::string> namedOutputs(const std::string& commandLine) {
    static const std::regex output(
        R"((?:^|\s)(?:-o|--output|--data|--table|--plot|--spectrum|--image|--tides|--movie)\s+(\S+))");
    std::vector<std::string> out;
    for (auto it = std::sregex_iterator(commandLine.begin(), commandLine.end(), output); it != std::sregex_iterator();
         ++it)
        out.push_back((*it)[1]);
    return out;
}

bool outputExists(const fs::path& folder, const std::string& name) {
    if (name.find('%') == std::string::npos) return fs::exists(folder / name);
    const fs::path dir = (folder / name).parent_path();
    return fs::is_directory(dir) && !fs::is_empty(dir);
}

TEST(DocumentedExamples, EveryHelpAndReadmeExampleRunsAsWrittenFromAFreshFolder) {
    std::vector<std::string> examples;
    for (const CommandDeclaration& c : commandDeclarations())
        examples.insert(examples.end(), c.examples.begin(), c.examples.end());
    const std::vector<std::string> readme = readmeCommandLines();
    ASSERT_GE(readme.size(), 3u);
    examples.insert(examples.end(), readme.begin(), readme.end());
    ASSERT_GT(examples.size(), 15u);

    const ScratchFolder folder("examples");
    fs::create_directory_symlink(sourcePath("data"), folder.path() / "data");
    const bool display = std::getenv("DISPLAY") != nullptr;
    int ran = 0;
    std::set<std::string> seen;  // the help and the README share some examples: each runs once
    for (std::string example : examples) {
        if (!seen.insert(example).second) continue;
        example = example.substr(0, example.find("  #"));  // a comment after the command
        std::string line = example;
        if (line.rfind("xvfb-run -a ", 0) == 0) {
            if (!display) continue;  // ctest runs under xvfb-run, as the README's command does
            line = line.substr(std::string("xvfb-run -a ").size());
        }
        if (line.rfind("lightcone ", 0) != 0) continue;
        line = std::regex_replace(line, std::regex(" --movie \\S+"), "");
        const std::string command = line.substr(std::string("lightcone ").size(), line.find(' ', 10) - 10);
        std::string cheaper;
        if (command == "render") cheaper = " --width 48 --height 24 --quiet";
        if (command == "animate") cheaper = " --width 48 --height 12 --frames 0-1 --quiet";
        const auto start = std::chrono::steady_clock::now();
        const CommandResult r =
            runCommand("cd " + folder.path().string() + " && " + lightcone() + line.substr(9) + cheaper);
        ++ran;
        std::printf("[ measured ] %.2f s: %s\n",
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), line.c_str());
        EXPECT_EQ(r.exitCode, 0) << example << "\n" << r.output;
        for (const std::string& name : namedOutputs(line))
            EXPECT_TRUE(outputExists(folder.path(), name)) << example << " did not write " << name << "\n" << r.output;
    }
    EXPECT_GT(ran, 15);
}

}  // namespace
}  // namespace lc::cli
