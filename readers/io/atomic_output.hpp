// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every file Lightcone writes goes through here, so outputs are all-or-nothing: the bytes are
// made in memory first, written to unnamed files (O_TMPFILE) in the target's own folder, linked
// under temporary names and renamed over the targets only when every file is ready. A failed run
// replaces nothing; a run killed while it computes leaves nothing behind (the data lives in
// memory and unnamed inodes); temporary names exist only for the instant between link and
// rename, and any left by a killed process are removed by the next write to that folder.
#include <filesystem>
#include <string>
#include <vector>

namespace lc::io {

// One command's files, committed together.
class OutputSet {
public:
    // `option` names the command-line option or field in error messages (e.g. "-o").
    void add(const std::string& target, std::string bytes, const std::string& option = "");
    // Throws std::runtime_error naming the file; nothing is replaced then.
    void commit();
    std::size_t size() const { return files_.size(); }

private:
    struct File {
        std::filesystem::path target;
        std::string bytes, option;
    };
    std::vector<File> files_;
};

void writeFileAtomically(const std::string& target, const std::string& bytes, const std::string& option = "");

// A folder of files (export): written complete into a temporary folder beside `folder` and
// renamed into place when `folder` does not exist yet; into an existing folder each file is
// replaced atomically as above. Relative names must stay inside the folder.
void writeFolderAtomically(const std::filesystem::path& folder,
                           const std::vector<std::pair<std::string, std::string>>& relativeNamesAndBytes);

// Before any work: throws std::invalid_argument, naming `option`, unless `path` can become an
// output: its folder exists and is a folder, it is not itself a folder, and its extension is one
// of `extensions` (lower case, with the dot). An empty list accepts any extension.
void checkOutputPath(const std::string& path, const std::vector<std::string>& extensions, const std::string& option);
// The same for an output folder: absent (it will be created, its parent must exist) or a folder.
void checkOutputFolder(const std::string& folder, const std::string& option);

// A file-name part from any text: letters, digits, '-', '_' and '.' kept, the rest '_'; never
// empty, never starting with '.', at most 64 characters. Object names pass through this before
// they name exported files.
std::string sanitizeFileName(const std::string& name);

// The prefix of temporary names ("NAME" of ".lightcone-tmp-PID-N-NAME"), for tests.
const char* temporaryPrefix();

}  // namespace lc::io
