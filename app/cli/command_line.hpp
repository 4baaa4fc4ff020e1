// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every command of `lightcone` and every option it takes, declared once: the parser (CLI11,
// app/cli/cli_args.cpp), `--help`, `lightcone help`, the bash completion and the test that keeps
// README.md and docs/CLI.md equal to the help all read this table.
#include "core/input/ranges.hpp"

#include <string>
#include <utility>
#include <vector>

namespace lc::cli {

struct OptionDeclaration {
    std::string names;                    // "--width", or "-o,--output" (the long name last)
    std::string value;                    // what it takes ("N", "IMAGE.png"); empty for a flag
    std::string group;                    // the heading it is listed under in --help
    std::string help;                     // what it does, its unit and its default
    const input::Range* range = nullptr;  // each number it takes lies in this range (checked, printed)
    bool repeatable = false;              // may be given more than once; every value is kept
    std::vector<std::string> choices;     // the words it accepts (checked, printed, completed)
    std::vector<std::string> needs;       // long names of options it needs beside it
    std::vector<std::string> excludes;    // long names of options it cannot go with

    std::string longName() const;  // "--output" for "-o,--output"
    bool flag() const { return value.empty(); }
};

struct CommandDeclaration {
    std::string name;
    std::string summary;             // one line, in `lightcone help`
    std::vector<std::string> usage;  // synopsis lines, each after "lightcone NAME "
    std::vector<OptionDeclaration> options;
    std::vector<std::string> examples;  // command lines shown under "examples:"
    bool needsVtk = false;              // diagram, export: VTK builds only

    // The option named `name` (any of its names); nullptr when the command has none.
    const OptionDeclaration* option(const std::string& optionName) const;
};

// Every command, in the order `lightcone help` lists them (this build's only).
const std::vector<CommandDeclaration>& commandDeclarations();
// nullptr for an unknown command.
const CommandDeclaration* findCommand(const std::string& name);

// An option's help text: what it does, its choices, accepted range, needs and exclusions.
std::string optionDescription(const OptionDeclaration& option);
// `lightcone COMMAND --help`: usage, options by group with their ranges, examples.
std::string commandHelp(const CommandDeclaration& command);
// `lightcone help`: every command's usage line and summary.
std::string overviewHelp();
// docs/CLI.md: the overview and every command's help, as Markdown.
std::string helpMarkdown();
// `lightcone help --man DIR`: a man page per command (lightcone-COMMAND.1) and lightcone.1 for
// the overview, in roff, as (file name, text), from the same declarations as --help.
std::vector<std::pair<std::string, std::string>> manPages();
// `lightcone completion bash`: a bash completion script for commands, options and their words.
std::string bashCompletion();

}  // namespace lc::cli
