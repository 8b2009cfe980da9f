// PNG encoding of an RgbImage (libpng's simplified API). Only png_file.cpp includes libpng.
#pragma once
#include <string>

#include "rgb_image.hpp"

namespace dbs {

/// Writes `image` as an 8-bit RGB PNG; Error(Io) naming the file and libpng's message.
void write_png(const std::string& path, const RgbImage& image);
/// Reads any PNG, converted to 8-bit RGB (alpha composited on white); Error(Io) when the
/// file cannot be opened, Error(Parse) when it is not a valid PNG.
RgbImage read_png(const std::string& path);

}  // namespace dbs
