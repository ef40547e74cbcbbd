// Writes docs/codes.md from the interpreter's tables:
//   build/tests/docs/write_code_reference docs/codes.md
#include <fstream>
#include <iostream>

#include "tests/docs/code_reference.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_code_reference FILE (e.g. " << lathesim::docs::kRegenerateCodeReference << ")\n";
    return 2;
  }
  std::ofstream out(argv[1], std::ios::binary);
  out << lathesim::docs::codeReference();
  out.close();
  if (!out) {
    std::cerr << "write_code_reference: cannot write " << argv[1] << '\n';
    return 1;
  }
  return 0;
}
