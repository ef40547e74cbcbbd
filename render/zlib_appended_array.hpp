#pragma once
// One data array of a VTK XML file's appended data, compressed as vtkXMLWriter compresses it
// by default (vtkZLibDataCompressor at its default level, blocks of 32 KiB, header_type
// UInt64): the values are added one at a time and each block is compressed as soon as it is
// full, into a temporary file, so that an array of any length holds about two blocks in
// memory. Once finished, its size in the file is known (what the XML's `offset` attributes
// need before any data is written) and it is copied out: the header
//   [number of blocks, 32768, uncompressed size of the last block (0: a whole one),
//    compressed size of each block…]
// then the compressed blocks.

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <vtkSmartPointer.h>

#include "interp/output/spool_file.hpp"

class vtkDataCompressor;

namespace lathesim::render {

class ZLibAppendedArray {
 public:
  /// vtkXMLWriter's default BlockSize: the uncompressed bytes compressed together.
  static constexpr std::size_t kBlockBytes = 32768;

  /// `what` names the array in errors ("the toolpath's points"). Throws std::runtime_error
  /// when no temporary file can be made.
  explicit ZLibAppendedArray(std::string_view what);
  ~ZLibAppendedArray();
  ZLibAppendedArray(const ZLibAppendedArray&) = delete;
  ZLibAppendedArray& operator=(const ZLibAppendedArray&) = delete;

  /// Appends one value, in the machine's byte order.
  template <typename T>
  void add(T value) {
    static_assert(std::is_arithmetic_v<T>, "the arrays hold numbers");
    add(&value, sizeof value);
  }
  void add(const void* bytes, std::size_t size);

  /// Compresses the last, shorter block if there is one; nothing may be added after.
  void finish();
  /// The array's bytes in the appended data, header and compressed blocks. After finish().
  std::uint64_t appendedBytes() const;
  /// Writes the header and the compressed blocks to `out`. After finish(). Throws
  /// std::runtime_error if a temporary file failed (a full disk).
  void copyTo(std::ostream& out) const;

 private:
  void compressBlock();

  std::string what_;
  vtkSmartPointer<vtkDataCompressor> compressor_;
  std::vector<unsigned char> block_;       // the uncompressed block being filled
  std::vector<unsigned char> compressed_;  // room for one block compressed
  interp::SpoolFile blocks_;               // the compressed blocks, one after the other
  interp::SpoolFile blockSizes_;           // each block's compressed size, a UInt64 each
  std::uint64_t uncompressedBytes_ = 0, compressedBytes_ = 0, blockCount_ = 0;
};

}  // namespace lathesim::render
