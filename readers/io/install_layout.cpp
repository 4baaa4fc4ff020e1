// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/install_layout.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cerrno>  // program_invocation_name (glibc)
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace lc::io {

namespace fs = std::filesystem;

fs::path programFile() {
    Dl_info self{};
    std::error_code ignored;
    if (!dladdr(reinterpret_cast<void*>(&programFile), &self) || !self.dli_fname) return {};
    // In the executable itself dladdr answers argv[0] ("lightcone" when found on PATH): the
    // kernel's link names the file run.
    if (std::strcmp(self.dli_fname, program_invocation_name) == 0) {
        const fs::path executable = fs::read_symlink("/proc/self/exe", ignored);
        if (!ignored) return executable;
    }
    return fs::absolute(self.dli_fname, ignored);
}

std::optional<fs::path> findAboveProgram(const fs::path& relative) {
    std::error_code ignored;
    const fs::path program = programFile();
    if (program.empty()) return std::nullopt;
    for (fs::path folder = program.parent_path(); folder.has_relative_path(); folder = folder.parent_path())
        if (fs::exists(folder / relative, ignored)) return folder / relative;
    return std::nullopt;
}

std::vector<fs::path> dataSearchPath(bool metricFiles) {
    std::vector<fs::path> folders;
    if (const char* env = std::getenv("LIGHTCONE_DATA_PATH")) {
        std::istringstream list(env);
        for (std::string folder; std::getline(list, folder, ':');)
            if (!folder.empty()) folders.emplace_back(folder);
    }
    // Installed: PREFIX/bin/lightcone (or PREFIX/lib/python3/dist-packages/lightcone/_core.so)
    // and PREFIX/share/lightcone/data.
    // Metric files first in metrics/: data/kerr.json is a scene, data/metrics/kerr.json its metric.
    std::optional<fs::path> data = findAboveProgram(LIGHTCONE_INSTALL_DATA_DIR);
    // A build tree inside the checkout (build/app/lightcone): the checkout's data/, recognised by
    // its CMakeLists.txt beside it.
    if (!data)
        if (const auto checkout = findAboveProgram("data/metrics"))
            if (fs::exists(checkout->parent_path().parent_path() / "CMakeLists.txt")) data = checkout->parent_path();
    if (data) {
        if (metricFiles) folders.push_back(*data / "metrics");
        folders.push_back(*data);
    }
    // Each folder once (LIGHTCONE_DATA_PATH may name the installed one), in first-seen order.
    std::vector<fs::path> distinct, canonicals;
    std::error_code ignored;
    for (const fs::path& folder : folders) {
        fs::path canonical = fs::weakly_canonical(folder, ignored);
        if (std::find(canonicals.begin(), canonicals.end(), canonical) != canonicals.end()) continue;
        canonicals.push_back(std::move(canonical));
        distinct.push_back(folder);
    }
    return distinct;
}

std::string findDataFile(const std::string& given, bool metricFile, std::string* searchedNote) {
    std::error_code ignored;
    const fs::path path(given);
    if (given.empty() || path.is_absolute() || fs::exists(path, ignored)) return given;
    std::string searched;
    // A metric by its name alone: "kerr" is kerr.json.
    const fs::path named = metricFile && !path.has_extension() ? fs::path(given + ".json") : path;
    for (const fs::path& folder : dataSearchPath(metricFile)) {
        if (fs::is_regular_file(folder / path, ignored)) return (folder / path).string();
        if (fs::is_regular_file(folder / named, ignored)) return (folder / named).string();
        searched += (searched.empty() ? "" : ", ") + folder.string();
    }
    if (searchedNote)
        *searchedNote = searched.empty() ? "not found in the working folder; set LIGHTCONE_DATA_PATH to search others"
                                         : "not found in the working folder nor in " + searched;
    return given;
}

}  // namespace lc::io
