#include "interp/output/spool_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace lathesim::interp {

SpoolFile::SpoolFile(std::string_view what) : what_(what), file_(std::tmpfile(), &std::fclose) {
  if (!file_) throw std::runtime_error("cannot make a temporary file for " + what_ + ": " + std::strerror(errno));
}

void SpoolFile::append(const void* bytes, std::size_t size) { std::fwrite(bytes, 1, size, file_.get()); }

void SpoolFile::readBack(std::size_t chunkBytes, const std::function<void(std::string_view chunk)>& take) const {
  Reader reader(*this);
  std::vector<char> buffer(chunkBytes);
  for (std::size_t got; (got = reader.read(buffer.data(), buffer.size())) > 0;) take({buffer.data(), got});
}

SpoolFile::Reader::Reader(const SpoolFile& spool) : spool_(spool) {
  std::FILE* file = spool.file_.get();
  if (std::fflush(file) != 0 || std::ferror(file))
    throw std::runtime_error("cannot write " + spool.what_ + " to a temporary file: " + std::strerror(errno));
  end_ = std::ftell(file);
  std::rewind(file);
}

SpoolFile::Reader::~Reader() { std::fseek(spool_.file_.get(), end_, SEEK_SET); }  // where the next append goes

std::size_t SpoolFile::Reader::read(void* bytes, std::size_t size) {
  std::FILE* file = spool_.file_.get();
  const std::size_t got = std::fread(bytes, 1, size, file);
  if (got < size && std::ferror(file)) throw std::runtime_error("cannot read back " + spool_.what_ + "'s temporary file");
  return got;
}

}  // namespace lathesim::interp
