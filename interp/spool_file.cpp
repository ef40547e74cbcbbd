#include "interp/spool_file.hpp"

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
  std::FILE* file = file_.get();
  if (std::fflush(file) != 0 || std::ferror(file))
    throw std::runtime_error("cannot write " + what_ + " to a temporary file: " + std::strerror(errno));
  const long end = std::ftell(file);
  std::rewind(file);
  std::vector<char> buffer(chunkBytes);
  for (std::size_t got; (got = std::fread(buffer.data(), 1, buffer.size(), file)) > 0;) take({buffer.data(), got});
  if (std::ferror(file)) throw std::runtime_error("cannot read back " + what_ + "'s temporary file");
  std::fseek(file, end, SEEK_SET);  // where the next append goes
}

}  // namespace lathesim::interp
