// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/image_io.hpp"

#include "core/colour/srgb.hpp"
#include "core/input/number_text.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/file_extension.hpp"
#include "readers/io/input_file.hpp"
#include "readers/io/oiio_codec.hpp"
#include "readers/io/png_encoder.hpp"
#include "readers/io/provenance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lc::io {

float srgbEncode(float c) { return static_cast<float>(colour::srgbEncodeDisplay<double>(c)); }
float srgbDecode(float c) { return static_cast<float>(colour::srgbToLinear<double>(c)); }

namespace {
bool isLowDynamicRange(const std::string& ext) {
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".ppm";
}
}  // namespace

const std::vector<std::string>& imageExtensions() {
    static const std::vector<std::string> e{".png", ".jpg", ".jpeg", ".bmp", ".exr", ".tif", ".tiff", ".hdr"};
    return e;
}

const std::vector<std::string>& multiChannelImageExtensions() {
    static const std::vector<std::string> e{".exr", ".tif", ".tiff"};
    return e;
}

std::string encodeImage(const std::string& path, const ImageChannels& img) {
    const std::string ext = lowerCaseExtension(path);
    const bool ldr = isLowDynamicRange(ext);
    const std::size_t nIn = img.names.size();
    const int nOut = ldr || ext == ".hdr" ? 3 : static_cast<int>(nIn);
    if (img.width <= 0 || img.height <= 0 || nIn < 3 || img.data.size() != nIn * img.width * img.height)
        throw std::invalid_argument("writeImage(" + path + "): image size and channel data disagree");
    std::size_t nonFinite = 0;
    for (float v : img.data) nonFinite += !std::isfinite(v);
    if (nonFinite)
        throw std::runtime_error("image '" + path + "' has " + std::to_string(nonFinite) +
                                 " non-finite values (NaN or infinity); nothing was written");

    ImageChannels pixels;
    pixels.width = img.width;
    pixels.height = img.height;
    pixels.names.assign(img.names.begin(), img.names.begin() + nOut);
    if (!ldr) pixels.attributes = img.attributes;
    pixels.attributes.emplace_back("Software", softwareName());  // PNG tEXt, EXR and TIFF headers alike
    pixels.data.resize(static_cast<std::size_t>(img.width) * img.height * nOut);
    for (std::size_t p = 0; p < static_cast<std::size_t>(img.width) * img.height; ++p)
        for (int c = 0; c < nOut; ++c) {
            const float v = img.data[p * nIn + c];
            pixels.data[p * nOut + c] = ldr ? srgbEncode(v) : v;
        }
    if (ext == ".png") return encodePng(pixels);  // without loading OpenImageIO (io/png_encoder)
    return oiioCodec().encode(path, pixels, ldr);
}

void writeImage(const std::string& path, const ImageChannels& img) {
    writeFileAtomically(path, encodeImage(path, img));
}

namespace {
// Reads only regular files of bounded size whose pixel count fits the budget.
ImageChannels readImage(const std::string& path, bool& eightBitFile) {
    checkInputFile(path, input::kTextureFileBytes);
    auto check = [&](int width, int height, int depth, int channels) {
        // A volume (depth > 1) would be read past a 2D buffer: refused, as is more data than four
        // floats for each of the largest texture's pixels (64 channels of it would be 69 GB).
        if (depth > 1)
            throw std::runtime_error("image '" + path + "' is a volume (" + std::to_string(depth) +
                                     " slices deep): a texture or pixel data is one 2D image");
        const double values = double(width) * height * channels, most = 4 * input::kTexturePixels.max;
        if (width > 0 && height > 0 && channels > 0 && values > most)
            throw std::runtime_error("image '" + path + "' holds " + input::significantDigits(values) + " values (" +
                                     std::to_string(channels) + " channels), more than " +
                                     input::significantDigits(most) + " (4 GB of floats)");
        const double pixels = double(width) * height * std::max(1, depth);
        if (width <= 0 || height <= 0 || channels <= 0 || channels > 64 || !input::kTexturePixels.contains(pixels))
            throw std::runtime_error("image '" + path + "' is " + std::to_string(width) + " x " +
                                     std::to_string(height) + " with " + std::to_string(channels) +
                                     " channels: " + input::kTexturePixels.problem(pixels));
    };
    return oiioCodec().read(path, check, eightBitFile);
}
}  // namespace

ImageChannels readImageRgb(const std::string& path) {
    bool eightBitFile = false;
    const ImageChannels raw = readImage(path, eightBitFile);
    const int n = static_cast<int>(raw.names.size());
    ImageChannels img;
    img.width = raw.width;
    img.height = raw.height;
    img.names = {"R", "G", "B"};
    img.data.resize(static_cast<std::size_t>(raw.width) * raw.height * 3);
    for (std::size_t p = 0; p < static_cast<std::size_t>(raw.width) * raw.height; ++p)
        for (int c = 0; c < 3; ++c) {
            const float v = raw.data[p * n + std::min(c, n - 1)];
            img.data[p * 3 + c] = eightBitFile ? srgbDecode(v) : v;
        }
    return img;
}

ImageChannels readImageChannels(const std::string& path) {
    bool eightBitFile = false;
    return readImage(path, eightBitFile);
}

void drawLabels(ImageChannels& image, const std::vector<ImageLabel>& labels, int fontPixels) {
    if (labels.empty()) return;
    if (image.names.size() != 3) throw std::invalid_argument("labels are drawn into RGB images");
    const float shadow[3] = {0.0f, 0.0f, 0.0f}, white[3] = {1.0f, 1.0f, 1.0f};
    for (const ImageLabel& l : labels)
        for (const auto& [dx, colour] : {std::pair{1, shadow}, std::pair{0, white}})
            oiioCodec().drawText(image, l.x + dx, l.y + dx, l.text, fontPixels, colour);
}

}  // namespace lc::io
