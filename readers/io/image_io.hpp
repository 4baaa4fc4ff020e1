#pragma once
// Image files through OpenImageIO, written atomically (temporary file, then rename), so an
// existing image is never left half-written.
#include <string>
#include <vector>

namespace lc::io {

// Linear-RGB float pixels (row 0 at the top). PNG/JPEG get the sRGB curve and 8 bits;
// EXR/HDR/TIFF keep linear floats. Extra named channels go only into formats that hold them.
struct ImageChannels {
    int width = 0, height = 0;
    std::vector<std::string> names;  // e.g. {"R","G","B"} or {"R","G","B","object","u",...}
    std::vector<float> data;         // interleaved, names.size() per pixel
};

void writeImage(const std::string& path, const ImageChannels& image);
// Reads any OIIO format into linear RGB floats (sRGB-decoded for 8-bit files).
ImageChannels readImageRgb(const std::string& path);
// Reads every channel of a float image (e.g. the per-pixel data EXR of `render --data`).
ImageChannels readImageChannels(const std::string& path);

float srgbEncode(float linear);
float srgbDecode(float encoded);

}  // namespace lc::io
