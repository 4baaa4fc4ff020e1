// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The fixed input files a fuzz target writes into its temporary folder at start-up.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace lc::fuzz {

// Written aside and renamed: another fuzzing process may be reading the same file.
inline void writeFile(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
    const std::filesystem::path tmp = dir / (name + ".tmp" + std::to_string(::getpid()));
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
    }
    std::filesystem::rename(tmp, dir / name);
}

}  // namespace lc::fuzz
