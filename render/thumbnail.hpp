#pragma once
// A small copy of a rendered picture, for overviews that show many parts at once.

#include <filesystem>

namespace lathesim::render {

/// Reads the PNG `source` and writes it shrunk by a whole factor to about `widthPx` wide
/// (1600 → 229 for 240: each thumbnail pixel the mean of a 7×7 block), as the PNG `target`.
/// Needs no display. Throws std::runtime_error if the source is not a readable PNG or the
/// target cannot be written.
void writeThumbnailPng(const std::filesystem::path& source, const std::filesystem::path& target, int widthPx);

}  // namespace lathesim::render
