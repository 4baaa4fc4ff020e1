// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A file with the given bytes in the temporary folder, its name unique to this process: the
// input-check tests write the files they then refuse or read.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace lc::test {

inline std::filesystem::path writeFile(const std::string& name, const std::string& bytes) {
    const std::filesystem::path p =
        std::filesystem::temp_directory_path() / ("lightcone_check_" + std::to_string(::getpid()) + "_" + name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
}

}  // namespace lc::test
