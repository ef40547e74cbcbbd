#include "tests/structure/source_includes.hpp"

#include <algorithm>
#include <fstream>
#include <regex>

namespace lathesim::structure {
namespace fs = std::filesystem;

std::vector<std::string> sourceFiles(const fs::path& root) {
  std::vector<std::string> files;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path& path = it->path();
    if (it->is_directory()) {
      const std::string name = path.filename().string();
      if (name.front() == '.' || name == "node_modules" || fs::exists(path / "CMakeCache.txt")) {
        it.disable_recursion_pending();
      }
      continue;
    }
    const std::string extension = path.extension().string();
    if (extension == ".cpp" || extension == ".hpp" || extension == ".h" || extension == ".cc") {
      files.push_back(path.lexically_relative(root).generic_string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<Include> readIncludes(const fs::path& root, const std::vector<std::string>& files) {
  static const std::regex includeLine(R"(^\s*#\s*include\s*"([^"]+)\")");
  std::vector<Include> includes;
  for (const std::string& file : files) {
    std::ifstream in(root / file);
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
      ++lineNumber;
      std::smatch match;
      if (!std::regex_search(line, match, includeLine)) continue;
      const fs::path named(match[1].str());
      for (const fs::path& candidate : {(fs::path(file).parent_path() / named).lexically_normal(), named.lexically_normal()}) {
        if (fs::is_regular_file(root / candidate)) {
          includes.push_back({file, lineNumber, candidate.generic_string()});
          break;
        }
      }
    }
  }
  return includes;
}

}  // namespace lathesim::structure
