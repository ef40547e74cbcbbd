#include "setup/comment_tools.hpp"

#include <regex>

#include <fmt/format.h>

#include "geometry/iso_holder.hpp"
#include "geometry/iso_insert.hpp"
#include "geometry/tool_shape.hpp"
#include "interp/text/regex_text.hpp"

namespace lathesim::setup {
namespace {

using std::regex_constants::icase;

const std::string kNumber = R"(([0-9]+(?:\.[0-9]+)?|\.[0-9]+))";

// The holder style most shops put each insert shape in (iso-tools.md §2.3).
std::optional<char> usualStyle(char shape) {
  switch (shape) {
    case 'C': case 'W': return 'L';
    case 'D': case 'V': return 'J';
    case 'T': return 'G';
    case 'S': return 'B';
    default: return std::nullopt;
  }
}

// The tool built, numbered; its facts' source is set by whoever finds the comment.
std::optional<CommentTool> place(BuiltTool built, int number, std::string description, ToolFacts facts) {
  if (!built.tool) return std::nullopt;
  ToolShape& shape = *built.tool;
  return CommentTool{ToolDefinition{number, std::move(shape.cutter), std::move(shape.holderBody), shape.tipNumber,
                                    shape.noseRadiusMm, std::nullopt, std::move(facts)},
                     std::move(description), std::move(built.warnings)};
}

ToolFacts factsOf(std::string kind, std::string shape, std::optional<double> angleDeg) {
  ToolFacts facts;
  facts.kind = std::move(kind);
  facts.insertShape = std::move(shape);
  facts.insertAngleDeg = angleDeg;
  return facts;
}

std::optional<CommentTool> isoInsertTool(const std::string& comment, int number) {
  static const std::regex insertCode(R"(\b([A-Z]{4})\s?-?\s?([0-9]{2}|S[0-9])\s?([0-9]{2}|T[0-9])\s?([0-9]{2}|M0)\b)", icase);
  std::smatch m;
  if (!std::regex_search(comment, m, insertCode)) return std::nullopt;
  std::string code = m[1].str() + m[2].str() + m[3].str() + m[4].str();
  for (char& c : code) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const auto insert = parseIsoInsert(code);
  if (!insert.value) return std::nullopt;
  static const std::regex holderCode(R"(\b([CDMPSW][A-Z]{3}[RLN][0-9]{4}[A-Z][0-9]{2})\b)", icase);
  std::smatch h;
  std::string holderText;
  std::string why;
  if (std::regex_search(comment, h, holderCode)) {
    holderText = h[1].str();
    for (char& c : holderText) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  } else {
    const auto style = usualStyle(insert.value->shape);
    if (!style) return std::nullopt;
    const char clamp = insert.value->clearance == 'N' ? 'P' : 'S';
    holderText = fmt::format("{}{}{}{}R2525M{}", clamp, insert.value->shape, *style, insert.value->clearance,
                             insert.value->sizeCode);
    why = fmt::format(" (the holder assumed for a {} insert)", insert.value->shape);
  }
  const auto holder = parseIsoHolder(holderText);
  if (!holder.value) return std::nullopt;
  auto named = place(turningTool(*insert.value, *holder.value, std::nullopt), number,
                     fmt::format("{} in {}{}", code, holderText, why), turningFacts(*insert.value, *holder.value));
  if (named) named->warnings.insert(named->warnings.end(), insert.warnings.begin(), insert.warnings.end());
  return named;
}

// The patterns are compiled once: compiling them for every comment took most of the time of
// reading one (the iso_codes fuzz harness ran at ~600 inputs a second).
std::regex pattern(const std::string& text) { return std::regex(text, icase); }

std::optional<double> numberAfter(const std::string& text, const std::regex& number) {
  std::smatch m;
  if (!std::regex_search(text, m, number)) return std::nullopt;
  return interp::matchedNumber(m[1]);
}

std::optional<CommentTool> grooveBlade(const std::string& comment, int number, double barDiameterMm) {
  static const std::regex blade = pattern(R"(\b(GROOV\w*|PARTING|PART[- ]?OFF|CUT[- ]?OFF)\b)");
  static const std::regex widthMm = pattern(kNumber + R"(\s*MM\b)");
  static const std::regex widthW = pattern(R"(\bW\s*=?\s*)" + kNumber);
  if (!std::regex_search(comment, blade)) return std::nullopt;
  auto width = numberAfter(comment, widthMm);
  if (!width) width = numberAfter(comment, widthW);
  if (!width || *width <= 0) return std::nullopt;
  const double depth = barDiameterMm / 2.0 + 5.0;
  return place(grooveTool(*width, 0.0, 0.0, depth, 3), number,
               fmt::format("a grooving/parting blade {:g} mm wide, {:g} mm deep, square corners, tip 3", *width, depth),
               factsOf("groove", fmt::format("a blade {:g} mm wide, {:g} mm deep", *width, depth), std::nullopt));
}

std::optional<CommentTool> drill(const std::string& comment, int number) {
  static const std::regex drillWord = pattern(R"(\bDRILL)");
  static const std::regex diameterAfter = pattern(R"(DRILL\w*\s*(?:D|DIA|Ø|Φ)?\s*=?\s*)" + kNumber);
  static const std::regex diameterBefore = pattern(R"((?:Ø|Φ|\bD|\bDIA)?\s*)" + kNumber + R"(\s*(?:MM)?\s*DRILL)");
  if (!std::regex_search(comment, drillWord)) return std::nullopt;
  auto diameter = numberAfter(comment, diameterAfter);
  if (!diameter) diameter = numberAfter(comment, diameterBefore);
  if (!diameter || *diameter <= 0) return std::nullopt;
  return place(drillTool(*diameter, 118.0, 10.0 * *diameter), number,
               fmt::format("a Φ{:g} drill, 118° point", *diameter),
               factsOf("drill", fmt::format("a Φ{:g} drill, 118° point, {:g} mm long", *diameter, 10.0 * *diameter), 118.0));
}

std::optional<CommentTool> threadingTool(const std::string& comment, int number) {
  static const std::regex threadWord = pattern(R"(\bTHREAD)");
  static const std::regex angleDeg = pattern(kNumber + R"(\s*(?:DEG|°))");
  static const std::regex pitchP = pattern(R"(\b(?:P|PITCH)\s*=?\s*)" + kNumber);
  static const std::regex pitchMetric = pattern(R"(\bM[0-9]+(?:\.[0-9]+)?\s*X\s*)" + kNumber);
  if (!std::regex_search(comment, threadWord)) return std::nullopt;
  const double angle = numberAfter(comment, angleDeg).value_or(60.0);
  auto pitch = numberAfter(comment, pitchP);
  if (!pitch) pitch = numberAfter(comment, pitchMetric);
  if (pitch && *pitch <= 0) return std::nullopt;
  // Full profile: the ISO root radius 0.125·P; partial (AG, 0.5–3 mm): drawn for 3 mm with the
  // nose of 0.5 mm.
  constexpr double kPartialLargestPitchMm = 3.0;
  constexpr double kPartialSmallestPitchMm = 0.5;
  const double drawnPitch = pitch.value_or(kPartialLargestPitchMm);
  const double nose = 0.125 * pitch.value_or(kPartialSmallestPitchMm);
  std::string description =
      pitch ? fmt::format("a {:g}° threading insert for pitch {:g}", angle, *pitch)
            : fmt::format("a {:g}° partial-profile threading insert (0.5–3 mm pitches, no pitch named)", angle);
  ToolFacts facts = factsOf("thread", description, angle);
  return place(lathesim::threadTool(angle, drawnPitch, nose, 8), number, std::move(description), std::move(facts));
}

}  // namespace

std::optional<CommentTool> toolNamedIn(const std::string& written, int number, double barDiameterMm) {
  const std::string comment = interp::regexText(written);
  if (auto tool = isoInsertTool(comment, number)) return tool;
  if (auto tool = grooveBlade(comment, number, barDiameterMm)) return tool;
  if (auto tool = drill(comment, number)) return tool;
  return threadingTool(comment, number);
}

}  // namespace lathesim::setup
