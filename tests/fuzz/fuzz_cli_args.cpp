// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the bytes are a command line (arguments separated by NUL bytes, the command
// first), parsed exactly as `lightcone` parses it (app/cli/command_options.hpp) without running the
// command. std::invalid_argument naming the option is how a bad command line is refused; a
// crash, a sanitizer report, a hang or any other exception is a finding.
#include "app/cli/command_options.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> argv(1);
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            if (argv.size() == 64) break;  // a shell passes few arguments; 64 is plenty
            argv.emplace_back();
        } else {
            argv.back() += static_cast<char>(data[i]);
        }
    }
    try {
        lc::cli::parseCommandLine(argv);
    } catch (const std::invalid_argument&) {
        // refused with a message: the expected outcome for most inputs
    }
    return 0;
}
