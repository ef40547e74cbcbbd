#include "geometry/iso_holder.hpp"

#include <array>
#include <cctype>
#include <cmath>

#include "geometry/iso_insert.hpp"

namespace lathesim {
namespace {

struct StyleInfo {
  char letter;
  double enteringAngleDeg;  // κr; symmetric styles: computed from the insert's ε
  HolderFamily family;
  bool offset;
};

// §2.3.
constexpr std::array<StyleInfo, 22> kStyles{{
    {'A', 90.0, HolderFamily::Side, false},   {'B', 75.0, HolderFamily::Side, false},
    {'C', 90.0, HolderFamily::End, false},    {'D', 45.0, HolderFamily::Symmetric, false},
    {'E', 60.0, HolderFamily::Symmetric, false}, {'F', 90.0, HolderFamily::End, true},
    {'G', 90.0, HolderFamily::Side, true},    {'H', 107.5, HolderFamily::Side, true},
    {'J', 93.0, HolderFamily::Side, true},    {'K', 75.0, HolderFamily::End, true},
    {'L', 95.0, HolderFamily::Side, true},    {'M', 50.0, HolderFamily::Symmetric, false},
    {'N', 63.0, HolderFamily::Symmetric, false}, {'P', 117.5, HolderFamily::Side, true},
    {'Q', 107.5, HolderFamily::End, true},    {'R', 75.0, HolderFamily::Side, true},
    {'S', 45.0, HolderFamily::Side, true},    {'T', 60.0, HolderFamily::Side, true},
    {'U', 93.0, HolderFamily::End, true},     {'V', 72.5, HolderFamily::Symmetric, false},
    {'W', 60.0, HolderFamily::End, true},     {'Y', 85.0, HolderFamily::End, true},
}};

struct LengthLetter {
  char letter;
  double mm;
};

// §2.8 (G, W, Y are the [C] values 90, 450, 500).
constexpr std::array<LengthLetter, 22> kLengths{{
    {'A', 32},  {'B', 40},  {'C', 50},  {'D', 60},  {'E', 70},  {'F', 80},  {'G', 90},  {'H', 100},
    {'J', 110}, {'K', 125}, {'L', 140}, {'M', 150}, {'N', 160}, {'P', 170}, {'Q', 180}, {'R', 200},
    {'S', 250}, {'T', 300}, {'U', 350}, {'V', 400}, {'W', 450}, {'Y', 500},
}};

constexpr std::string_view kClampings = "CMPSDW";
constexpr std::string_view kInsertClearanceLetters = "ABCDEFGNPO";
constexpr std::string_view kInsertShapeLetters = "CDEMVSTWRHOPABKL";

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

class HolderCodeReader {
 public:
  explicit HolderCodeReader(std::string code) : code_(std::move(code)) {}
  ParsedCode<IsoHolder> fail(std::size_t index, std::size_t width, int position, const std::string& what) const {
    const std::string shown = index < code_.size() ? code_.substr(index, width) : std::string();
    return {std::nullopt,
            CodeProblem{index, "holder " + code_ + ": position " + std::to_string(position) + " '" + shown + "' " + what},
            {}};
  }
  const std::string& code() const { return code_; }

 private:
  std::string code_;
};

std::string degrees(double value) {
  std::string text = std::to_string(value);
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text + "°";
}

}  // namespace

double IsoHolder::functionalWidthMm() const {
  if (family == HolderFamily::Symmetric) return shankWidthMm / 2.0;
  if (!offsetShank) return shankWidthMm;
  if (shankWidthMm == 25.0) return 32.0;  // the catalogue value; 1.25·25 would be 31.25
  return 1.25 * shankWidthMm;
}

ParsedCode<IsoHolder> parseIsoHolder(std::string_view given) {
  std::string upper(given);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const HolderCodeReader r(upper);
  const std::string& code = r.code();
  IsoHolder holder;
  holder.code = code;

  if (code.size() < 12)
    return {std::nullopt,
            CodeProblem{std::min(code.find('-'), code.size()),
                        "holder " + code + ": too short; expected clamping, insert shape, style, clearance, hand, "
                                           "shank height and width, length letter and edge length (12 characters, "
                                           "e.g. PCLNR2525M12)"},
            {}};

  if (kClampings.find(code[0]) == std::string_view::npos)
    return r.fail(0, 1, 1, "is not a clamping system; expected one of C M P S D W");
  holder.clamping = code[0];

  if (kInsertShapeLetters.find(code[1]) == std::string_view::npos)
    return r.fail(1, 1, 2, "is not an insert shape; expected one of C D E M V S T W R H O P");
  holder.insertShape = code[1];

  const StyleInfo* style = nullptr;
  for (const auto& s : kStyles)
    if (s.letter == code[2]) style = &s;
  if (!style)
    return r.fail(2, 1, 3, "is not a holder style; expected one of A B C D E F G H J K L M N P Q R S T U V W Y");
  holder.style = style->letter;
  holder.family = style->family;
  holder.offsetShank = style->offset;
  holder.enteringAngleDeg = style->enteringAngleDeg;
  // The insert's nose angle, when the holder's shape letter names one with an inscribed circle.
  double epsilon = 0.0;
  if (const auto probe = parseIsoInsert(std::string(1, holder.insertShape) + "NMG120408"); probe.value)
    epsilon = probe.value->noseAngleDeg;
  if (holder.family == HolderFamily::Symmetric) {
    holder.enteringAngleDeg = (180.0 - epsilon) / 2.0;
  } else if (epsilon > 0.0 && holder.enteringAngleDeg + epsilon >= 180.0) {
    return r.fail(2, 1, 3, "has κr " + degrees(holder.enteringAngleDeg) + ", which leaves no room for a " +
                               degrees(epsilon) + " insert (κr + ε must stay below 180°)");
  }

  if (kInsertClearanceLetters.find(code[3]) == std::string_view::npos)
    return r.fail(3, 1, 4, "is not a clearance angle; expected one of A B C D E F G N P O");
  holder.clearance = code[3];

  if (holder.family == HolderFamily::Symmetric ? code[4] != 'N' : (code[4] != 'R' && code[4] != 'L'))
    return r.fail(4, 1, 5, holder.family == HolderFamily::Symmetric
                               ? "is not the hand of a symmetric style; expected N"
                               : "is not a hand for style " + std::string(1, holder.style) + "; expected R or L");
  holder.hand = code[4];

  for (std::size_t i = 5; i < 9; ++i)
    if (!digit(code[i]))
      return r.fail(i < 7 ? 5 : 7, 2, i < 7 ? 6 : 7,
                    std::string("is not a shank ") + (i < 7 ? "height" : "width") + "; expected two digits (mm)");
  holder.shankHeightMm = std::stod(code.substr(5, 2));
  holder.shankWidthMm = std::stod(code.substr(7, 2));
  if (holder.shankHeightMm <= 0.0) return r.fail(5, 2, 6, "is not a shank height; expected two digits (mm), not 00");
  if (holder.shankWidthMm <= 0.0) return r.fail(7, 2, 7, "is not a shank width; expected two digits (mm), not 00");

  bool lengthOk = false;
  for (const auto& l : kLengths)
    if (l.letter == code[9]) {
      holder.lengthMm = l.mm;
      lengthOk = true;
    }
  if (!lengthOk)
    return r.fail(9, 1, 8, code[9] == 'X' ? "is a special length, which this simulator cannot read; give a standard letter"
                                          : "is not a tool length letter; expected one of A B C D E F G H J K L M N P Q R S T U V W Y");

  const char e0 = code[10], e1 = code[11];
  if (!((digit(e0) || e0 == 'S') && digit(e1)))
    return r.fail(10, 2, 9, "is not a cutting-edge length; expected the insert's two-digit size code");
  holder.edgeSizeCode = code.substr(10, 2);

  std::size_t i = 12;
  if (i < code.size() && std::isalpha(static_cast<unsigned char>(code[i]))) ++i;  // position 10: tolerance option
  if (i < code.size() && code[i] != '-')
    return r.fail(i, 1, 10, "is not expected here; expected one option letter or a '-' before a maker's suffix");
  return {std::move(holder), std::nullopt, {}};
}

}  // namespace lathesim
