// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every file Lightcone reads (scenes, meshes, textures, pixel data) is opened through here: only
// regular files of bounded size. A device (/dev/zero), a FIFO or a directory would otherwise be
// read forever or fail deep inside a library.
#include "core/input/ranges.hpp"

#include <cstdint>
#include <string>

namespace lc::io {

// Throws std::runtime_error ("is a directory", "is not a regular file", "is N bytes, over the
// limit of M bytes", "no such file") unless `path` is a readable regular file inside `bytes`.
// Returns its size.
std::uintmax_t checkInputFile(const std::string& path, const input::Range& bytes);

// The whole file, after checkInputFile.
std::string readInputFile(const std::string& path, const input::Range& bytes);

}  // namespace lc::io
