#pragma once
// Whole files read and written by tests: the bytes as they are, no newline translation.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace lathesim::test {

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace lathesim::test
