// ISO 286 and ISO 2768-1 as data tables. Values are the standards' own, in micrometres for
// ISO 286 and millimetres for ISO 2768-1; each table says where it is from.

#include "measure/iso_tolerances.hpp"

#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace lathesim::measure {
namespace {

// ISO 286-1:2010 nominal size steps (main steps; the letters used here need no intermediate
// ones): over the previous bound, up to and including this one, mm.
constexpr std::array<double, 13> kSizeStepsMm{3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500};
using Row = std::array<int, 13>;

// ISO 286-1:2010 Table 1, standard tolerance grades IT4–IT11 (µm). IT4 is only used for Δ of IT5.
constexpr std::array<Row, 8> kIt{{
    {3, 4, 4, 5, 6, 7, 8, 10, 12, 14, 16, 18, 20},                         // IT4
    {4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27},                       // IT5
    {6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40},                     // IT6
    {10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63},                  // IT7
    {14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97},                  // IT8
    {25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155},             // IT9
    {40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250},          // IT10
    {60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400},        // IT11
}};
constexpr int kFirstItGrade = 4;

// ISO 286-1:2010 Table 2, fundamental deviations of shafts (µm): the upper deviation es of
// d–h, the lower deviation ei of k (grades 4–7; 0 otherwise), m, n, p.
constexpr Row kShaftD{-20, -30, -40, -50, -65, -80, -100, -120, -145, -170, -190, -210, -230};
constexpr Row kShaftE{-14, -20, -25, -32, -40, -50, -60, -72, -85, -100, -110, -125, -135};
constexpr Row kShaftF{-6, -10, -13, -16, -20, -25, -30, -36, -43, -50, -56, -62, -68};
constexpr Row kShaftG{-2, -4, -5, -6, -7, -9, -10, -12, -14, -15, -17, -18, -20};
constexpr Row kShaftK{0, 1, 1, 1, 2, 2, 2, 3, 3, 4, 4, 4, 5};
constexpr Row kShaftM{2, 4, 6, 7, 8, 9, 11, 13, 15, 17, 20, 21, 23};
constexpr Row kShaftN{4, 8, 10, 12, 15, 17, 20, 23, 27, 31, 34, 37, 40};
constexpr Row kShaftP{6, 12, 15, 18, 22, 26, 32, 37, 43, 50, 56, 62, 68};

// ISO 2768-1:1989 Table 1, permissible deviations for linear dimensions (mm), by class, over
// 0.5–3, 3–6, 6–30, 30–120, 120–400, 400–1000, 1000–2000, 2000–4000 mm. Class v has none
// for 0.5–3 (NaN stands for "—").
constexpr std::array<double, 8> kLinearBoundsMm{3, 6, 30, 120, 400, 1000, 2000, 4000};
constexpr std::array<double, 8> kLinearF{0.05, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 0.5};
constexpr std::array<double, 8> kLinearM{0.1, 0.1, 0.2, 0.3, 0.5, 0.8, 1.2, 2};
constexpr std::array<double, 8> kLinearC{0.2, 0.3, 0.5, 0.8, 1.2, 2, 3, 4};
constexpr std::array<double, 8> kLinearV{-1, 0.5, 1, 1.5, 2.5, 4, 6, 8};

std::string formatted(const char* format, double value) {
  char text[48];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

bool isHoleFit(const std::string& fit) { return !fit.empty() && std::isupper(static_cast<unsigned char>(fit[0])) != 0; }

std::optional<Tolerance> isoFit(const std::string& fit, double nominalMm, std::string& problem) {
  std::size_t digits = 0;
  while (digits < fit.size() && std::isalpha(static_cast<unsigned char>(fit[digits]))) ++digits;
  const std::string letter = fit.substr(0, digits), gradeText = fit.substr(digits);
  char* end = nullptr;
  const long grade = gradeText.empty() ? 0 : std::strtol(gradeText.c_str(), &end, 10);
  if (letter.empty() || gradeText.empty() || *end != '\0' || grade < 5 || grade > 11) {
    problem = "'" + fit + "' is not an ISO 286 fit covered here (a letter d e f g h js k m n p for a shaft, D E F G H "
              "JS K M N P for a hole, then a grade 5 to 11, e.g. h7 or H7)";
    return std::nullopt;
  }
  if (!(nominalMm > 0 && nominalMm <= 500)) {
    problem = "ISO 286 fits are tabled here for sizes up to 500 mm; this one is " + formatted("%.3f", nominalMm) + " mm";
    return std::nullopt;
  }
  std::size_t step = 0;
  while (nominalMm > kSizeStepsMm[step]) ++step;
  const auto it = [&](long n) { return kIt[n - kFirstItGrade][step]; };
  const int tolerance = it(grade);
  // Δ = ITn − IT(n−1) (ISO 286-1:2010 Table 3); 0 up to 3 mm.
  const int delta = step == 0 ? 0 : tolerance - it(grade - 1);
  // js/JS: ±IT/2; odd values of IT7–IT11 rounded down to the even number below (ISO 286-1 §A.2 note).
  const double halfJs = (grade >= 7 && tolerance % 2 == 1 ? tolerance - 1 : tolerance) / 2.0;
  std::string lower = letter;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string upperCase = letter;
  for (char& c : upperCase) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const bool hole = letter == upperCase;
  if (!hole && letter != lower) {
    problem = "'" + fit + "' mixes upper- and lower-case letters: a shaft's fit is lower case (h7), a hole's upper case (H7)";
    return std::nullopt;
  }
  double upper = 0, lowerDev = 0;  // µm
  const auto shaftUpper = [&](int es) { upper = es, lowerDev = es - tolerance; };
  const auto shaftLower = [&](int ei) { lowerDev = ei, upper = ei + tolerance; };
  if (lower == "js") upper = halfJs, lowerDev = -halfJs;
  else if (!hole && lower == "d") shaftUpper(kShaftD[step]);
  else if (!hole && lower == "e") shaftUpper(kShaftE[step]);
  else if (!hole && lower == "f") shaftUpper(kShaftF[step]);
  else if (!hole && lower == "g") shaftUpper(kShaftG[step]);
  else if (!hole && lower == "h") shaftUpper(0);
  else if (!hole && lower == "k") shaftLower(grade <= 7 ? kShaftK[step] : 0);
  else if (!hole && lower == "m") shaftLower(kShaftM[step]);
  else if (!hole && lower == "n") shaftLower(kShaftN[step]);
  else if (!hole && lower == "p") shaftLower(kShaftP[step]);
  // Holes (ISO 286-1:2010 Table 3): EI = −es for D–H; ES = −ei + Δ for K, M, N up to IT8 and
  // P up to IT7, ES = −ei above (K and N over 3 mm: 0).
  else if (hole && (lower == "d" || lower == "e" || lower == "f" || lower == "g" || lower == "h")) {
    const int es = lower == "d" ? kShaftD[step] : lower == "e" ? kShaftE[step] : lower == "f" ? kShaftF[step]
                   : lower == "g" ? kShaftG[step] : 0;
    lowerDev = -es, upper = -es + tolerance;
  } else if (hole && (lower == "k" || lower == "m" || lower == "n" || lower == "p")) {
    const int ei = lower == "k" ? kShaftK[step] : lower == "m" ? kShaftM[step] : lower == "n" ? kShaftN[step] : kShaftP[step];
    const bool withDelta = grade <= (lower == "p" ? 7 : 8);
    int es = withDelta ? -ei + delta : -ei;
    if (!withDelta && step > 0 && (lower == "k" || lower == "n")) es = 0;
    upper = es, lowerDev = es - tolerance;
  } else {
    problem = "'" + fit + "': the fundamental deviation '" + letter + "' is not tabled here (shafts: d e f g h js k m n p; "
              "holes: D E F G H JS K M N P)";
    return std::nullopt;
  }
  return Tolerance{upper / 1000.0, lowerDev / 1000.0, fit};
}

std::optional<double> generalLinearTolerance(char toleranceClass, double nominalMm) {
  const std::array<double, 8>* row = toleranceClass == 'f' ? &kLinearF : toleranceClass == 'm' ? &kLinearM
                                     : toleranceClass == 'c' ? &kLinearC : toleranceClass == 'v' ? &kLinearV : nullptr;
  if (row == nullptr) return std::nullopt;
  std::size_t step = 0;
  while (step + 1 < kLinearBoundsMm.size() && nominalMm > kLinearBoundsMm[step]) ++step;
  if ((*row)[step] < 0) return std::nullopt;
  return (*row)[step];
}

}  // namespace lathesim::measure
