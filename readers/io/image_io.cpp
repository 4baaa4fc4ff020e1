#include "readers/io/image_io.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace lc::io {
namespace fs = std::filesystem;

float srgbEncode(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
float srgbDecode(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

namespace {
bool isLowDynamicRange(const std::string& ext) {
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".ppm";
}
}  // namespace

void writeImage(const std::string& path, const ImageChannels& img) {
    const std::string ext = [&] {
        std::string e = fs::path(path).extension().string();
        std::transform(e.begin(), e.end(), e.begin(), ::tolower);
        return e;
    }();
    const bool ldr = isLowDynamicRange(ext);
    const std::size_t nIn = img.names.size();
    const int nOut = ldr ? 3 : static_cast<int>(nIn);
    if (img.width <= 0 || img.height <= 0 || nIn < 3 || img.data.size() != nIn * img.width * img.height)
        throw std::invalid_argument("writeImage(" + path + "): image size and channel data disagree");

    OIIO::ImageSpec spec(img.width, img.height, nOut, ldr ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.channelnames.assign(img.names.begin(), img.names.begin() + nOut);
    std::vector<float> pixels(static_cast<std::size_t>(img.width) * img.height * nOut);
    for (std::size_t p = 0; p < static_cast<std::size_t>(img.width) * img.height; ++p)
        for (int c = 0; c < nOut; ++c) {
            const float v = img.data[p * nIn + c];
            pixels[p * nOut + c] = ldr ? srgbEncode(v) : v;
        }

    // Same directory so the final rename is atomic; the extension tells OIIO the format.
    const fs::path target(path);
    const fs::path tmp = target.parent_path() / (".tmp-" + std::to_string(::getpid()) + "-" + target.filename().string());
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) throw std::runtime_error("cannot write image '" + path + "': " + OIIO::geterror() +
                                       " (hint: use .png, .exr or .tif)");
    if (!out->open(tmp.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close()) {
        const std::string err = out->geterror();
        std::error_code ec;
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write image '" + path + "': " + err + " (hint: is the folder writable?)");
    }
    fs::rename(tmp, target);
}

ImageChannels readImageRgb(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const int n = spec.nchannels;
    std::vector<float> raw(static_cast<std::size_t>(spec.width) * spec.height * n);
    if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::FLOAT, raw.data()))
        throw std::runtime_error("cannot read pixels of '" + path + "': " + in->geterror());
    const bool encoded = spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
    ImageChannels img;
    img.width = spec.width;
    img.height = spec.height;
    img.names = {"R", "G", "B"};
    img.data.resize(static_cast<std::size_t>(spec.width) * spec.height * 3);
    for (std::size_t p = 0; p < static_cast<std::size_t>(spec.width) * spec.height; ++p)
        for (int c = 0; c < 3; ++c) {
            const float v = raw[p * n + std::min(c, n - 1)];
            img.data[p * 3 + c] = encoded ? srgbDecode(v) : v;
        }
    in->close();
    return img;
}

ImageChannels readImageChannels(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    ImageChannels img;
    img.width = spec.width;
    img.height = spec.height;
    img.names = spec.channelnames;
    img.data.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.data.data()))
        throw std::runtime_error("cannot read pixels of '" + path + "': " + in->geterror());
    in->close();
    return img;
}

}  // namespace lc::io
