// The drawing's profile file: TOML rows → the outline's points in (radius, Z), arcs as
// chords. Every problem is reported with the line of the row it is in; a file with any
// problem yields no outline.

#include "measure/drawing.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "geometry/meridian_profile.hpp"

namespace lathesim::measure {
namespace {

using interp::Diagnostic;

struct Reader {
  std::string fileName;
  std::string_view text;
  std::vector<Diagnostic> diagnostics;

  void error(const toml::source_region& where, const std::string& message) {
    const int line = static_cast<int>(where.begin.line);
    diagnostics.push_back({interp::Severity::Error, fileName, line, static_cast<int>(where.begin.column), message,
                           interp::lineOf(text, line)});
  }
};

/// A number (integer or float) under `key` of `row`, or nullopt with an error if present but wrong.
std::optional<double> number(Reader& reader, const toml::table& row, const char* key, bool required) {
  const toml::node* node = row.get(key);
  if (node == nullptr) {
    if (required) reader.error(row.source(), std::string("profile row needs ") + key);
    return std::nullopt;
  }
  if (const auto value = node->value<double>(); value && std::isfinite(*value)) return *value;
  reader.error(node->source(), std::string("profile ") + key + " must be a number (mm)");
  return std::nullopt;
}

/// More chords than this for one arc is no turned part's arc (a full circle of radius 100 m
/// needs 70 000): refused rather than filling the memory.
constexpr double kMaxArcChords = 100000;

/// Appends the arc from `from` to `to` (radius, Z) as chords, excluding `from`; false (and
/// nothing appended) when it would need more than kMaxArcChords.
/// In the drawing view u = Z is to the right and v = r is up; clockwise is as seen there.
bool appendArc(std::vector<RZ>& out, const RZ& from, const RZ& to, const RZ& centre, bool clockwise) {
  const auto angle = [&](const RZ& p) { return std::atan2(p.x() - centre.x(), p.y() - centre.y()); };
  const double radius = (from - centre).norm();
  double sweep = angle(to) - angle(from);
  if (clockwise)
    while (sweep >= 0) sweep -= 2 * M_PI;
  else
    while (sweep <= 0) sweep += 2 * M_PI;
  // The angle whose chord strays e from the arc: 2·acos(1 − e/r), written as 4·asin(√(e/2r)),
  // which stays exact where 1 − e/r would round to 1 (a radius of a kilometre or more).
  const double maxStep = 4 * std::asin(std::min(1.0, std::sqrt(kDrawingChordErrorMm / (2 * radius))));
  const double needed = std::ceil(std::abs(sweep) / maxStep);
  if (!(needed <= kMaxArcChords)) return false;
  const int steps = std::max(1, static_cast<int>(needed));
  const double start = angle(from);
  for (int s = 1; s < steps; ++s) {
    const double a = start + sweep * s / steps;
    out.emplace_back(centre.x() + radius * std::sin(a), centre.y() + radius * std::cos(a));
  }
  out.push_back(to);
  return true;
}

/// The centre of an arc of signed radius R from a to b (R < 0: the longer arc), or nullopt.
std::optional<RZ> centreFromRadius(const RZ& a, const RZ& b, double radius, bool clockwise) {
  const RZ chord = b - a;
  const double half = chord.norm() / 2;
  if (half == 0 || std::abs(radius) < half * (1 - 1e-9)) return std::nullopt;
  const double offset = std::sqrt(std::max(0.0, radius * radius - half * half));
  // In (u, v) = (z, r), the right of the direction (du, dv) is (dv, −du); as (r, z): (−du, dv).
  const RZ unit = chord / chord.norm();
  const RZ right(-unit.y(), unit.x());
  const double side = (clockwise ? 1.0 : -1.0) * (radius > 0 ? 1.0 : -1.0);
  return RZ((a + b) / 2 + side * offset * right);
}

/// A pair of numbers [a, b] with a ≤ b under `key`, or nullopt with an error if present but wrong.
std::optional<std::pair<double, double>> pairOf(Reader& reader, const toml::table& row, const char* key) {
  const toml::node* node = row.get(key);
  if (node == nullptr) return std::nullopt;
  const toml::array* pair = node->as_array();
  const auto a = pair && pair->size() == 2 ? pair->get(0)->value<double>() : std::nullopt;
  const auto b = pair && pair->size() == 2 ? pair->get(1)->value<double>() : std::nullopt;
  if (!a || !b || !std::isfinite(*a) || !std::isfinite(*b) || *a > *b) {
    reader.error(node->source(), std::string("thread ") + key + " must be [least, greatest], two numbers in mm");
    return std::nullopt;
  }
  return std::pair(*a, *b);
}

std::optional<ThreadCallout> threadCallout(Reader& reader, const toml::table& row) {
  for (const auto& [key, node] : row)
    if (key.str() != "z_range" && key.str() != "pitch" && key.str() != "starts" && key.str() != "hand" &&
        key.str() != "major" && key.str() != "minor" && key.str() != "pitch_diameter")
      reader.error(key.source(), "unknown thread key '" + std::string(key.str()) +
                                     "' (expected z_range, pitch, starts, hand, major, minor or pitch_diameter)");
  ThreadCallout callout;
  callout.line = static_cast<int>(row.source().begin.line);
  const auto zone = pairOf(reader, row, "z_range");
  if (!zone && !row.get("z_range")) reader.error(row.source(), "a [[thread]] needs z_range = [low Z, high Z]");
  const auto pitch = number(reader, row, "pitch", true);
  if (pitch && !(*pitch > 0)) reader.error(row.get("pitch")->source(), "thread pitch must be a number > 0 (mm)");
  if (const toml::node* starts = row.get("starts")) {
    const auto n = starts->value<int64_t>();
    if (!n || *n < 1) reader.error(starts->source(), "thread starts must be a whole number ≥ 1");
    else callout.starts = static_cast<int>(*n);
  }
  if (const toml::node* hand = row.get("hand")) {
    const auto text = hand->value<std::string>();
    if (!text || (*text != "right" && *text != "left")) reader.error(hand->source(), "thread hand must be \"right\" or \"left\"");
    else callout.rightHand = *text == "right";
  }
  const auto limits = [&](const char* key) -> std::optional<DiameterLimits> {
    const auto pair = pairOf(reader, row, key);
    if (!pair) return std::nullopt;
    return DiameterLimits{pair->first, pair->second};
  };
  callout.major = limits("major");
  callout.minor = limits("minor");
  callout.pitchDiameter = limits("pitch_diameter");
  if (!zone || !pitch || !(*pitch > 0)) return std::nullopt;
  callout.zLowMm = zone->first;
  callout.zHighMm = zone->second;
  callout.pitchMm = *pitch;
  return callout;
}

/// A fit stated on a diameter, resolved once the outline tells a shaft from a bore.
struct PendingFit {
  std::size_t line;  // index into the lines
  std::string fit;
  toml::source_region where;
};

std::string signedMm(double value) {
  std::ostringstream text;
  text << (value > 0 ? "+" : value < 0 ? "−" : "") << std::abs(value);
  return text.str();
}

/// The tolerance a row states for the line reaching it: ±t, [upper, lower] or (a diameter) a fit.
std::optional<Tolerance> statedTolerance(Reader& reader, const toml::node& node, const DrawnLine& line,
                                         std::size_t lineIndex, std::vector<PendingFit>& fits) {
  if (const auto plusMinus = node.value<double>()) {
    if (!std::isfinite(*plusMinus) || *plusMinus < 0) {
      reader.error(node.source(), "tolerance must be ± a number ≥ 0 (mm), [upper, lower] or an ISO 286 fit such as \"h7\"");
      return std::nullopt;
    }
    std::ostringstream text;
    text << "±" << *plusMinus;
    return Tolerance{*plusMinus, -*plusMinus, text.str()};
  }
  if (const toml::array* pair = node.as_array()) {
    const auto upper = pair->size() == 2 ? pair->get(0)->value<double>() : std::nullopt;
    const auto lower = pair->size() == 2 ? pair->get(1)->value<double>() : std::nullopt;
    if (!upper || !lower || !std::isfinite(*upper) || !std::isfinite(*lower) || *upper < *lower) {
      reader.error(node.source(), "tolerance [upper, lower] must be two numbers in mm, upper ≥ lower, e.g. [0, -0.1]");
      return std::nullopt;
    }
    return Tolerance{*upper, *lower, signedMm(*upper) + "/" + signedMm(*lower)};
  }
  if (const auto fit = node.value<std::string>()) {
    if (!line.diameter()) {
      reader.error(node.source(), "an ISO 286 fit ('" + *fit + "') applies to a diameter: this row's line is not parallel to the "
                                  "axis; give ± a number or [upper, lower]");
      return std::nullopt;
    }
    std::string problem;
    if (!isoFit(*fit, 2 * line.to.x(), problem)) {
      reader.error(node.source(), problem);
      return std::nullopt;
    }
    fits.push_back({lineIndex, *fit, node.source()});
    return std::nullopt;
  }
  reader.error(node.source(), "tolerance must be ± a number (mm), [upper, lower] or an ISO 286 fit such as \"h7\"");
  return std::nullopt;
}

/// Sets each fit's limits, checking its case against the side the material is on: a shaft
/// (material towards the axis) takes a lower-case fit, a bore an upper-case one.
void resolveFits(Reader& reader, const std::vector<RZ>& outline, std::vector<DrawnLine>& lines,
                 const std::vector<PendingFit>& fits) {
  if (fits.empty()) return;
  const MeridianProfile region = MeridianProfile::fromPolygon(outline);
  for (const PendingFit& pending : fits) {
    DrawnLine& line = lines[pending.line];
    const double step = std::min(1e-3, line.from.x() / 2);
    const bool shaft = region.contains(RZ(line.from.x() - step, (line.from.y() + line.to.y()) / 2));
    if (shaft == isHoleFit(pending.fit)) {
      const int row = static_cast<int>(pending.where.begin.line);
      reader.diagnostics.push_back({interp::Severity::Error, reader.fileName, row, static_cast<int>(pending.where.begin.column),
                                    "'" + pending.fit + "' is a " + (shaft ? "hole" : "shaft") + "'s fit, but this diameter is a " +
                                        (shaft ? "shaft's (material towards the axis): write it in lower case"
                                               : "bore's (material away from the axis): write it in upper case"),
                                    interp::lineOf(reader.text, row)});
      continue;
    }
    std::string problem;
    line.tolerance = isoFit(pending.fit, 2 * line.to.x(), problem);
  }
}

}  // namespace

DrawingResult parseDrawing(std::string_view tomlText, const std::string& fileName) {
  Reader reader{fileName, tomlText, {}};
  DrawingResult result;
  toml::table table;
  try {
    table = toml::parse(tomlText, fileName);
  } catch (const toml::parse_error& e) {
    reader.error(e.source(), std::string(e.description()));
    result.diagnostics = std::move(reader.diagnostics);
    return result;
  }
  for (const auto& [key, node] : table)
    if (key.str() != "profile" && key.str() != "thread" && key.str() != "general_tolerance" && key.str() != "corner_radius")
      reader.error(key.source(), "unknown key '" + std::string(key.str()) +
                                     "' (expected [[profile]] rows, [[thread]] callouts, general_tolerance or corner_radius)");
  if (const toml::node* general = table.get("general_tolerance")) {
    const auto text = general->value<std::string>();
    if (!text || text->size() != 1 || std::string("fmcv").find((*text)[0]) == std::string::npos)
      reader.error(general->source(), "general_tolerance must be an ISO 2768-1 class: \"f\", \"m\", \"c\" or \"v\"");
    else result.generalTolerance = (*text)[0];
  }
  if (const toml::node* corner = table.get("corner_radius")) {
    const auto radius = corner->value<double>();
    if (!radius || !std::isfinite(*radius) || *radius < 0) reader.error(corner->source(), "corner_radius must be a number ≥ 0 (mm)");
    else result.cornerRadiusMm = *radius;
  }
  if (const toml::node* threads = table.get("thread")) {
    const toml::array* rows = threads->as_array();
    if (rows == nullptr) reader.error(threads->source(), "thread must be [[thread]] tables");
    for (std::size_t n = 0; rows && n < rows->size(); ++n) {
      const toml::table* row = rows->get(n)->as_table();
      if (row == nullptr) {
        reader.error(rows->get(n)->source(), "a thread callout must be a table");
        continue;
      }
      if (auto callout = threadCallout(reader, *row)) result.threads.push_back(*callout);
    }
  }
  const toml::array* rows = table["profile"].as_array();
  if (rows == nullptr || rows->size() < 2) {
    reader.error(table.source(), "the drawing needs at least two [[profile]] rows, each with x (diameter) and z");
    result.diagnostics = std::move(reader.diagnostics);
    return result;
  }
  std::vector<RZ> outline;
  std::vector<DrawnLine> lines;
  std::vector<PendingFit> fits;
  for (std::size_t n = 0; n < rows->size(); ++n) {
    const toml::table* row = rows->get(n)->as_table();
    if (row == nullptr) {
      reader.error(rows->get(n)->source(), "a profile row must be a table such as {x = 30, z = 0}");
      continue;
    }
    for (const auto& [key, node] : *row)
      if (key.str() != "x" && key.str() != "z" && key.str() != "arc" && key.str() != "radius" && key.str() != "center" &&
          key.str() != "tolerance")
        reader.error(key.source(), "unknown profile key '" + std::string(key.str()) + "' (expected x, z, arc, radius, center or tolerance)");
    const auto x = number(reader, *row, "x", true);
    const auto z = number(reader, *row, "z", true);
    if (!x || !z) continue;
    if (*x < 0) {
      reader.error(row->source(), "profile x is a diameter and cannot be negative");
      continue;
    }
    const RZ point(*x / 2, *z);
    const toml::node* arc = row->get("arc");
    if (!outline.empty())
      lines.push_back({outline.back(), point, static_cast<int>(row->source().begin.line), arc != nullptr, std::nullopt,
                       outline.size() - 1, outline.size()});  // the arc's chords may push the end on
    if (const toml::node* stated = row->get("tolerance")) {
      if (outline.empty()) reader.error(stated->source(), "the first profile row has no line to tolerance: a row's tolerance is "
                                                          "that of the line reaching it from the previous row");
      else lines.back().tolerance = statedTolerance(reader, *stated, lines.back(), lines.size() - 1, fits);
    }
    if (arc == nullptr) {
      if (row->get("radius") || row->get("center")) reader.error(row->source(), "radius and center need arc = \"cw\" or \"ccw\"");
      outline.push_back(point);
      continue;
    }
    const auto direction = arc->value<std::string>();
    if (!direction || (*direction != "cw" && *direction != "ccw")) {
      reader.error(arc->source(), "arc must be \"cw\" or \"ccw\" (as drawn: Z to the right, X up)");
      continue;
    }
    if (outline.empty()) {
      reader.error(row->source(), "the first profile row cannot be an arc: an arc runs from the previous point");
      continue;
    }
    const bool clockwise = *direction == "cw";
    std::optional<RZ> centre;
    if (const toml::array* c = row->get_as<toml::array>("center")) {
      const auto cx = c->size() == 2 ? c->get(0)->value<double>() : std::nullopt;
      const auto cz = c->size() == 2 ? c->get(1)->value<double>() : std::nullopt;
      if (!cx || !cz || !std::isfinite(*cx) || !std::isfinite(*cz)) {
        reader.error(c->source(), "center must be [x diameter, z]");
        continue;
      }
      centre = RZ(*cx / 2, *cz);
      const double r0 = (outline.back() - *centre).norm(), r1 = (point - *centre).norm();
      if (std::abs(r0 - r1) > 1e-3) {
        reader.error(c->source(), "the arc's ends are not the same distance from its center");
        continue;
      }
    } else if (const auto radius = number(reader, *row, "radius", false)) {
      centre = centreFromRadius(outline.back(), point, *radius, clockwise);
      if (!centre) {
        reader.error(row->source(), "the arc's radius is shorter than half the distance between its ends");
        continue;
      }
    } else {
      if (!row->get("radius")) reader.error(row->source(), "an arc needs radius or center");
      continue;
    }
    const bool drawn = appendArc(outline, outline.back(), point, *centre, clockwise);
    lines.back().outlineTo = outline.size() - 1;
    if (!drawn) {
      std::ostringstream message;
      message << "the arc's radius, " << (point - *centre).norm() << " mm, is too large for a turned part: drawn "
              << "within " << kDrawingChordErrorMm << " mm it would take more than " << kMaxArcChords << " chords";
      reader.error(row->source(), message.str());
    }
  }
  if (reader.diagnostics.empty()) resolveFits(reader, outline, lines, fits);
  result.diagnostics = std::move(reader.diagnostics);
  if (result.diagnostics.empty()) result.outline = std::move(outline), result.lines = std::move(lines);
  return result;
}

DrawingResult loadDrawing(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    DrawingResult result;
    result.diagnostics.push_back({interp::Severity::Error, file.string(), 0, 0, "cannot read the drawing file", ""});
    return result;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseDrawing(text.str(), file.string());
}

}  // namespace lathesim::measure
