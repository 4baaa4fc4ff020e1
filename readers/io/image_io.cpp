#include "readers/io/image_io.hpp"

#include "core/colour/srgb.hpp"
#include "readers/io/atomic_output.hpp"
#include "readers/io/file_extension.hpp"
#include "readers/io/input_file.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

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

    OIIO::ImageSpec spec(img.width, img.height, nOut, ldr ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.channelnames.assign(img.names.begin(), img.names.begin() + nOut);
    std::vector<float> pixels(static_cast<std::size_t>(img.width) * img.height * nOut);
    for (std::size_t p = 0; p < static_cast<std::size_t>(img.width) * img.height; ++p)
        for (int c = 0; c < nOut; ++c) {
            const float v = img.data[p * nIn + c];
            pixels[p * nOut + c] = ldr ? srgbEncode(v) : v;
        }

    // Encoded in memory (OIIO's IOProxy): the file system sees only the finished bytes.
    auto out = OIIO::ImageOutput::create(path);
    if (!out)
        throw std::runtime_error("cannot write image '" + path + "': unknown format (hint: use .png, .exr or .tif)");
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    OIIO::Filesystem::IOProxy* proxy = &memory;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close())
        throw std::runtime_error("cannot encode image '" + path + "': " + out->geterror());
    return std::string(bytes.begin(), bytes.end());
}

void writeImage(const std::string& path, const ImageChannels& img) {
    writeFileAtomically(path, encodeImage(path, img));
}

namespace {
// Opens only regular files of bounded size whose pixel count fits the budget.
std::unique_ptr<OIIO::ImageInput> openImage(const std::string& path) {
    checkInputFile(path, input::kTextureFileBytes);
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const double pixels = double(spec.width) * spec.height * std::max(1, spec.depth);
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.nchannels > 64 ||
        !input::kTexturePixels.contains(pixels))
        throw std::runtime_error("image '" + path + "' is " + std::to_string(spec.width) + " x " +
                                 std::to_string(spec.height) + " with " + std::to_string(spec.nchannels) +
                                 " channels: " + input::kTexturePixels.problem(pixels));
    return in;
}
}  // namespace

ImageChannels readImageRgb(const std::string& path) {
    auto in = openImage(path);
    const OIIO::ImageSpec& spec = in->spec();
    const int n = spec.nchannels;
    std::vector<float> raw(static_cast<std::size_t>(spec.width) * spec.height * n);
    if (!in->read_image(0, 0, 0, n, OIIO::TypeDesc::FLOAT, raw.data()))
        throw std::runtime_error("cannot read pixels of '" + path + "': " + in->geterror());
    const bool encoded =
        spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
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
    auto in = openImage(path);
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

void drawLabels(ImageChannels& image, const std::vector<ImageLabel>& labels, int fontPixels) {
    if (labels.empty()) return;
    if (image.names.size() != 3) throw std::invalid_argument("labels are drawn into RGB images");
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buf(spec, image.data.data());  // wraps the pixels: drawn in place
    const float shadow[3] = {0.0f, 0.0f, 0.0f}, white[3] = {1.0f, 1.0f, 1.0f};
    for (const ImageLabel& l : labels)
        for (const auto& [dx, colour] : {std::pair{1, shadow}, std::pair{0, white}})
            if (!OIIO::ImageBufAlgo::render_text(buf, l.x + dx, l.y + dx, l.text, fontPixels, "DejaVuSans", colour))
                throw std::runtime_error("cannot draw the label '" + l.text + "': " + buf.geterror() +
                                         " (Debian's fonts-dejavu-core has the font)");
}

}  // namespace lc::io
