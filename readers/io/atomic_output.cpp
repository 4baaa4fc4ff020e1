// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/atomic_output.hpp"
#include "readers/io/file_extension.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <set>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace lc::io {
namespace fs = std::filesystem;
namespace {

constexpr const char* kPrefix = ".lightcone-tmp-";

std::string uniqueTemporaryName(const std::string& base) {
    static std::atomic<unsigned> counter{0};
    return std::string(kPrefix) + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" + base;
}

fs::path folderOf(const fs::path& p) { return p.has_parent_path() ? p.parent_path() : fs::path("."); }

std::string describe(const fs::path& target, const std::string& option) {
    return (option.empty() ? "" : option + " ") + "'" + target.string() + "'";
}

// Temporary names whose process is gone (killed between link and rename) are removed.
void removeStaleTemporaries(const fs::path& folder) {
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.rfind(kPrefix, 0) != 0) continue;
        const long pid = std::strtol(name.c_str() + std::strlen(kPrefix), nullptr, 10);
        if (pid == ::getpid()) continue;
        if (pid <= 0 || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)) {
            std::error_code ignored;
            fs::remove_all(it->path(), ignored);
        }
    }
}

bool writeAll(int fd, const std::string& bytes) {
    const char* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    return ::fsync(fd) == 0;
}

// Writes `bytes` to an unnamed file in `folder` and links it as `name`; falls back to a named
// temporary file where O_TMPFILE or /proc is unavailable. Returns false with errno set.
bool stage(const fs::path& folder, const std::string& name, const std::string& bytes) {
    const fs::path temp = folder / name;
    int fd = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0644);
    if (fd >= 0) {
        const bool ok = writeAll(fd, bytes) && ::linkat(AT_FDCWD, ("/proc/self/fd/" + std::to_string(fd)).c_str(),
                                                        AT_FDCWD, temp.c_str(), AT_SYMLINK_FOLLOW) == 0;
        const int saved = errno;
        ::close(fd);
        errno = saved;
        if (ok) return true;
        if (errno != ENOENT && errno != EXDEV && errno != EPERM) return false;
    }
    fd = ::open(temp.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0644);
    if (fd < 0) return false;
    const bool ok = writeAll(fd, bytes);
    const int saved = errno;
    ::close(fd);
    if (!ok) ::unlink(temp.c_str());
    errno = saved;
    return ok;
}

// Can files be created in `folder`? Asked of the file system itself (access() says yes to root
// even on /proc): an unnamed file where O_TMPFILE works, else a named probe removed at once.
bool canCreateFilesIn(const fs::path& folder) {
    int fd = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
    if (fd >= 0) {
        ::close(fd);
        return true;
    }
    if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) return false;
    const fs::path probe = folder / uniqueTemporaryName("probe");
    fd = ::open(probe.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0600);
    if (fd < 0) return false;
    ::close(fd);
    ::unlink(probe.c_str());
    return true;
}

}  // namespace

const char* temporaryPrefix() { return kPrefix; }

void OutputSet::add(const std::string& target, std::string bytes, const std::string& option) {
    if (target.empty()) throw std::invalid_argument((option.empty() ? "output" : option) + ": empty file name");
    files_.push_back({fs::path(target), std::move(bytes), option});
}

void OutputSet::commit() {
    std::vector<fs::path> staged;
    auto unstage = [&staged] {
        for (const auto& p : staged) ::unlink(p.c_str());
    };
    std::set<fs::path> folders;
    for (const File& f : files_) folders.insert(folderOf(f.target));
    for (const auto& folder : folders) removeStaleTemporaries(folder);
    for (const File& f : files_) {
        const fs::path folder = folderOf(f.target);
        std::error_code ec;
        if (fs::is_directory(f.target, ec)) {
            unstage();
            throw std::runtime_error("cannot write " + describe(f.target, f.option) + ": it is a folder");
        }
        const std::string temp = uniqueTemporaryName(f.target.filename().string());
        if (!stage(folder, temp, f.bytes)) {
            const std::string why = std::strerror(errno);
            unstage();
            throw std::runtime_error("cannot write " + describe(f.target, f.option) + ": " + why +
                                     " (nothing was replaced; is the folder there and writable?)");
        }
        staged.push_back(folder / temp);
    }
    for (std::size_t i = 0; i < files_.size(); ++i) {
        if (::rename(staged[i].c_str(), files_[i].target.c_str()) != 0) {
            const std::string why = std::strerror(errno);
            for (std::size_t k = i; k < staged.size(); ++k) ::unlink(staged[k].c_str());
            throw std::runtime_error("cannot replace " + describe(files_[i].target, files_[i].option) + ": " + why);
        }
    }
    files_.clear();
}

void writeFileAtomically(const std::string& target, const std::string& bytes, const std::string& option) {
    OutputSet set;
    set.add(target, bytes, option);
    set.commit();
}

namespace {
fs::path inside(const fs::path& folder, const std::string& relative) {
    const fs::path rel(relative);
    if (rel.empty() || rel.is_absolute())
        throw std::invalid_argument("output name '" + relative + "' must be relative");
    for (const auto& part : rel)
        if (part == ".." || part == "." || part.string().empty() || part.string().front() == '.')
            throw std::invalid_argument("output name '" + relative + "' would leave its folder or be hidden");
    return folder / rel;
}
}  // namespace

void writeFolderAtomically(const fs::path& folder, const std::vector<std::pair<std::string, std::string>>& files) {
    std::error_code ec;
    for (const auto& [name, bytes] : files) inside(folder, name);  // every name checked before writing
    if (fs::exists(folder, ec)) {
        if (!fs::is_directory(folder, ec))
            throw std::runtime_error("cannot write into '" + folder.string() + "': not a folder");
        OutputSet set;
        for (const auto& [name, bytes] : files) {
            const fs::path target = inside(folder, name);
            fs::create_directories(target.parent_path(), ec);
            set.add(target.string(), bytes);
        }
        set.commit();
        return;
    }
    const fs::path parent = folderOf(folder);
    removeStaleTemporaries(parent);
    const fs::path temp = parent / uniqueTemporaryName(folder.filename().string());
    if (!fs::create_directory(temp, ec))
        throw std::runtime_error("cannot create a folder beside '" + folder.string() + "': " + ec.message());
    try {
        for (const auto& [name, bytes] : files) {
            const fs::path target = inside(temp, name);
            fs::create_directories(target.parent_path());
            const int fd = ::open(target.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0644);
            const bool ok = fd >= 0 && writeAll(fd, bytes);
            const std::string why = std::strerror(errno);
            if (fd >= 0) ::close(fd);
            if (!ok) throw std::runtime_error("cannot write '" + (folder / name).string() + "': " + why);
        }
        fs::rename(temp, folder);
    } catch (...) {
        fs::remove_all(temp, ec);
        throw;
    }
}

void checkOutputPath(const std::string& path, const std::vector<std::string>& extensions, const std::string& option) {
    const fs::path p(path);
    const std::string what = option + " '" + path + "'";
    if (path.empty()) throw std::invalid_argument(option + " needs a file name");
    std::error_code ec;
    if (fs::is_directory(p, ec)) throw std::invalid_argument(what + " is a folder; give a file name inside it");
    const fs::path folder = folderOf(p);
    if (!fs::is_directory(folder, ec))
        throw std::invalid_argument(what + ": the folder '" + folder.string() + "' does not exist");
    if (!canCreateFilesIn(folder))
        throw std::invalid_argument(what + ": cannot create files in the folder '" + folder.string() + "' (" +
                                    std::strerror(errno) + ")");
    if (!p.has_filename() || p.filename().string().front() == '.')
        throw std::invalid_argument(what + ": give a visible file name (not starting with '.')");
    if (!extensions.empty()) {
        const std::string ext = lowerCaseExtension(path);
        if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
            std::string list;
            for (const auto& e : extensions) list += (list.empty() ? "" : ", ") + e;
            throw std::invalid_argument(what + ": unknown file type '" + ext + "' (use " + list + ")");
        }
    }
}

void checkOutputFolder(const std::string& folder, const std::string& option) {
    const fs::path p(folder);
    std::error_code ec;
    if (fs::exists(p, ec)) {
        if (!fs::is_directory(p, ec))
            throw std::invalid_argument(option + " '" + folder + "' exists and is not a folder");
        if (!canCreateFilesIn(p)) throw std::invalid_argument(option + " '" + folder + "': cannot create files in it");
        return;
    }
    const fs::path parent = folderOf(p);
    if (!fs::is_directory(parent, ec))
        throw std::invalid_argument(option + " '" + folder + "': its parent folder '" + parent.string() +
                                    "' does not exist");
    if (!canCreateFilesIn(parent))
        throw std::invalid_argument(option + " '" + folder + "': cannot create a folder in its parent");
}

std::string sanitizeFileName(const std::string& name) {
    std::string out;
    for (char c : name) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
        out += keep ? c : '_';
        if (out.size() == 64) break;
    }
    if (out.empty() || out.front() == '.') out.insert(out.begin(), '_');
    return out.substr(0, 64);
}

}  // namespace lc::io
