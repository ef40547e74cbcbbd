#include "interp/text/program_library.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <system_error>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

std::string lowerCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::vector<std::string> programFileNames(int number) {
  std::vector<std::string> numbers{fmt::format("{:04}", number)};
  if (numbers.front() != std::to_string(number)) numbers.push_back(std::to_string(number));
  std::vector<std::string> names;
  for (const std::string prefix : {"O", ""})
    for (const std::string& digits : numbers)
      for (const char* extension : {"", ".nc", ".tap", ".txt"}) names.push_back(prefix + digits + extension);
  return names;
}

bool isProgramFileName(std::string_view fileName) {
  const std::string name = lowerCase(std::string(fileName));
  std::string digits = name.substr(name.starts_with('o') ? 1 : 0);
  digits = digits.substr(0, digits.find('.'));
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
  for (const std::string& candidate : programFileNames(std::stoi(digits)))
    if (lowerCase(candidate) == name) return true;
  return false;
}

std::optional<ProgramFile> findProgramFile(int number, const std::vector<std::filesystem::path>& directories) {
  const std::vector<std::string> names = programFileNames(number);
  for (const auto& directory : directories) {
    std::error_code ec;
    std::map<std::string, std::filesystem::path> files;  // lower-case name → file
    for (const auto& entry : std::filesystem::directory_iterator(directory, ec)) {
      if (entry.is_regular_file(ec)) files.emplace(lowerCase(entry.path().filename().string()), entry.path());
    }
    for (const std::string& name : names) {
      const auto found = files.find(lowerCase(name));
      if (found == files.end()) continue;
      try {
        return ProgramFile{found->second, FileText::read(found->second)};
      } catch (const std::system_error&) {  // unreadable: the next name may be
      }
    }
  }
  return std::nullopt;
}

}  // namespace lathesim::interp
