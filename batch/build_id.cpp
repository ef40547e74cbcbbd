#include "batch/build_id.hpp"

#include <elf.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <vector>

#include "batch/content_hash.hpp"

namespace lathesim::batch {
namespace {

std::string hexOf(const unsigned char* bytes, std::size_t count) {
  std::string text;
  char digits[3];
  for (std::size_t i = 0; i < count; ++i) {
    std::snprintf(digits, sizeof digits, "%02x", bytes[i]);
    text += digits;
  }
  return text;
}

/// The NT_GNU_BUILD_ID note among the notes in `notes`, as hex, or nullopt.
std::optional<std::string> buildIdNote(const std::vector<unsigned char>& notes) {
  const auto align4 = [](std::size_t n) { return (n + 3) & ~std::size_t{3}; };
  std::size_t at = 0;
  while (at + sizeof(Elf64_Nhdr) <= notes.size()) {
    Elf64_Nhdr header;
    std::memcpy(&header, notes.data() + at, sizeof header);
    const std::size_t name = at + sizeof header;
    const std::size_t description = name + align4(header.n_namesz);
    const std::size_t next = description + align4(header.n_descsz);
    if (next > notes.size()) return std::nullopt;
    if (header.n_type == NT_GNU_BUILD_ID && header.n_namesz == 4 && std::memcmp(notes.data() + name, "GNU", 4) == 0)
      return hexOf(notes.data() + description, header.n_descsz);
    at = next;
  }
  return std::nullopt;
}

/// The build ID from a 64-bit little-endian ELF file's PT_NOTE segments, or nullopt.
std::optional<std::string> elfBuildId(std::ifstream& in) {
  Elf64_Ehdr elf;
  if (!in.read(reinterpret_cast<char*>(&elf), sizeof elf)) return std::nullopt;
  if (std::memcmp(elf.e_ident, ELFMAG, SELFMAG) != 0 || elf.e_ident[EI_CLASS] != ELFCLASS64 ||
      elf.e_phentsize != sizeof(Elf64_Phdr))
    return std::nullopt;
  for (int i = 0; i < elf.e_phnum; ++i) {
    Elf64_Phdr segment;
    in.seekg(static_cast<std::streamoff>(elf.e_phoff + i * sizeof segment));
    if (!in.read(reinterpret_cast<char*>(&segment), sizeof segment)) return std::nullopt;
    if (segment.p_type != PT_NOTE || segment.p_filesz > (1u << 20)) continue;
    std::vector<unsigned char> notes(segment.p_filesz);
    in.seekg(static_cast<std::streamoff>(segment.p_offset));
    if (!in.read(reinterpret_cast<char*>(notes.data()), static_cast<std::streamsize>(notes.size()))) return std::nullopt;
    if (auto id = buildIdNote(notes)) return id;
  }
  return std::nullopt;
}

}  // namespace

std::string buildIdOf(const std::filesystem::path& executable) {
  std::ifstream in(executable, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + executable.string());
  if (auto id = elfBuildId(in)) return *id;
  if (auto hash = fileHash(executable)) return "file-" + *hash;
  throw std::runtime_error("cannot read " + executable.string());
}

}  // namespace lathesim::batch
