#pragma once
// --stock on the command line: the bar as a few letters, parts joined by 'x':
//   D40xL80        Φ40, 80 long, its face at Z0
//   D40xL80xZ1     the same with the face at Z1
//   D60xd40xL80    a tube: Φ60 outside, a Φ40 bore
// D (diameter) and L (length) are required, d (bore) and Z optional; numbers are mm,
// positive (Z any), the bore smaller than the diameter.

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "sim/stock_spec.hpp"

namespace lathesim::setup {

/// The bar `text` describes, or the message saying what is wrong with it.
std::variant<sim::StockSpec, std::string> parseStockOption(std::string_view text);

/// Whether `text` (a valid --stock) states the face (a Z part); else the face is at Z0, assumed.
bool stockOptionStatesFace(std::string_view text);

}  // namespace lathesim::setup
