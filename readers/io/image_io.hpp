// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Image files through OpenImageIO, encoded in memory and written atomically
// (readers/io/atomic_output.hpp), so an existing image is never left half-written.
#include <string>
#include <utility>
#include <vector>

namespace lc::io {

// Linear-RGB float pixels (row 0 at the top). PNG/JPEG get the sRGB curve and 8 bits;
// EXR/HDR/TIFF keep linear floats. Extra named channels go only into formats that hold them.
struct ImageChannels {
    int width = 0, height = 0;
    std::vector<std::string> names;  // e.g. {"R","G","B"} or {"R","G","B","object","u",...}
    std::vector<float> data;         // interleaved, names.size() per pixel
    // Text attributes kept in the file's header by formats that hold them (EXR, TIFF), e.g.
    // "lightcone:report": the render's figures beside its per-pixel data. Read back: those named
    // "lightcone:...".
    std::vector<std::pair<std::string, std::string>> attributes;
};

// The file's bytes in the format its extension names (.png, .jpg, .exr, .tif, .hdr, .bmp).
std::string encodeImage(const std::string& pathForFormat, const ImageChannels& image);
// encodeImage, then the atomic writer (readers/io/atomic_output.hpp). Refuses non-finite pixels.
void writeImage(const std::string& path, const ImageChannels& image);
// Extensions writeImage understands; those that keep extra channels (per-pixel data).
const std::vector<std::string>& imageExtensions();
const std::vector<std::string>& multiChannelImageExtensions();
// Reads any OIIO format into linear RGB floats (sRGB-decoded for 8-bit files). Only regular
// files within input::kTextureFileBytes and input::kTexturePixels are opened.
ImageChannels readImageRgb(const std::string& path);
// Reads every channel of a float image (e.g. the per-pixel data EXR of `render --data`).
ImageChannels readImageChannels(const std::string& path);

// A text drawn into an RGB image: its baseline starts at pixel (x, y) (row 0 at the top).
struct ImageLabel {
    int x = 0, y = 0;
    std::string text;  // UTF-8
};
// Draws the labels in white over a dark shadow (DejaVu Sans through OIIO's FreeType text), so they
// read on any background; labels outside the image are clipped. `image` must be RGB.
void drawLabels(ImageChannels& image, const std::vector<ImageLabel>& labels, int fontPixels = 13);

float srgbEncode(float linear);
float srgbDecode(float encoded);

}  // namespace lc::io
