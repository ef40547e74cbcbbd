#include "setup/tool_facts.hpp"

#include <fmt/format.h>

namespace lathesim::setup {

std::string insertShapeName(const IsoInsert& insert) {
  switch (insert.shape) {
    case 'R': return "R (round)";
    case 'S': return "S (square)";
    case 'T': return "T (triangle)";
    case 'W': return "W (80° trigon)";
    case 'H': return "H (hexagon)";
    case 'O': return "O (octagon)";
    case 'P': return "P (pentagon)";
    default: return fmt::format("{} ({:g}° rhombic)", insert.shape, insert.noseAngleDeg);
  }
}

ToolFacts turningFacts(const IsoInsert& insert, const IsoHolder& holder) {
  ToolFacts facts;
  facts.kind = "turning";
  facts.insert = insert.code;
  facts.insertShape = insertShapeName(insert);
  facts.cuttingEdgeLengthMm = insert.edgeLengthMm;
  if (!insert.round()) facts.insertAngleDeg = insert.noseAngleDeg;
  facts.enteringAngleDeg = holder.enteringAngleDeg;
  facts.holder = holder.code;
  facts.shankWidthMm = holder.shankWidthMm;
  facts.shankHeightMm = holder.shankHeightMm;
  return facts;
}

}  // namespace lathesim::setup
