#pragma once
// Subprograms kept in the control rather than in the program's file: `M98 P7615` names
// program O7615, which a shop keeps as a file of its own. lathesim looks for it in the
// directories it is given, in order (the command's --programs directories, then the
// program's own directory), and in each for these names, in this order, with letters in any
// case:
//   O7615  O7615.nc  O7615.tap  O7615.txt   then without the O:  7615  7615.nc …
// each also with the number zero-padded to four digits when it is shorter (P15: O0015 before
// O15). The first file found is the program.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interp/text/file_text.hpp"

namespace lathesim::interp {

struct ProgramFile {
  std::filesystem::path path;
  FileText text;
};

/// The file names tried for program `number`, in order.
std::vector<std::string> programFileNames(int number);

/// Whether M98 could read a program from a file of this name (one of programFileNames(n)
/// for some n, in any case): a batch counts such files beside a program among its inputs.
bool isProgramFileName(std::string_view fileName);

/// The first file holding program `number` in `directories` that can be read, or nullopt.
std::optional<ProgramFile> findProgramFile(int number, const std::vector<std::filesystem::path>& directories);

}  // namespace lathesim::interp
