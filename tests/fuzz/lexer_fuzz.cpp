// libFuzzer harness: program text → blocks (BlockReader) → words (tokenize) → blocks sorted
// into codes (parseBlock) in every dialect, and the whole program read (readProgram), with
// every message formatted as the terminal would show it, and every N and O label found again
// by the searches that read the text apart (a label not found traps). Errors are answers; a
// crash, a hang, a leak or undefined behaviour is a finding.

#include <cstddef>
#include <cstdint>

#include "interp/control/dialect.hpp"
#include "interp/base/diagnostic.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/text/lexer.hpp"
#include "interp/text/program.hpp"

using namespace lathesim::interp;

namespace {

void show(const Error& error, std::string_view text) {
  format(Diagnostic{Severity::Error, "fuzz.nc", error.line, error.column, error.message, lineOf(text, error.line)});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  BlockReader reader(text);
  for (;;) {
    auto next = reader.next();
    if (!next.ok()) {
      show(next.error(), text);
      break;
    }
    if (!next.value()) break;
    const RawBlock& block = *next.value();
    auto words = tokenize(block);
    if (!words.ok()) {
      show(words.error(), text);
      continue;
    }
    for (Dialect dialect : kDialects) {
      auto parsed = parseBlock(words.value(), block.line, block.column, dialect);
      if (!parsed.ok()) show(parsed.error(), text);
    }
  }
  for (const ReadNote& note : reader.notes()) show(Error{note.line, note.column, note.message}, text);
  const Program program = readProgram(text, /*blockDelete=*/true, Dialect::FanucA);
  for (std::size_t ordinal = 0; ordinal < program.blockCount(); ++ordinal) {
    const ProgramBlock block = program.block(ordinal);
    if (const Error* error = program.errorOf(block)) show(*error, text);
    program.plainWords(block);  // each block of plain words read again from where it starts
    // A label the block bears is found by the searches, which read the text apart from it.
    if (block.sequenceNumber && !block.skipped) {
      const SequenceBlocks found = program.findSequence(*block.sequenceNumber, ordinal);
      if (found.count == 0 || found.first > ordinal) __builtin_trap();
    }
    if (block.programNumber) {
      const auto start = program.programStart(*block.programNumber);
      if (!start || *start > ordinal) __builtin_trap();
    }
  }
  return 0;
}
