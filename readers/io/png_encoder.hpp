// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// PNG files through libpng directly, the one format the command line writes most: a small
// render's PNG then needs no OpenImageIO, whose module takes 0.25 s to load (260 libraries;
// bench/bench_startup). Every other format goes through io/oiio_codec.
#include "readers/io/image_io.hpp"

#include <string>

namespace lc::io {

// 8-bit RGB PNG bytes of the first three channels of `pixels`, values in [0, 1] already
// sRGB-encoded (rounded to the nearest level, clamped), with an sRGB chunk and each attribute
// as a tEXt chunk (PNG keywords: 1-79 Latin-1 characters). Throws std::runtime_error.
std::string encodePng(const ImageChannels& pixels);

}  // namespace lc::io
