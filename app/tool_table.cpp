#include "app/tool_table.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "app/tool_picture.hpp"
#include "interp/compensation/tool_offset.hpp"

namespace lathesim::app {

void ToolUsage::note(const interp::Move& move) {
  if (last_ && last_->tool == move.tool && last_->offset == move.toolOffset && lastShift_ == move.offsetShift) {
    ++last_->moves;
    return;
  }
  auto pair = std::find_if(used_.begin(), used_.end(), [&](const UsedToolOffset& u) {
    return u.tool == move.tool && u.offset == move.toolOffset;
  });
  if (pair == used_.end()) {
    used_.push_back({move.tool, move.toolOffset, move.line, 0, {}, 0});
    pair = used_.end() - 1;
  }
  last_ = &*pair;
  lastShift_ = move.offsetShift;
  ++last_->moves;
  if (std::find(last_->shifts.begin(), last_->shifts.end(), move.offsetShift) != last_->shifts.end()) return;
  if (last_->shifts.size() < kShiftsKept) last_->shifts.push_back(move.offsetShift);
  else ++last_->moreShifts;
}

namespace {

using Json = nlohmann::ordered_json;

Json optionalMm(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }

Json offsetJson(const setup::Setup& setup, const UsedToolOffset& u) {
  Json entry{{"offset", u.offset}, {"t_word", fmt::format("T{:02d}{:02d}", u.tool, u.offset)},
             {"first_line", u.firstLine}, {"moves", u.moves}};
  const auto defined = setup.offsets.find(u.offset);
  if (u.offset == 0) {
    entry["table"] = nullptr;
    entry["from"] = "offset 0: none";
  } else if (defined == setup.offsets.end()) {
    entry["table"] = nullptr;
    entry["from"] = "not in the setup: all zero, as on a machine whose entry is empty";
  } else {
    const interp::ToolOffset& o = defined->second;
    entry["table"] = {{"x_diameter_mm", o.xDiameterMm}, {"z_mm", o.zMm}, {"wear_x_diameter_mm", o.wearXDiameterMm},
                      {"wear_z_mm", o.wearZMm}, {"radius_mm", o.radiusMm}, {"wear_radius_mm", o.wearRadiusMm},
                      {"tip", o.tip}};
    entry["from"] = setup.sourceName + " [[offset]] number " + std::to_string(u.offset);
  }
  // As the run used it: geometry + wear, and what G10 set during the run.
  Json shifts = Json::array();
  for (const RZ& s : u.shifts) shifts.push_back({{"x_diameter_mm", 2.0 * s.x()}, {"z_mm", s.y()}});
  entry["shifts_used"] = shifts;
  if (u.moreShifts > 0) entry["more_shifts_used"] = u.moreShifts;
  return entry;
}

Json toolJson(const setup::Setup& setup, const setup::ToolDefinition* tool, int number,
              const std::vector<UsedToolOffset>& used) {
  Json entry{{"number", number}};
  if (tool) {
    const setup::ToolFacts& f = tool->facts;
    entry["kind"] = f.kind;
    entry["insert"] = f.insert.empty() ? Json(nullptr) : Json(f.insert);
    entry["insert_shape"] = f.insertShape.empty() ? Json(nullptr) : Json(f.insertShape);
    entry["nose_radius_mm"] = tool->noseRadiusMm;
    entry["cutting_edge_length_mm"] = optionalMm(f.cuttingEdgeLengthMm);
    entry["insert_angle_deg"] = optionalMm(f.insertAngleDeg);
    entry["entering_angle_deg"] = optionalMm(f.enteringAngleDeg);
    entry["holder"] = f.holder.empty() ? Json(nullptr) : Json(f.holder);
    entry["shank_mm"] = f.shankWidthMm && f.shankHeightMm ? Json{{"width", *f.shankWidthMm}, {"height", *f.shankHeightMm}}
                                                          : Json(nullptr);
    entry["tip"] = tool->tipNumber;
    entry["from"] = f.source;
    const DrawnToolSizes drawn = drawnToolSizes(*tool);
    entry["drawn"] = {{"holder_height_mm", drawn.holderHeightMm}, {"insert_thickness_mm", drawn.insertThicknessMm},
                      {"from", drawn.from}};
  } else {
    entry["kind"] = nullptr;
    entry["from"] = "not declared: the run used it without a definition";
  }
  Json offsets = Json::array();
  for (const UsedToolOffset& u : used)
    if (u.tool == number) offsets.push_back(offsetJson(setup, u));
  entry["used"] = !offsets.empty();
  entry["offsets_used"] = offsets;
  return entry;
}

}  // namespace

nlohmann::ordered_json toolTableJson(const setup::Setup& setup, const std::vector<UsedToolOffset>& used) {
  Json table = Json::array();
  for (const setup::ToolDefinition& tool : setup.tools) table.push_back(toolJson(setup, &tool, tool.number, used));
  std::vector<int> undeclared;
  for (const UsedToolOffset& u : used) {
    const bool declared = std::any_of(setup.tools.begin(), setup.tools.end(),
                                      [&](const setup::ToolDefinition& t) { return t.number == u.tool; });
    if (!declared && std::find(undeclared.begin(), undeclared.end(), u.tool) == undeclared.end())
      undeclared.push_back(u.tool);
  }
  for (int number : undeclared) table.push_back(toolJson(setup, nullptr, number, used));
  return table;
}

nlohmann::ordered_json stockJson(const setup::Setup& setup) {
  const sim::StockSpec& s = setup.stock;
  const std::string from = setup.stockBy.empty() ? "assumed: the default setup's bar (no setup, --stock or program states one)"
                                                 : setup.stockBy;
  return {{"diameter_mm", s.diameterMm},
          {"length_mm", s.lengthMm},
          {"bore_mm", s.boreMm},
          {"face_z_mm", s.faceZMm},
          {"material", setup.stockMaterial.empty() ? Json(nullptr) : Json(setup.stockMaterial)},
          {"from", from},
          {"face_z_from", setup.stockFaceGiven ? from : "assumed: Z" + std::string(setup.stockBy.empty() ? "2, the default bar's" : "0")}};
}

}  // namespace lathesim::app
