#include "geometry/thread_insert.hpp"

#include <array>
#include <cctype>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace lathesim {
namespace {

constexpr double kMmPerInch = 25.4;

struct SizeIc {
  std::string_view code;
  double icMm;
};
constexpr std::array<SizeIc, 6> kSizes{{
    {"06", 25.4 * 5 / 32}, {"08", 25.4 * 3 / 16}, {"11", 25.4 / 4}, {"16", 25.4 * 3 / 8}, {"22", 25.4 / 2}, {"27", 25.4 * 5 / 8},
}};

struct Standard {
  std::string_view name;
  double profileDeg;
  bool inch;            // the pitch is written in threads per inch
  double rootRadiusPerPitch;
};
// Longest names first: they are matched at the end of the code.
constexpr std::array<Standard, 5> kStandards{{
    {"BSPT", 55, true, 0.137329},
    {"ISO", 60, false, 0.125},
    {"NPT", 60, true, 0.0},
    {"UN", 60, true, 0.125},
    {"W", 55, true, 0.137329},
}};

struct PartialRange {
  std::string_view letters;
  double minMm, maxMm;
};
constexpr std::array<PartialRange, 6> kRanges{{
    {"AG", 0.5, 3.0}, {"A", 0.5, 1.5}, {"G", 1.75, 3.0}, {"N", 3.5, 5.0}, {"Q", 5.5, 6.0}, {"U", 5.5, 9.0},
}};

ParsedCode<ThreadInsert> fail(const std::string& code, std::size_t index, const std::string& why) {
  return {std::nullopt, CodeProblem{index, "threading insert " + code + ": " + why}, {}};
}

}  // namespace

bool looksLikeThreadInsert(std::string_view code) {
  return code.size() >= 2 && std::isdigit(static_cast<unsigned char>(code[0])) &&
         std::isdigit(static_cast<unsigned char>(code[1]));
}

ParsedCode<ThreadInsert> parseThreadInsert(std::string_view given) {
  // Upper case without spaces; `where` maps each kept character back to the code as given.
  std::string code;
  std::vector<std::size_t> where;
  for (std::size_t i = 0; i < given.size(); ++i) {
    if (given[i] == ' ') continue;
    code.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(given[i]))));
    where.push_back(i);
  }
  const auto at = [&](std::size_t i) { return i < where.size() ? where[i] : given.size(); };
  ThreadInsert insert;
  insert.code = code;

  std::size_t i = 0;
  const std::string size = code.substr(0, 2);
  const auto sizeRow = std::find_if(kSizes.begin(), kSizes.end(), [&](const SizeIc& s) { return s.code == size; });
  if (code.size() < 2 || sizeRow == kSizes.end())
    return fail(code, at(0), "'" + size + "' is not a size; expected 06, 08, 11, 16, 22 or 27 (the IC in 1/32 in)");
  insert.sizeCode = size;
  insert.inscribedCircleMm = sizeRow->icMm;
  i = 2;

  if (i < code.size() && code[i] == 'U') ++i;  // U-type: the same outline
  if (i >= code.size() || (code[i] != 'E' && code[i] != 'I'))
    return fail(code, at(i), "expected E (external) or I (internal) after the size");
  insert.internal = code[i] == 'I';
  ++i;
  if (i < code.size() && code[i] == 'I' && !insert.internal) ++i;  // UEI: external and internal
  if (i >= code.size() || (code[i] != 'R' && code[i] != 'L')) return fail(code, at(i), "expected the hand R, L or RL");
  insert.hand = code[i++];
  if (insert.hand == "R" && i < code.size() && code[i] == 'L') {
    insert.hand = "RL";
    ++i;
  }
  if (i < code.size() && code[i] == 'M') ++i;  // pressed chipbreaker

  // The standard is the code's tail: a name, or the partial profile's angle.
  std::size_t tail = code.size();
  const Standard* standard = nullptr;
  for (const Standard& s : kStandards)
    if (code.size() >= i + s.name.size() && code.ends_with(s.name)) {
      standard = &s;
      tail = code.size() - s.name.size();
      break;
    }
  if (!standard && (code.ends_with("60") || code.ends_with("55"))) {
    // Partial profile: a range letter, then the angle.
    const std::string letters = code.substr(i, code.size() - 2 - i);
    const auto range = std::find_if(kRanges.begin(), kRanges.end(), [&](const PartialRange& r) { return r.letters == letters; });
    if (range == kRanges.end())
      return fail(code, at(i), "'" + letters + "' is not a partial-profile range; expected A, AG, G, N, Q or U before the angle");
    insert.partialProfile = true;
    insert.standard = code.substr(code.size() - 2);
    insert.profileDeg = insert.standard == "60" ? 60 : 55;
    insert.minPitchMm = range->minMm;
    insert.pitchMm = range->maxMm;
    insert.noseRadiusMm = (insert.profileDeg == 60 ? 0.125 : 0.137329) * range->minMm;
    return {insert, std::nullopt, {}};
  }
  if (!standard)
    return fail(code, at(i), "the thread standard is not one lathesim reads; expected ISO, UN, W, BSPT or NPT (or 60/55 "
                             "after a partial-profile range)");
  const std::string pitchText = code.substr(i, tail - i);
  double value = 0;
  std::size_t used = 0;
  try {
    value = std::stod(pitchText, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (pitchText.empty() || used != pitchText.size() || !(value > 0))
    return fail(code, at(i), "'" + pitchText + "' is not a pitch; expected a number before " + std::string(standard->name));
  if (!standard->inch && pitchText.find('.') == std::string::npos && pitchText.size() >= 3) value /= 100.0;  // 200 = 2.00 mm
  insert.standard = standard->name;
  insert.profileDeg = standard->profileDeg;
  insert.pitchMm = standard->inch ? kMmPerInch / value : value;
  insert.minPitchMm = insert.pitchMm;
  const double rootPerPitch = standard->rootRadiusPerPitch;
  // The internal insert forms the nut's root at the major diameter: ISO 68's flat of P/8 there,
  // a radius of half the external one (⚠ no catalogue at hand).
  insert.noseRadiusMm = (insert.internal && standard->profileDeg == 60 ? rootPerPitch / 2 : rootPerPitch) * insert.pitchMm;
  return {insert, std::nullopt, {}};
}

}  // namespace lathesim
