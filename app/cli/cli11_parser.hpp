// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The CLI11 parser of one declared command (app/cli/command_line.hpp), shared by the argument
// parser (cli_args.cpp) and the help (command_help.cpp). Only these two files see CLI11.
#include "app/cli/command_line.hpp"

#include <memory>

namespace CLI {
class App;
}

namespace lc::cli {

// Every option of `command` with its names, value, group, description, needs and excludes.
// Positional arguments and unknown options stay in App::remaining() (allow_extras), so that
// Args can name an unknown option in Lightcone's words.
std::unique_ptr<CLI::App> makeParser(const CommandDeclaration& command);

}  // namespace lc::cli
