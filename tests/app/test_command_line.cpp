// SPDX-License-Identifier: BSD-3-Clause
// The command line's declarations (app/cli/command_line.hpp): the parser enforces what they declare,
// the help shows it, and the docs a user reads agree with the help.
#include "app/cli/cli_args.hpp"
#include "app/cli/command_line.hpp"
#include "core/metrics/factory.hpp"
#include "core/render/render.hpp"
#include "core/scene/observer_world_line.hpp"
#include "core/spacetime/integrator.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace lc::cli {
namespace {

const CommandDeclaration& command(const std::string& name) {
    const CommandDeclaration* c = findCommand(name);
    if (!c) throw std::logic_error("no command " + name);
    return *c;
}

std::string refusal(const std::vector<std::string>& argv, const std::string& name) {
    try {
        Args args(argv, command(name));
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::filesystem::path kSource = LIGHTCONE_SOURCE_DIR;

TEST(CommandLine, ValuesOptionsAndPositionalsAsDeclared) {
    const Args args({"scene.json", "--width=320", "-o", "a.png", "--output", "b.png", "--height", "200", "--quiet",
                     "--spectrum", "s.csv", "--spectrum", "s.svg", "--width", "5", "6"},
                    command("render"));
    EXPECT_EQ(args.positional(), (std::vector<std::string>{"scene.json", "6"}));  // one value per occurrence
    EXPECT_EQ(args.integer("--width", 0), 5);                                     // the later wins
    EXPECT_EQ(args.get("-o"), "b.png");                                           // -o and --output: one option
    EXPECT_EQ(args.get("--output"), "b.png");
    EXPECT_TRUE(args.has("--quiet"));
    EXPECT_FALSE(args.has("--gpu"));
    EXPECT_EQ(args.all("--spectrum"), (std::vector<std::string>{"s.csv", "s.svg"}));
    EXPECT_FALSE(args.has("--movie"));                                           // animate's, not render's: absent
    EXPECT_EQ(Args({"--width", "-5"}, command("render")).get("--width"), "-5");  // a negative number is a value
}

TEST(CommandLine, RefusesWhatTheDeclarationsForbid) {
    EXPECT_NE(refusal({"s.json", "--colour", "red"}, "render").find("unknown option '--colour'"), std::string::npos);
    EXPECT_NE(refusal({"s.json", "-x"}, "render").find("unknown option '-x'"), std::string::npos);
    EXPECT_EQ(refusal({"s.json", "--quiet=yes"}, "render"), "option --quiet is a flag and takes no value");
    EXPECT_EQ(refusal({"s.json", "--width"}, "render"), "option --width needs a value (N)");
    EXPECT_EQ(refusal({"s.json", "--method", "magic"}, "render"),
              "option --method: expected one of auto, numeric, closed_form, per_vertex, polygon_distortion; got "
              "'magic'");
    EXPECT_EQ(refusal({"s.json", "--data", "d.exr", "--gpu"}, "render"), "give --data or --gpu, not both");
    EXPECT_EQ(refusal({"s.json", "--orbit-frames", "3"}, "render"), "--orbit-frames goes with --gpu");
    EXPECT_EQ(refusal({"s.json", "-o", "%d.png", "--fps", "30"}, "animate"), "--fps goes with --movie");
    EXPECT_EQ(refusal({"s.json", "-o", "%d.png", "--motion", "static"}, "animate"), "--motion goes with --proper-time");
    EXPECT_EQ(refusal({"--impact", "3", "--event", "0,0,0,0", "--direction", "1,0,0"}, "trace"),
              "give --impact or --event, not both");
    EXPECT_EQ(refusal({"--impact", "3", "--direction", "1,0,0"}, "trace"), "give --impact or --direction, not both");
    EXPECT_EQ(refusal({"--event", "0,0,0,0"}, "trace"), "--event goes with --direction");
    EXPECT_EQ(refusal({"--distance", "5"}, "trace"), "--distance goes with --impact");
    EXPECT_EQ(refusal({"--point", "1,0,0", "--cylindrical", "1,0,0"}, "images"),
              "give --point or --cylindrical, not both");
    // A value left out: after '=', or before another option (issue #47: `--data --help` printed help
    // and exited 0; main leaves --help where a value belongs to this parser).
    EXPECT_EQ(refusal({"s.json", "--width=", "-o", "a.png"}, "render"), "option --width needs a value (N) after '='");
    EXPECT_EQ(refusal({"s.json", "--data", "--help"}, "render"),
              "option --data needs a value (DATA.exr), got the option '--help'");
    EXPECT_EQ(refusal({"s.json", "-o", "--quiet"}, "render"),
              "option --output needs a value (IMAGE.png), got the option '--quiet'");
    EXPECT_EQ(refusal({"--event", "0,0,0,0", "--direction", "-1,0,0"}, "trace"), "");  // a negative value is a value
    // An unknown option is named before a broken pair.
    EXPECT_NE(refusal({"--fps", "3", "--bogus"}, "animate").find("unknown option '--bogus'"), std::string::npos);
}

TEST(CommandLine, NumbersAreCheckedAgainstTheDeclaredRange) {
    const Args args({"s.json", "--width", "2.5", "--tolerance", "nan", "--look-at", "1,2"}, command("render"));
    EXPECT_THROW(args.integer("--width", 0), std::invalid_argument);
    EXPECT_THROW(args.number("--tolerance", 0), std::invalid_argument);
    EXPECT_THROW(args.numbers("--look-at", 3), std::invalid_argument);
    EXPECT_EQ(&args.range("--width"), &input::kImageSide);
    EXPECT_EQ(args.integer("--height", 7), 7);  // absent: the fallback
}

// Every word an option accepts is one the core understands, so a declared choice never fails later.
TEST(CommandLine, DeclaredChoicesAreTheCoresNames) {
    for (const std::string& m : command("render").option("--method")->choices)
        if (m != "polygon_distortion") {
            EXPECT_NO_THROW(parseRenderMethod(m)) << m;
        }
    for (const std::string& s : command("trace").option("--stepper")->choices) EXPECT_NO_THROW(parseStepper(s)) << s;
    EXPECT_EQ(command("trace").option("--stepper")->choices, stepperNames());
    for (const std::string& m : command("animate").option("--motion")->choices)
        EXPECT_NO_THROW(parseObserverMotion(m)) << m;
    for (const std::string& m : command("trace").option("--metric")->choices)
        EXPECT_NO_THROW(makeSpacetime(m, {})) << m;
}

TEST(CommandLine, HelpShowsEveryOptionWithItsRangeAndRules) {
    for (const CommandDeclaration& c : commandDeclarations()) {
        const std::string help = commandHelp(c);
        EXPECT_EQ(help.find("usage:\n  lightcone " + c.name), help.find("usage:")) << c.name;
        EXPECT_NE(help.find("usage:\n  lightcone " + c.name), std::string::npos) << c.name;
        for (const OptionDeclaration& o : c.options) {
            EXPECT_NE(help.find(o.names + (o.flag() ? "" : " " + o.value)), std::string::npos) << c.name << o.names;
            // The range's words may wrap: compare without line breaks and indentation.
            std::string flat = std::regex_replace(help, std::regex("\\s+"), " ");
            if (o.range) {
                EXPECT_NE(flat.find(o.range->describe()), std::string::npos) << c.name << o.names;
            }
            for (const std::string& n : o.needs) EXPECT_NE(flat.find("Needs " + n), std::string::npos) << o.names;
        }
        for (const std::string& line : c.usage)
            EXPECT_NE(overviewHelp().find("lightcone " + c.name + (line.empty() ? "" : " " + line) + "\n"),
                      std::string::npos);
    }
    EXPECT_NE(commandHelp(command("trace")).find("--impact B"), std::string::npos);
}

// docs/CLI.md is the program's help, as `lightcone help --markdown` prints it.
TEST(CommandLineDocs, CliMarkdownEqualsTheHelp) {
    EXPECT_EQ(readFile(kSource / "docs/CLI.md"), helpMarkdown())
        << "regenerate: ./build/app/lightcone help --markdown > docs/CLI.md";
}

// README.md shows each command's usage lines as --help prints them, and every command line in
// README.md and docs/*.md uses only options its command declares.
TEST(CommandLineDocs, ReadmeAndDocsUseTheDeclaredCommandLine) {
    const std::string readme = readFile(kSource / "README.md");
    for (const CommandDeclaration& c : commandDeclarations()) {
        if (c.name == "help" || c.name == "completion") continue;
        for (const std::string& line : c.usage)
            EXPECT_NE(readme.find("\n    lightcone " + c.name + (line.empty() ? "" : " " + line) + "\n"),
                      std::string::npos)
                << "README.md lacks the usage line of " << c.name << ": lightcone " << c.name << " " << line;
    }
    std::vector<std::filesystem::path> files{kSource / "README.md"};
    for (const auto& entry : std::filesystem::directory_iterator(kSource / "docs"))
        if (entry.path().extension() == ".md" && entry.path().filename() != "CLI.md") files.push_back(entry.path());
    const std::regex invocation("(^|[\\s/])lightcone ([a-z]+)( .*)?$");
    int checked = 0;
    for (const auto& file : files) {
        std::istringstream lines(readFile(file));
        std::string line;
        for (int number = 1; std::getline(lines, line); ++number) {
            std::smatch m;
            if (line.rfind("    ", 0) != 0 || !std::regex_search(line, m, invocation)) continue;
            const CommandDeclaration* c = findCommand(m[2]);
            if (!c) continue;
            ++checked;
            std::istringstream words(m[3]);
            for (std::string word; words >> word;) {
                const auto start = word.find_first_not_of("[(");
                if (start == std::string::npos) continue;
                word = word.substr(start);
                word = word.substr(0, word.find_first_of("=])"));
                if (word.size() < 2 || word[0] != '-' || word == "--help" || input::parseNumber(word)) continue;
                EXPECT_NE(c->option(word), nullptr)
                    << file.filename() << ":" << number << ": lightcone " << c->name << " declares no option " << word;
            }
        }
    }
    EXPECT_GT(checked, 12);  // the usage lines and examples of README.md and docs/
    // docs/SCENES.md names command-line options in prose: each one exists.
    const std::string scenes = readFile(kSource / "docs/SCENES.md");
    const std::regex named("`(--[a-z-]+)");
    for (auto it = std::sregex_iterator(scenes.begin(), scenes.end(), named); it != std::sregex_iterator(); ++it) {
        bool declared = false;
        for (const CommandDeclaration& c : commandDeclarations()) declared = declared || c.option((*it)[1]) != nullptr;
        EXPECT_TRUE(declared) << "docs/SCENES.md names " << (*it)[1] << ", which no command declares";
    }
}

}  // namespace
}  // namespace lc::cli
