// SPDX-License-Identifier: BSD-3-Clause
// The OpenImageIO calls of readers/io/image_io, built as a module that readers/io/oiio_codec.cpp
// loads on first use (readers/io/oiio_codec.hpp says why).
#include "readers/io/oiio_codec.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace {

using lc::io::ImageChannels;

std::string encode(const std::string& path, const ImageChannels& pixels, bool eightBit) {
    const int channels = static_cast<int>(pixels.names.size());
    OIIO::ImageSpec spec(pixels.width, pixels.height, channels,
                         eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.channelnames = pixels.names;
    for (const auto& [name, value] : pixels.attributes) spec.attribute(name, value);
    // Encoded in memory (OIIO's IOProxy): the file system sees only the finished bytes.
    auto out = OIIO::ImageOutput::create(path);
    if (!out)
        throw std::runtime_error("cannot write image '" + path + "': unknown format (hint: use .png, .exr or .tif)");
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    OIIO::Filesystem::IOProxy* proxy = &memory;
    spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data.data()) || !out->close())
        throw std::runtime_error("cannot encode image '" + path + "': " + out->geterror());
    return std::string(bytes.begin(), bytes.end());
}

ImageChannels read(const std::string& path, const std::function<void(int, int, int, int)>& check, bool& eightBitFile) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    check(spec.width, spec.height, spec.depth, spec.nchannels);
    ImageChannels pixels;
    pixels.width = spec.width;
    pixels.height = spec.height;
    pixels.names = spec.channelnames;
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        if (p.name().string().rfind("lightcone:", 0) == 0 && p.type() == OIIO::TypeDesc::STRING)
            pixels.attributes.emplace_back(p.name().string(), p.get_string());
    eightBitFile = spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
    pixels.data.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data.data()))
        throw std::runtime_error("cannot read pixels of '" + path + "': " + in->geterror());
    in->close();
    return pixels;
}

void drawText(ImageChannels& rgb, int x, int y, const std::string& text, int fontPixels, const float colour[3]) {
    OIIO::ImageSpec spec(rgb.width, rgb.height, 3, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf buf(spec, rgb.data.data());  // wraps the pixels: drawn in place
    if (!OIIO::ImageBufAlgo::render_text(buf, x, y, text, fontPixels, "DejaVuSans", colour))
        throw std::runtime_error("cannot draw the label '" + text + "': " + buf.geterror() +
                                 " (Debian's fonts-dejavu-core has the font)");
}

const lc::io::OiioCodec kCodec{&encode, &read, &drawText, OIIO_VERSION_STRING};

}  // namespace

extern "C" __attribute__((visibility("default"))) const lc::io::OiioCodec* lightconeOiioCodec() { return &kCodec; }
