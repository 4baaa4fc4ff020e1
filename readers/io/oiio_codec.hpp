// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What image_io needs of OpenImageIO, as a table of functions in a module loaded on first use
// (oiioCodec()). OpenImageIO pulls in about 260 shared libraries; loading them took 0.45 s at
// every start of `lightcone`, also for the runs that refuse their input before any image is
// read or written (the hostile corpus runs a thousand of them).
#include "readers/io/image_io.hpp"  // ImageChannels: the pixels both ways

#include <functional>
#include <string>

namespace lc::io {

struct OiioCodec {
    // The file's bytes in the format the extension of `pathForFormat` names; `eightBit` stores
    // UINT8 (the caller has applied the sRGB curve), else floats. Throws std::runtime_error.
    std::string (*encode)(const std::string& pathForFormat, const ImageChannels& pixels, bool eightBit);
    // Reads every channel as floats, as stored (no sRGB decoding); `check(width, height, depth,
    // channels)` runs before the pixels are read and throws to refuse the image. `eightBitFile`:
    // the file stored 8 or 16 bit integers (sRGB-encoded).
    ImageChannels (*read)(const std::string& path, const std::function<void(int, int, int, int)>& check,
                          bool& eightBitFile);
    // Draws `text` (UTF-8, DejaVu Sans) in `colour` into RGB float pixels, baseline at (x, y).
    void (*drawText)(ImageChannels& rgb, int x, int y, const std::string& text, int fontPixels, const float colour[3]);
    const char* version;  // OpenImageIO's version, e.g. "2.4.7"
};

// The codec module (liblightcone_oiio_codec.so), loaded once; throws std::runtime_error naming
// the module and dlerror() when it cannot be loaded.
const OiioCodec& oiioCodec();

}  // namespace lc::io
