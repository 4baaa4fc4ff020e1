// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/oiio_codec.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace lc::io {

namespace {

// Where CMake built it; for a build folder moved whole (LIGHTCONE_OIIO_CODEC_PATH gone), the
// same place below a folder above the program (build/app/lightcone -> build/readers/...).
std::string modulePath() {
    namespace fs = std::filesystem;
    std::error_code ignored;
    if (fs::exists(LIGHTCONE_OIIO_CODEC_PATH, ignored)) return LIGHTCONE_OIIO_CODEC_PATH;
    Dl_info self{};
    if (dladdr(reinterpret_cast<void*>(&oiioCodec), &self) && self.dli_fname)
        for (fs::path folder = fs::absolute(self.dli_fname, ignored).parent_path(); folder.has_relative_path();
             folder = folder.parent_path())
            if (fs::exists(folder / LIGHTCONE_OIIO_CODEC_IN_BUILD, ignored))
                return (folder / LIGHTCONE_OIIO_CODEC_IN_BUILD).string();
    return LIGHTCONE_OIIO_CODEC_PATH;
}

const OiioCodec& load() {
    const std::string path = modulePath();
    // RTLD_LOCAL: OpenImageIO's libraries stay out of the program's symbol scope.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
        throw std::runtime_error(std::string("cannot load the image codec (OpenImageIO) module: ") + dlerror() +
                                 " (rebuild with `cmake --build build`)");
    using Entry = const OiioCodec* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(handle, "lightconeOiioCodec"));
    if (!entry) throw std::runtime_error("the image codec module '" + path + "' has no lightconeOiioCodec()");
    return *entry();  // never unloaded: its functions are used until the program ends
}

}  // namespace

const OiioCodec& oiioCodec() {
    static const OiioCodec& codec = load();  // thread-safe, once
    return codec;
}

}  // namespace lc::io
