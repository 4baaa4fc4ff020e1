#pragma once
// What image_io needs of OpenImageIO, as a table of functions in a module loaded on first use
// (oiioCodec()). OpenImageIO pulls in about 260 shared libraries; loading them took 0.45 s at
// every start of `lightcone`, also for the runs that refuse their input before any image is
// read or written (the hostile corpus runs a thousand of them).
#include <functional>
#include <string>
#include <vector>

namespace lc::io {

// Pixels as OpenImageIO takes and gives them: interleaved floats, row 0 at the top.
struct OiioPixels {
    int width = 0, height = 0;
    std::vector<std::string> names;  // one per channel
    std::vector<float> data;
    bool eightBitFile = false;  // read: the file stored 8 or 16 bit integers (sRGB-encoded)
};

struct OiioCodec {
    // The file's bytes in the format the extension of `pathForFormat` names; `eightBit` stores
    // UINT8 (the caller has applied the sRGB curve), else floats. Throws std::runtime_error.
    std::string (*encode)(const std::string& pathForFormat, const OiioPixels& pixels, bool eightBit);
    // Reads every channel as floats; `check(width, height, depth, channels)` runs before the
    // pixels are read and throws to refuse the image.
    OiioPixels (*read)(const std::string& path, const std::function<void(int, int, int, int)>& check);
    // Draws `text` (UTF-8, DejaVu Sans) in `colour` into RGB float pixels, baseline at (x, y).
    void (*drawText)(OiioPixels& rgb, int x, int y, const std::string& text, int fontPixels, const float colour[3]);
    const char* version;  // OpenImageIO's version, e.g. "2.4.7"
};

// The codec module (liblightcone_oiio_codec.so), loaded once; throws std::runtime_error naming
// the module and dlerror() when it cannot be loaded.
const OiioCodec& oiioCodec();

}  // namespace lc::io
