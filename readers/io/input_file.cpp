// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/input_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lc::io {
namespace fs = std::filesystem;

std::uintmax_t checkInputFile(const std::string& path, const input::Range& bytes) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) throw std::runtime_error("does not exist");
    if (fs::is_directory(st)) throw std::runtime_error("is a directory, not a file");
    if (!fs::is_regular_file(st)) throw std::runtime_error("is not a regular file (a device, FIFO or socket)");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw std::runtime_error("cannot read its size: " + ec.message());
    if (static_cast<double>(size) > bytes.max)
        throw std::runtime_error("is " + std::to_string(size) + " bytes, over the limit of " +
                                 input::formatBound(bytes.max) + " bytes for a " + bytes.key);
    if (size == 0) throw std::runtime_error("is empty");
    return size;
}

std::string readInputFile(const std::string& path, const input::Range& bytes) {
    checkInputFile(path, bytes);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot be opened (check the permissions)");
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace lc::io
