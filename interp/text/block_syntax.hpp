#pragma once
// The tokens of a block → a MacroBlock (text/statement.hpp), for blocks holding anything of
// Custom Macro B: a statement, an expression in an address, or a macro call (G65). A block
// of plain words is sorted by text/block_parser.hpp instead.

#include <vector>

#include "interp/text/statement.hpp"
#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp::macro {

/// Whether `tokens` need the macro reader: any token but a plain word, or the word G65.
bool needsMacroReader(const std::vector<Token>& tokens);

/// Reads a block's tokens. Fails, located, on a statement or expression that is malformed, a
/// statement sharing its block with NC words, or an N/O number given by a variable.
Result<MacroBlock> readMacroBlock(const std::vector<Token>& tokens, const RawBlock& block);

}  // namespace lathesim::interp::macro
