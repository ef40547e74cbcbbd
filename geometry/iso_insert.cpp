#include "geometry/iso_insert.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>

namespace lathesim {
namespace {

struct ShapeInfo {
  char letter;
  double noseAngleDeg;  // 0: round
  const char* name;
};

// §1.1. A B K L (parallelograms, rectangle) are known but have no inscribed circle.
constexpr std::array<ShapeInfo, 12> kShapes{{
    {'C', 80.0, "rhombic 80°"},  {'D', 55.0, "rhombic 55°"},  {'E', 75.0, "rhombic 75°"},
    {'M', 86.0, "rhombic 86°"},  {'V', 35.0, "rhombic 35°"},  {'S', 90.0, "square"},
    {'T', 60.0, "triangle"},     {'W', 80.0, "trigon"},       {'R', 0.0, "round"},
    {'H', 120.0, "hexagon"},     {'O', 135.0, "octagon"},     {'P', 108.0, "pentagon"},
}};
constexpr std::string_view kUnsupportedShapes = "ABKL";

struct LetterValue {
  char letter;
  double value;
};

// §1.2 clearance angles; O ("other") is described separately and simulated as 0°.
constexpr std::array<LetterValue, 10> kClearances{{
    {'A', 3}, {'B', 5}, {'C', 7}, {'D', 15}, {'E', 20}, {'F', 25}, {'G', 30}, {'N', 0}, {'P', 11}, {'O', 0},
}};
constexpr std::string_view kTolerances = "AFCHEGJKLMNU";  // §1.3
constexpr std::string_view kTypes = "NRFAMGWTQUBHCJX";    // §1.4
constexpr std::string_view kEdgeConditions = "FETSKP";    // §1.8 position 8
constexpr std::string_view kHands = "RLN";                // §1.8 position 9

struct CodeValue {
  std::string_view code;
  double value;
};

// §1.6 thickness codes, mm.
constexpr std::array<CodeValue, 10> kThicknesses{{
    {"01", 1.59}, {"T1", 1.98}, {"02", 2.38}, {"03", 3.18}, {"T3", 3.97},
    {"04", 4.76}, {"05", 5.56}, {"06", 6.35}, {"07", 7.94}, {"09", 9.52},
}};

// §1.5 the inch IC series, mm.
constexpr std::array<double, 15> kInchSeries{3.97,  4.76,  5.56,   6.35,  7.94,  9.525, 11.11, 12.70,
                                             14.29, 15.875, 17.46, 19.05, 22.225, 25.40, 31.75};

// §1.5 size code → IC, as printed (WIDIA code key), one row per IC.
struct SizeRow {
  double icMm;
  std::array<std::string_view, 7> codes;  // columns C D V S T W R
};
constexpr std::string_view kTableShapes = "CDVSTWR";
constexpr std::array<SizeRow, 11> kSizeTable{{
    {3.97, {"S4", "04", "06", "03", "06", "02", "03"}},
    {4.76, {"04", "05", "08", "04", "08", "S3", "04"}},
    {5.56, {"05", "06", "09", "05", "09", "03", "05"}},
    {6.35, {"06", "07", "11", "06", "11", "04", "06"}},
    {7.94, {"08", "09", "13", "07", "13", "05", "07"}},
    {9.525, {"09", "11", "16", "09", "16", "06", "09"}},
    {11.11, {"11", "13", "19", "11", "19", "07", "11"}},
    {12.70, {"12", "15", "22", "12", "22", "08", "12"}},
    {15.875, {"16", "19", "27", "15", "27", "10", "15"}},
    {19.05, {"19", "23", "33", "19", "33", "13", "19"}},
    {25.40, {"25", "31", "44", "25", "44", "17", "25"}},
}};

std::string listOf(std::string_view letters) {
  std::string text;
  for (char c : letters) {
    if (!text.empty()) text += ' ';
    text += c;
  }
  return text;
}

const ShapeInfo* shapeOf(char letter) {
  for (const auto& s : kShapes)
    if (s.letter == letter) return &s;
  return nullptr;
}

bool twoDigits(std::string_view s) {
  return s.size() == 2 && std::isdigit(static_cast<unsigned char>(s[0])) && std::isdigit(static_cast<unsigned char>(s[1]));
}

/// The code a shape of IC d gets by §1.5: l rounded to 0.1 mm, then truncated.
std::string codeForInscribed(char shape, double icMm) {
  const double tenths = std::round(icMm * edgeLengthPerInscribedMm(shape) * 10.0);
  const int whole = static_cast<int>(std::floor(tenths / 10.0));
  std::string code = std::to_string(whole);
  if (code.size() < 2) code.insert(code.begin(), '0');
  return code;
}

/// IC for (shape, size code) from the printed table, or for shapes the table does not print,
/// the one IC of the inch series whose edge length truncates to the code.
std::optional<double> tabulatedInscribedMm(char shape, std::string_view sizeCode) {
  if (const auto column = kTableShapes.find(shape); column != std::string_view::npos) {
    for (const auto& row : kSizeTable)
      if (row.codes[column] == sizeCode) return row.icMm;
    return std::nullopt;
  }
  std::optional<double> found;
  for (double ic : kInchSeries) {
    if (codeForInscribed(shape, ic) != sizeCode) continue;
    if (found) return std::nullopt;  // ambiguous: not a code this shape's series uses
    found = ic;
  }
  return found;
}

class Reader {
 public:
  explicit Reader(std::string code) : code_(std::move(code)) {}

  ParsedCode<IsoInsert> fail(std::size_t index, int position, std::string_view what) const {
    const std::string shown = index < code_.size() ? std::string(code_.substr(index, position >= 5 && position <= 7 ? 2 : 1))
                                                   : std::string();
    return {std::nullopt,
            CodeProblem{index, "insert " + code_ + ": position " + std::to_string(position) + " '" + shown + "' " +
                                   std::string(what)},
            {}};
  }
  const std::string& code() const { return code_; }

 private:
  std::string code_;
};

}  // namespace

double edgeLengthPerInscribedMm(char shape) {
  const double pi = std::numbers::pi;
  const auto rad = [pi](double deg) { return deg * pi / 180.0; };
  switch (shape) {
    case 'S': case 'R': return 1.0;
    case 'T': return std::sqrt(3.0);
    case 'W': return 0.5 * (1.0 / std::tan(rad(40)) + 1.0 / std::tan(rad(80)));
    case 'P': return std::tan(pi / 5);
    case 'H': return std::tan(pi / 6);
    case 'O': return std::tan(pi / 8);
    default: {
      const ShapeInfo* s = shapeOf(shape);
      return s && s->noseAngleDeg > 0 ? 1.0 / std::sin(rad(s->noseAngleDeg)) : 1.0;  // rhombic: l = d / sin ε
    }
  }
}

ParsedCode<IsoInsert> parseIsoInsert(std::string_view given) {
  std::string upper(given);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const Reader r(upper);
  const std::string& code = r.code();
  IsoInsert insert;
  insert.code = code;
  std::vector<std::string> warnings;

  if (code.size() < 10) {
    const std::size_t dash = code.find('-');
    const std::size_t end = std::min(dash, code.size());
    return {std::nullopt,
            CodeProblem{end, "insert " + code + ": too short; expected shape, clearance, tolerance, type, "
                                                "two-digit size, thickness and corner (10 characters, e.g. CNMG120408)"},
            {}};
  }

  // 1: shape
  const ShapeInfo* shape = shapeOf(code[0]);
  if (!shape) {
    if (kUnsupportedShapes.find(code[0]) != std::string_view::npos)
      return r.fail(0, 1, "is a parallelogram or rectangle, which has no inscribed circle; not supported "
                          "(give the tool as a polygon)");
    return r.fail(0, 1, "is not an insert shape; expected one of C D E M V S T W R H O P");
  }
  insert.shape = shape->letter;
  insert.noseAngleDeg = shape->noseAngleDeg;

  // 2: clearance
  bool clearanceOk = false;
  for (const auto& c : kClearances)
    if (c.letter == code[1]) {
      insert.clearance = c.letter;
      insert.clearanceDeg = c.value;
      clearanceOk = true;
    }
  if (!clearanceOk) return r.fail(1, 2, "is not a clearance angle; expected one of A B C D E F G N P O");

  // 3, 4: tolerance class, hole and chipbreaker type
  if (kTolerances.find(code[2]) == std::string_view::npos)
    return r.fail(2, 3, "is not a tolerance class; expected one of " + listOf(kTolerances));
  insert.tolerance = code[2];
  if (kTypes.find(code[3]) == std::string_view::npos)
    return r.fail(3, 4, "is not an insert type; expected one of " + listOf(kTypes));
  insert.type = code[3];

  // 7 first: a round insert's corner (00 inch, M0 metric) decides how its size reads.
  const std::string_view corner = std::string_view(code).substr(8, 2);
  const bool metricRound = corner == "M0";
  if (insert.round()) {
    if (corner != "00" && !metricRound)
      return r.fail(8, 7, "is not a round insert's corner; expected 00 (inch diameter) or M0 (metric diameter)");
  } else if (!twoDigits(corner)) {
    return r.fail(8, 7, "is not a corner radius; expected two digits, the nose radius × 10 mm (04, 08, 12 …)");
  }

  // 5: size
  const std::string_view size = std::string_view(code).substr(4, 2);
  insert.sizeCode = std::string(size);
  const double factor = edgeLengthPerInscribedMm(insert.shape);
  if (metricRound) {
    if (!twoDigits(size)) return r.fail(4, 5, "is not a metric round diameter; expected two digits (mm)");
    insert.inscribedCircleMm = std::stod(std::string(size));
  } else if (const auto ic = tabulatedInscribedMm(insert.shape, size)) {
    insert.inscribedCircleMm = *ic;
  } else if (twoDigits(size) && size != "00") {
    insert.vendorSpecialSize = true;
    insert.inscribedCircleMm = std::stod(std::string(size)) / factor;
    warnings.push_back("insert " + code + ": size " + std::string(size) + " is not in the inch IC series for shape " +
                       std::string(1, insert.shape) + "; read as a vendor special with edge length " +
                       std::string(size) + " mm (check the catalogue)");
  } else {
    return r.fail(4, 5, "is not a size code for shape " + std::string(1, insert.shape) +
                            "; expected two digits, the edge length in mm");
  }
  insert.edgeLengthMm = insert.vendorSpecialSize ? std::stod(std::string(size)) : insert.inscribedCircleMm * factor;

  // 6: thickness
  bool thicknessOk = false;
  for (const auto& t : kThicknesses)
    if (t.code == std::string_view(code).substr(6, 2)) {
      insert.thicknessMm = t.value;
      thicknessOk = true;
    }
  if (!thicknessOk)
    return r.fail(6, 6, "is not a thickness code; expected one of 01 T1 02 03 T3 04 05 06 07 09");

  // 7: nose radius
  insert.noseRadiusMm = insert.round() ? insert.inscribedCircleMm / 2.0 : std::stod(std::string(corner)) / 10.0;
  if (!insert.round() && insert.noseRadiusMm >= insert.inscribedCircleMm / 2.0)
    return r.fail(8, 7, "is a nose radius that does not fit the insert's inscribed circle");

  // 8, 9 (optional), then an optional maker's suffix after a dash
  std::size_t i = 10;
  if (i < code.size() && kEdgeConditions.find(code[i]) != std::string_view::npos) insert.edgeCondition = code[i++];
  if (i < code.size() && kHands.find(code[i]) != std::string_view::npos) insert.hand = code[i++];
  if (i < code.size() && code[i] != '-') {
    const int position = insert.hand ? 10 : insert.edgeCondition ? 9 : 8;
    return r.fail(i, position, position == 8 ? "is not an edge condition or hand; expected one of F E T S K P, R L N, "
                                               "or a '-' before a maker's suffix"
                                             : "is not expected here; expected a hand (R L N) or a '-' before a maker's suffix");
  }
  return {std::move(insert), std::nullopt, std::move(warnings)};
}

}  // namespace lathesim
