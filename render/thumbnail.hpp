#pragma once
// A small copy of a rendered picture, for overviews that show many parts at once.

#include <string>

#include "render/rgb_image.hpp"

namespace lathesim::render {

/// `picture` shrunk by a whole factor to about `widthPx` wide, encoded as a PNG: each
/// thumbnail pixel the mean of a block (1600 × 1200 for 240: 7 × 7 blocks, 228 × 171; what
/// is left over at the right and top is dropped). Made from the pixels in memory, not from
/// the picture's PNG read back and decoded (50 ms of a batch job's overhead). Needs no
/// display. Throws std::runtime_error if the picture is empty or cannot be encoded.
std::string thumbnailPng(const RgbImage& picture, int widthPx);

}  // namespace lathesim::render
