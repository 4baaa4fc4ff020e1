// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A file name's extension in lower case, dot included (".PNG" -> ".png", "" when there is none):
// how every reader and writer of Lightcone picks the format of a file.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace lc::io {

inline std::string lowerCaseExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace lc::io
