// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/oiio_codec.hpp"

#include "readers/io/install_layout.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace lc::io {

namespace {

// Installed: PREFIX/lib/lightcone/ beside PREFIX/bin/; in a build tree: build/readers/ beside
// build/app/ (and build/tests/..., build/python/...). Found from the program's own file, so a
// moved install or build tree works and nothing installed names the build tree.
std::string modulePath() {
    for (const char* relative : {LIGHTCONE_OIIO_CODEC_INSTALLED, LIGHTCONE_OIIO_CODEC_IN_BUILD})
        if (const auto found = findAboveProgram(relative)) return found->string();
    return LIGHTCONE_OIIO_CODEC_INSTALLED;  // dlopen's error then names what was looked for
}

const OiioCodec& load() {
    const std::string path = modulePath();
    // RTLD_LOCAL: OpenImageIO's libraries stay out of the program's symbol scope.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
        throw std::runtime_error(std::string("cannot load the image codec (OpenImageIO) module: ") + dlerror() +
                                 " (looked for " LIGHTCONE_OIIO_CODEC_INSTALLED " and " LIGHTCONE_OIIO_CODEC_IN_BUILD
                                 " in the program's folder and those above it; rebuild or reinstall)");
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
