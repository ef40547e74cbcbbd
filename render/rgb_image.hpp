#pragma once
// A rendered picture's pixels held in memory: encoded as a PNG for its file, and shrunk into
// a thumbnail (render/thumbnail.hpp) from the same pixels rather than from the PNG read back.

#include <string>
#include <vector>

namespace lathesim::render {

/// 8-bit RGB pixels, widthPx × heightPx × 3 bytes, row after row from the bottom of the
/// picture (as VTK reads a window back).
struct RgbImage {
  int widthPx = 0, heightPx = 0;
  std::vector<unsigned char> rgb;
};

/// `image` encoded as a PNG. Throws std::runtime_error if it cannot be encoded.
std::string encodePng(const RgbImage& image);

}  // namespace lathesim::render
