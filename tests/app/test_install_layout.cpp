// SPDX-License-Identifier: BSD-3-Clause
// What an installed Lightcone relies on (issue #45), through the real binary: scenes and metrics
// found by bare name on LIGHTCONE_DATA_PATH (installed: PREFIX/share/lightcone/data, checked from
// a moved install by tests/install/installed_tree.sh), the man pages written from the declarations,
// and the program's version in every output it writes (image headers, VTK field data).
#include "app/cli/command_line.hpp"
#include "run_command.hpp"

#ifdef LIGHTCONE_WITH_VTK
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <regex>

using namespace lc::test;
namespace fs = std::filesystem;

namespace {

// "Lightcone 0.1.0 (commit abc1234)" from `lightcone --version`'s first line
// ("lightcone 0.1.0 (commit abc1234, Release build)").
std::string softwareFromVersion() {
    const std::string version = runCommand(lightcone() + " --version").output;
    std::smatch m;
    EXPECT_TRUE(std::regex_search(version, m, std::regex(R"(^lightcone ([0-9.]+) \(commit ([0-9a-f]+|unknown),)")))
        << version;
    return "Lightcone " + m[1].str() + " (commit " + m[2].str() + ")";
}

TEST(DataSearchPath, ABareSceneNameIsFoundOnLightconeDataPathInOrder) {
    const ScratchFolder dir("data-path");
    fs::create_directories(dir.path() / "run");
    fs::create_directories(dir.path() / "first");
    // The first folder's default.json is not a scene: found first, so refused by name.
    std::ofstream(dir / "first/default.json") << "{\"metric\": 5}";
    const std::string cd = "cd " + dir / "run" + " && ";
    CommandResult r = runCommand(cd + "LIGHTCONE_DATA_PATH=" + sourcePath("data") + " " + lightcone() +
                                 " render default.json -o d.png --width 16 --height 8 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "run/d.png"));
    r = runCommand(cd + "LIGHTCONE_DATA_PATH=" + dir / "first" + ":" + sourcePath("data") + " " + lightcone() +
                   " render default.json -o e.png --quiet");
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find(dir / "first/default.json"), std::string::npos) << r.output;
    // A file in the working folder wins over the search path.
    fs::copy_file(sourcePath("data/kerr.json"), dir / "run/default.json");
    r = runCommand(cd + "LIGHTCONE_DATA_PATH=" + dir / "first" + " " + lightcone() +
                   " render default.json -o f.png --width 16 --height 8 --quiet");
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(DataSearchPath, AMissingSceneSaysWhereItLooked) {
    const ScratchFolder dir("data-missing");
    CommandResult r = runCommand("cd " + dir / "" + " && env -u LIGHTCONE_DATA_PATH " + lightcone() +
                                 " render nowhere.json -o x.png");
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("nowhere.json: the file does not exist"), std::string::npos) << r.output;
    // This build tree lies in the checkout: its data/ is searched (installed: share/lightcone/data).
    EXPECT_NE(r.output.find("not found in the working folder nor in " + sourcePath("data") + ")"), std::string::npos)
        << r.output;
    r = runCommand("cd " + dir / "" + " && LIGHTCONE_DATA_PATH=/nonexistent:" + sourcePath("data") + " " + lightcone() +
                   " render nowhere.json -o x.png");
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("not found in the working folder nor in /nonexistent, " + sourcePath("data") + ")"),
              std::string::npos)
        << r.output;
}

TEST(DataSearchPath, MetricFilesByBareName) {
    const ScratchFolder dir("data-metric");
    const CommandResult r = runCommand("cd " + dir / "" + " && LIGHTCONE_DATA_PATH=" + sourcePath("data/metrics") +
                                       " " + lightcone() + " metric check ellis_wormhole.json");
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(MetricCatalogue, ListsEveryMetricFileFoundAndTheBuiltIns) {
    const ScratchFolder dir("metric-list");
    // An extra folder first: a broken metric file is listed with its error, a scene is skipped.
    std::ofstream(dir / "broken.json") << "{\"name\": \"broken\", \"coordinates\": [\"t\", \"x\", \"y\", \"z\"], "
                                          "\"ds2\": \"-dt^2 + (dx^2\"}";
    fs::copy_file(sourcePath("data/kerr.json"), dir / "a_scene.json");
    const CommandResult r =
        runCommand("cd " + dir / "" + " && LIGHTCONE_DATA_PATH=" + dir / "" + " " + lightcone() + " metric list");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("  broken: not a readable metric: "), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("a_scene"), std::string::npos) << r.output;
    int files = 0;
    for (const auto& entry : fs::directory_iterator(sourcePath("data/metrics")))
        if (entry.path().extension() == ".json") {
            ++files;
            EXPECT_NE(r.output.find("\n  " + entry.path().stem().string() + ": "), std::string::npos)
                << entry.path() << "\n"
                << r.output;
        }
    EXPECT_NE(r.output.find(std::to_string(files) + " metric files, "), std::string::npos) << r.output;
    for (const std::string builtIn : {"minkowski", "schwarzschild", "kerr-newman", "alcubierre", "godel-cylindrical"})
        EXPECT_NE(r.output.find("\n  " + builtIn + ": "), std::string::npos) << builtIn;
    EXPECT_NE(r.output.find("kerr: kerr-formula, cartesian chart; M = 1 [1e-06, 1e+06], a = 0.9"), std::string::npos)
        << r.output;
}

TEST(MetricCatalogue, CheckTakesAMetricByItsNameAndListTakesNoOptions) {
    const ScratchFolder dir("metric-name");
    CommandResult r = runCommand("cd " + dir / "" + " && " + lightcone() + " metric check kerr --param a=0.5");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("metric 'kerr-formula' (" + sourcePath("data/metrics/kerr.json") + ")"), std::string::npos)
        << r.output;
    r = runCommand(lightcone() + " metric list --at 0,1,2,3");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("metric list takes no options"), std::string::npos) << r.output;
}

TEST(ManPages, OnePagePerCommandWithEveryOptionEscapedForRoff) {
    const auto pages = lc::cli::manPages();
    ASSERT_EQ(pages.size(), lc::cli::commandDeclarations().size() + 1);
    EXPECT_EQ(pages[0].first, "lightcone.1");
    for (const lc::cli::CommandDeclaration& c : lc::cli::commandDeclarations()) {
        const auto page = std::find_if(pages.begin(), pages.end(),
                                       [&](const auto& p) { return p.first == "lightcone-" + c.name + ".1"; });
        ASSERT_NE(page, pages.end()) << c.name;
        std::string upper = "LIGHTCONE-" + c.name;
        for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        EXPECT_EQ(page->second.rfind(".TH " + upper + " 1 ", 0), 0u) << page->second.substr(0, 80);
        for (const lc::cli::OptionDeclaration& o : c.options) {
            // --max-affine as roff writes it: \-\-max\-affine
            const std::string escaped = std::regex_replace(o.longName(), std::regex("-"), "\\-");
            EXPECT_NE(page->second.find("\\fB" + escaped + "\\fR"), std::string::npos) << c.name << " " << o.names;
        }
        // No line may start with a roff control character except the requests written on purpose.
        std::istringstream lines(page->second);
        for (std::string line; std::getline(lines, line);)
            if (!line.empty() && (line[0] == '.' || line[0] == '\'')) {
                EXPECT_TRUE(std::regex_match(line, std::regex(R"(\.(TH|SH|SS|TP|PP|nf|fi)( .*)?)"))) << line;
            }
    }
}

TEST(ManPages, HelpManWritesThemIntoTheFolderAskedForOnly) {
    const ScratchFolder dir("man");
    CommandResult r = runCommand(lightcone() + " help --man " + dir / "man1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "man1/lightcone.1"));
    EXPECT_TRUE(fs::exists(dir / "man1/lightcone-render.1"));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
    for (const char* wrong : {"", " --markdown", " ''", " a b"}) {
        r = runCommand("cd " + dir / "" + " && " + lightcone() + " help --man" + wrong);
        EXPECT_EQ(r.exitCode, 2) << wrong << ": " << r.output;
        EXPECT_NE(r.output.find("help --man expects one folder"), std::string::npos) << r.output;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator{}), 1);
    std::ofstream(dir / "file") << "x";
    r = runCommand(lightcone() + " help --man " + dir / "file");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--man"), std::string::npos) << r.output;
}

TEST(Provenance, ImagesNameTheProgramThatWroteThemInTheirHeaders) {
    const ScratchFolder dir("provenance-image");
    const std::string software = softwareFromVersion();
    const CommandResult r = runCommand(lightcone() + " render " + sourcePath("data/default.json") + " -o " +
                                       dir / "d.png" + " --data " + dir / "d.exr" + " --width 16 --height 8 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // PNG: a tEXt chunk "Software\0<text>" (PNG specification 11.3.4.3).
    EXPECT_NE(fileBytes(dir / "d.png").find(std::string("tEXtSoftware") + '\0' + software), std::string::npos);
    // EXR: an attribute "Software" of type "string" (OpenEXR file layout: name\0 type\0 size value).
    const std::string exr = fileBytes(dir / "d.exr");
    EXPECT_NE(exr.find(std::string("Software") + '\0' + "string" + '\0'), std::string::npos);
    EXPECT_NE(exr.find(software), std::string::npos);
}

#ifdef LIGHTCONE_WITH_VTK
TEST(Provenance, ExportedVtkFilesCarryTheVersionInFieldData) {
    const ScratchFolder dir("provenance-vtk");
    const CommandResult r = runCommand(lightcone() + " export " + sourcePath("data/kerr.json") + " -o " + dir / "out");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName((dir / "out/horizon.vtp").c_str());
    reader->Update();
    auto* version =
        vtkStringArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray("lightcone_version"));
    ASSERT_NE(version, nullptr);
    EXPECT_EQ(version->GetValue(0), softwareFromVersion());
    EXPECT_GT(reader->GetOutput()->GetNumberOfPoints(), 0);
}
#endif

}  // namespace
