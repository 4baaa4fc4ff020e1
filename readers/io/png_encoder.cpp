// SPDX-License-Identifier: BSD-3-Clause
#include "readers/io/png_encoder.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace lc::io {

namespace {

void appendToString(png_structp png, png_bytep data, png_size_t length) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}

void flushNothing(png_structp) {}

// libpng reports errors by longjmp back to writePng's setjmp (its documented way), after keeping
// the message here.
void keepPngError(png_structp png, png_const_charp message) {
    *static_cast<std::string*>(png_get_error_ptr(png)) = message;
    png_longjmp(png, 1);
}

void ignoreWarning(png_structp, png_const_charp) {}

// libpng's calls alone, between its setjmp and any longjmp: no C++ object lives in this frame,
// so an error's longjmp skips no destructor. False on an error (its message in `error`).
__attribute__((noinline)) bool writePng(int width, int height, png_bytep* rows, png_textp texts, int textCount,
                                        std::string* bytes, std::string* error) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, keepPngError, ignoreWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, bytes, appendToString, flushNothing);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (textCount > 0) png_set_text(png, info, texts, textCount);
    png_set_rows(png, info, rows);
    png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::string encodePng(const ImageChannels& pixels) {
    const std::size_t channels = pixels.names.size();
    if (pixels.width <= 0 || pixels.height <= 0 || channels < 3 ||
        pixels.data.size() != channels * static_cast<std::size_t>(pixels.width) * pixels.height)
        throw std::invalid_argument("encodePng: image size and channel data disagree");
    std::vector<png_byte> rows(3 * static_cast<std::size_t>(pixels.width) * pixels.height);
    for (std::size_t p = 0; p < rows.size() / 3; ++p)
        for (std::size_t c = 0; c < 3; ++c)
            rows[3 * p + c] =
                static_cast<png_byte>(std::lround(std::clamp(pixels.data[p * channels + c], 0.0f, 1.0f) * 255.0f));
    std::vector<png_bytep> rowPointers(static_cast<std::size_t>(pixels.height));
    for (std::size_t y = 0; y < rowPointers.size(); ++y) rowPointers[y] = rows.data() + 3 * y * pixels.width;

    std::string bytes, error;
    std::vector<png_text> texts(pixels.attributes.size());
    for (std::size_t k = 0; k < texts.size(); ++k) {
        texts[k].compression = PNG_TEXT_COMPRESSION_NONE;
        texts[k].key = const_cast<png_charp>(pixels.attributes[k].first.c_str());
        texts[k].text = const_cast<png_charp>(pixels.attributes[k].second.c_str());
    }
    if (!writePng(pixels.width, pixels.height, rowPointers.data(), texts.data(), static_cast<int>(texts.size()), &bytes,
                  &error))
        throw std::runtime_error("cannot encode PNG: " + (error.empty() ? std::string("out of memory") : error));
    return bytes;
}

}  // namespace lc::io
