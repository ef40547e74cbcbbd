#include "render/zlib_appended_array.hpp"

#include <algorithm>
#include <stdexcept>

#include <vtkZLibDataCompressor.h>

namespace lathesim::render {

ZLibAppendedArray::ZLibAppendedArray(std::string_view what)
    : what_(what),
      compressor_(vtkSmartPointer<vtkZLibDataCompressor>::New()),  // its default level, as vtkXMLWriter's
      compressed_(compressor_->GetMaximumCompressionSpace(kBlockBytes)),
      blocks_(what_),
      blockSizes_(what_ + "'s block sizes") {
  block_.reserve(kBlockBytes);
}

ZLibAppendedArray::~ZLibAppendedArray() = default;

void ZLibAppendedArray::add(const void* bytes, std::size_t size) {
  const auto* from = static_cast<const unsigned char*>(bytes);
  while (size > 0) {
    const std::size_t taken = std::min(size, kBlockBytes - block_.size());
    block_.insert(block_.end(), from, from + taken);
    from += taken, size -= taken;
    if (block_.size() == kBlockBytes) compressBlock();
  }
}

void ZLibAppendedArray::finish() {
  if (!block_.empty()) compressBlock();
}

void ZLibAppendedArray::compressBlock() {
  const std::uint64_t size = compressor_->Compress(block_.data(), block_.size(), compressed_.data(), compressed_.size());
  if (size == 0) throw std::runtime_error("zlib could not compress " + what_);
  blocks_.append(compressed_.data(), size);
  blockSizes_.append(&size, sizeof size);
  uncompressedBytes_ += block_.size(), compressedBytes_ += size, ++blockCount_;
  block_.clear();
}

std::uint64_t ZLibAppendedArray::appendedBytes() const { return (3 + blockCount_) * sizeof(std::uint64_t) + compressedBytes_; }

void ZLibAppendedArray::copyTo(std::ostream& out) const {
  const std::uint64_t header[3] = {blockCount_, kBlockBytes, uncompressedBytes_ % kBlockBytes};
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  const auto copy = [&out](std::string_view chunk) { out.write(chunk.data(), static_cast<std::streamsize>(chunk.size())); };
  blockSizes_.readBack(kBlockBytes, copy);
  blocks_.readBack(kBlockBytes, copy);
}

}  // namespace lathesim::render
