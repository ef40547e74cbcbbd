#pragma once
// Which control's G-code the program is written for. The interpreter works in one set of
// meanings — Fanuc/GSK system A — and each dialect is a table that says which written code
// means which system-A code (see gcode_table.cpp), plus absolute/incremental distance
// modes, which system A expresses with X/U and Z/W alone.

#include <array>
#include <optional>
#include <string_view>

namespace lathesim::interp {

enum class Dialect {
  FanucA,  // "fanuc-a": Fanuc/GSK system A (default): G90/G92/G94 cycles, G98/G99 feed modes
  FanucB,  // "fanuc-b": Fanuc system B: G77/G78/G79 cycles, G90/G91 abs/inc, G94/G95 feed modes
  Hnc,     // "hnc": Huazhong HNC lathe: G80/G81/G82 cycles, G90/G91 abs/inc, G94/G95 feed modes
  Haas,    // "haas": Haas lathes: system A codes, with the compound cycles in Haas's one-block
           // forms (G71/G72 P Q D I K U W, G76 X Z K D F A P)
};

inline constexpr std::array kDialects{Dialect::FanucA, Dialect::FanucB, Dialect::Hnc, Dialect::Haas};

std::optional<Dialect> dialectNamed(std::string_view name);
std::string_view dialectName(Dialect dialect);

}  // namespace lathesim::interp
