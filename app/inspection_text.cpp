#include "app/inspection_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "batch/html_text.hpp"
#include "interp/base/printable_text.hpp"

namespace lathesim::app {
namespace {

/// A tolerance figure as drawings write it: no trailing zeros ("0.021", "0.2", "0").
std::string shortMm(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.4f", std::abs(value));
  std::string s = text;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string signedShort(double value, bool plusForZero) {
  if (value == 0) return plusForZero ? "+0" : "0";
  return (value > 0 ? "+" : "−") + shortMm(value);
}

}  // namespace

std::string limitsText(double upperMm, double lowerMm) {
  if (upperMm == -lowerMm) return "±" + shortMm(upperMm);
  return signedShort(upperMm, true) + "/" + signedShort(lowerMm, false);
}

std::string madeByText(const std::vector<int>& lines, const BlockText& block) {
  if (lines.empty()) return "";
  std::string text = lines.size() == 1 ? "made by line" : "made by lines";
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::string quoted = block ? block(lines[n]) : "";
    text += (n ? ", " : " ") + std::to_string(lines[n]);
    if (!quoted.empty()) text += " `" + interp::printable(quoted) + "`";
  }
  return text;
}

std::string verdictText(measure::Verdict verdict, double outsideMm, double voxelMm, double uncertaintyMm) {
  if (verdict == measure::Verdict::Within) return "within";
  if (verdict == measure::Verdict::Out) return "OUT";
  const auto finer = measure::decidingVoxelMm(outsideMm, voxelMm, uncertaintyMm);
  if (!finer) return "undecided: it lies on its limit, which no voxel decides";
  char text[64];
  std::snprintf(text, sizeof text, "%g", *finer);
  return std::string("undecided at this voxel; rerun with --voxel ") + text;
}

std::string sizeText(const measure::SizeCheck& size, double voxelMm, const BlockText& block) {
  const double off = size.worstMm - size.nominalMm;
  std::string text;
  if (!size.probed) {
    const std::string limits = limitsText(size.tolerance.upperMm, size.tolerance.lowerMm);
    return "face drawn Z" + batch::fixed(size.nominalMm, 3) + " (" + limits +
           (size.tolerance.source == limits ? "" : ", " + size.tolerance.source) + ", drawing line " +
           std::to_string(size.drawn.line) +
           "): undecided: not measured, the part beside it stands over all of it, so no column crosses this face "
           "alone (see the profile's regions there)";
  }
  if (size.diameter) {
    text = "Ø" + batch::fixed(size.worstMm, 3) + " ±" + batch::fixed(size.uncertaintyMm, 3) + " measured at Z" + batch::fixed(size.worstAt.y(), 3) +
           " (drawn " + std::string(size.bore ? "bore " : "") + "Ø" + batch::fixed(size.nominalMm, 3) + " ";
  } else {
    text = "face Z" + batch::fixed(size.worstMm, 3) + " ±" + batch::fixed(size.uncertaintyMm, 3) + " measured at Ø" +
           batch::fixed(diameterOf(size.worstAt), 3) + " (drawn Z" + batch::fixed(size.nominalMm, 3) + " ";
  }
  const std::string limits = limitsText(size.tolerance.upperMm, size.tolerance.lowerMm);
  text += limits + (size.tolerance.source == limits ? "" : ", " + size.tolerance.source) + ", drawing line " +
          std::to_string(size.drawn.line) + "): ";
  if (size.diameter) text += batch::fixed(std::abs(off), 3) + (off < 0 ? " undersize" : " oversize");
  else text += batch::fixed(std::abs(off), 3) + (off < 0 ? " towards −Z" : " towards +Z");
  if (size.outsideMm > 0) text += ", " + batch::fixed(size.outsideMm, 3) + " beyond its limit";
  text += ": " + verdictText(size.verdict, size.outsideMm, voxelMm, size.uncertaintyMm);
  if (size.verdict != measure::Verdict::Within && !size.lines.empty()) {
    text += "; " + madeByText(size.lines, block);
    if (size.valueLine != 0 && size.valueLine != size.lines.front()) {
      const std::string quoted = block ? interp::printable(block(size.valueLine)) : "";
      text += std::string(" (its ") + (size.diameter ? "X" : "Z") + " from line " + std::to_string(size.valueLine) +
              (quoted.empty() ? "" : " `" + quoted + "`") + ")";
    }
  }
  return text;
}

std::string regionText(const measure::DeviationRegion& r, double uncertaintyMm, double voxelMm, const BlockText& block) {
  std::string text = std::string(r.gouge ? "gouge " : "excess ") + batch::fixed(r.maxMm, 3) + " ±" + batch::fixed(uncertaintyMm, 3) +
                     " mm normal to the drawing at Z" + batch::fixed(r.at.y(), 3) + " Ø" + batch::fixed(diameterOf(r.at), 3) + " (Z" +
                     batch::fixed(r.lower.y(), 3) + "..Z" + batch::fixed(r.upper.y(), 3) + ", Ø" + batch::fixed(diameterOf(r.lower), 3) + "..Ø" +
                     batch::fixed(diameterOf(r.upper), 3) + "), allowed " + limitsText(r.band.upperMm, r.band.lowerMm) +
                     " there";
  if (r.beyondMm > 0) text += ", " + batch::fixed(r.beyondMm, 3) + " beyond";
  text += ": " + verdictText(r.verdict, r.beyondMm, voxelMm, uncertaintyMm);
  const std::vector<int>& lines = r.madeBy.empty() ? r.lines : r.madeBy;
  if (!lines.empty()) text += "; " + madeByText(lines, block);
  else if (r.gouge) text += "; not cut: the bar had no material there";
  return text;
}

measure::Verdict overallVerdict(const std::vector<measure::SizeCheck>& sizes, const measure::DeviationReport& deviation,
                                const std::vector<measure::ThreadCheck>& threads) {
  std::vector<measure::Verdict> all;
  for (const auto& s : sizes) all.push_back(s.verdict);
  for (const auto& r : deviation.regions) all.push_back(r.verdict);
  for (const auto& t : threads) all.push_back(t.within() ? measure::Verdict::Within : measure::Verdict::Out);
  if (std::count(all.begin(), all.end(), measure::Verdict::Out)) return measure::Verdict::Out;
  if (std::count(all.begin(), all.end(), measure::Verdict::Undecided)) return measure::Verdict::Undecided;
  return measure::Verdict::Within;
}

}  // namespace lathesim::app
