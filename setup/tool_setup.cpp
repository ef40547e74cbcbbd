// [[tool]] shape keys → ToolDefinition. The kind is "turning" when insert/holder are given,
// else what `kind` says; each kind takes its own keys:
//   turning: insert, holder, tip          groove: width, corner_radius (r or [r−Z, r+Z]), depth, tip
//   thread:  angle, pitch, nose_radius, tip, or insert (a laydown code: 16ER200ISO), nose_radius, tip
//   drill:   diameter, point_angle, length
// A polygon tool may give tip alone (default 3). Any tool may give thickness (mm), the
// insert's thickness for cuts made with the spindle stopped (an ISO insert's own otherwise).

#include "setup/tool_setup.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "geometry/iso_holder.hpp"
#include "geometry/iso_insert.hpp"
#include "geometry/thread_insert.hpp"
#include "geometry/tool_shape.hpp"

namespace lathesim::setup {
namespace {

using interp::Severity;

struct KindKeys {
  std::string_view kind;
  std::vector<std::string_view> keys;
};

const std::vector<KindKeys>& kinds() {
  static const std::vector<KindKeys> table{
      {"turning", {"insert", "holder", "tip"}},
      {"groove", {"width", "corner_radius", "depth", "tip"}},
      {"thread", {"insert", "angle", "pitch", "nose_radius", "tip"}},
      {"drill", {"diameter", "point_angle", "length"}},
  };
  return table;
}

/// A scalar as TOML spells it, for messages.
std::string spelled(const toml::node& node) {
  if (const auto* s = node.as_string()) return "\"" + s->get() + "\"";
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* f = node.as_floating_point()) {
    std::string text = std::to_string(f->get());
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text += '0';
    return text;
  }
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  return node.is_table() ? "a table" : node.is_array() ? "an array" : "a value";
}

class ToolReader {
 public:
  ToolReader(const toml::table& table, const std::string& name, std::vector<ToolKeyProblem>& problems)
      : table_(table), name_(name), problems_(problems) {}

  void error(const toml::node& at, std::string message, int columnOffset = 0) {
    problems_.push_back({at.source(), columnOffset, std::move(message), Severity::Error});
    failed_ = true;
  }
  void warn(const toml::node& at, std::string message) {
    problems_.push_back({at.source(), 0, std::move(message), Severity::Warning});
  }
  bool failed() const { return failed_; }
  const std::string& name() const { return name_; }
  const toml::table& table() const { return table_; }

  /// A number (integer or float) key; `minimum` is exclusive unless `zeroOk`.
  std::optional<double> number(std::string_view key, std::optional<double> fallback, bool zeroOk, std::string_view unit) {
    const toml::node* node = table_.get(key);
    if (!node) {
      if (!fallback) error(table_, name_ + " (kind \"" + kind_ + "\") needs " + std::string(key) + " (" + std::string(unit) + ")");
      return fallback;
    }
    std::optional<double> value;
    if (const auto* i = node->as_integer()) value = static_cast<double>(i->get());
    if (const auto* f = node->as_floating_point()) value = f->get();
    if (!value || !std::isfinite(*value) || *value < 0 || (*value == 0 && !zeroOk)) {
      error(*node, name_ + "." + std::string(key) + " must be a " + (zeroOk ? "non-negative" : "positive") +
                       " number of " + std::string(unit) + ", got " + spelled(*node));
      return std::nullopt;
    }
    return value;
  }

  std::optional<int> tip() {
    const toml::node* node = table_.get("tip");
    if (!node) return std::nullopt;
    const auto* integer = node->as_integer();
    if (!integer || integer->get() < 0 || integer->get() > 9) {
      error(*node, name_ + ".tip must be an integer 0..9 (the imaginary tool tip number), got " + spelled(*node));
      return std::nullopt;
    }
    return static_cast<int>(integer->get());
  }

  /// corner_radius: one radius for both end corners, or [−Z corner, +Z corner]; default 0.
  std::optional<std::pair<double, double>> cornerRadii() {
    const toml::node* node = table_.get("corner_radius");
    if (!node) return std::pair(0.0, 0.0);
    if (!node->is_array()) {
      const auto both = number("corner_radius", std::nullopt, true, "mm");
      if (!both) return std::nullopt;
      return std::pair(*both, *both);
    }
    const auto* pair = node->as_array();
    std::optional<double> values[2];
    if (pair->size() == 2)
      for (std::size_t i = 0; i < 2; ++i) {
        const toml::node& v = *pair->get(i);
        if (v.is_integer()) values[i] = static_cast<double>(v.as_integer()->get());
        if (v.is_floating_point()) values[i] = v.as_floating_point()->get();
        if (values[i] && !(*values[i] >= 0 && std::isfinite(*values[i]))) values[i].reset();
      }
    if (!values[0] || !values[1]) {
      error(*node, name_ + ".corner_radius must be a radius or [−Z corner, +Z corner], non-negative mm");
      return std::nullopt;
    }
    return std::pair(*values[0], *values[1]);
  }

  /// A catalogue code key: its text, or an error.
  const toml::value<std::string>* code(std::string_view key) {
    const toml::node* node = table_.get(key);
    if (!node) {
      error(table_, name_ + " has " + (key == "insert" ? "a holder but no insert" : "an insert but no holder") +
                        " (add " + std::string(key) + " = \"" + (key == "insert" ? "CNMG120408" : "PCLNR2525M12") + "\")");
      return nullptr;
    }
    const auto* text = node->as_string();
    if (!text) error(*node, name_ + "." + std::string(key) + " must be a catalogue code in quotes, got " + spelled(*node));
    return text;
  }

  void setKind(std::string kind) { kind_ = std::move(kind); }

 private:
  const toml::table& table_;
  std::string name_;
  std::vector<ToolKeyProblem>& problems_;
  std::string kind_;
  bool failed_ = false;
};

/// Places a BuiltTool into `tool`, or reports why it could not be built at `at`.
void take(BuiltTool built, const toml::node& at, ToolReader& reader, ToolDefinition& tool) {
  for (auto& w : built.warnings) reader.warn(at, reader.name() + ": " + w);
  if (!built.tool) {
    reader.error(at, reader.name() + ": " + built.problem);
    return;
  }
  tool.outline = std::move(built.tool->cutter);
  tool.holderBody = std::move(built.tool->holderBody);
  tool.tipNumber = built.tool->tipNumber;
  tool.noseRadiusMm = built.tool->noseRadiusMm;
}

void readTurning(ToolReader& r, ToolDefinition& tool) {
  if (!r.table().contains("insert") && !r.table().contains("holder")) {
    r.error(r.table(), r.name() + " (kind \"turning\") needs insert and holder (e.g. insert = \"CNMG120408\", "
                                  "holder = \"PCLNR2525M12\")");
    return;
  }
  const auto* insertText = r.code("insert");
  const auto* holderText = r.code("holder");
  const std::optional<int> tip = r.tip();
  if (!insertText || !holderText) return;
  const auto insert = parseIsoInsert(insertText->get());
  const auto holder = parseIsoHolder(holderText->get());
  // The caret goes under the offending character: +1 for the opening quote.
  if (insert.problem) r.error(*insertText, r.name() + ".insert: " + insert.problem->message, 1 + static_cast<int>(insert.problem->index));
  if (holder.problem) r.error(*holderText, r.name() + ".holder: " + holder.problem->message, 1 + static_cast<int>(holder.problem->index));
  for (const auto& w : insert.warnings) r.warn(*insertText, r.name() + ".insert: " + w);
  if (!insert.value || !holder.value || r.failed()) return;
  take(turningTool(*insert.value, *holder.value, tip), *holderText, r, tool);
  if (!tool.thicknessMm) tool.thicknessMm = insert.value->thicknessMm;
  tool.facts = turningFacts(*insert.value, *holder.value);
}

// A laydown threading insert (geometry/thread_insert.hpp): its profile, pitch and nose radius
// (nose_radius overrides the derived one); angle and pitch come from the code alone.
void readThreadInsert(ToolReader& r, ToolDefinition& tool) {
  for (const char* key : {"angle", "pitch"})
    if (const toml::node* node = r.table().get(key))
      r.error(*node, r.name() + "." + key + " comes from the insert code; give one or the other");
  const auto* text = r.table().get("insert")->as_string();
  if (!text) {
    r.error(*r.table().get("insert"), r.name() + ".insert must be a catalogue code in quotes, e.g. \"16ER200ISO\"");
    return;
  }
  const auto insert = parseThreadInsert(text->get());
  if (insert.problem) {
    r.error(*text, r.name() + ".insert: " + insert.problem->message, 1 + static_cast<int>(insert.problem->index));
    return;
  }
  const auto nose = r.number("nose_radius", insert.value->noseRadiusMm, true, "mm");
  const auto tip = r.tip();
  if (!nose || r.failed()) return;
  take(threadTool(insert.value->profileDeg, insert.value->pitchMm, *nose, tip, insert.value->internal), *text, r, tool);
  tool.facts.kind = "thread";
  tool.facts.insert = text->get();
  tool.facts.insertShape = fmt::format("{}threading insert, pitch {:g} mm", insert.value->internal ? "internal " : "",
                                       insert.value->pitchMm);
  tool.facts.insertAngleDeg = insert.value->profileDeg;
}

}  // namespace

const std::vector<std::string_view>& toolShapeKeys() {
  static const std::vector<std::string_view> keys = [] {
    std::vector<std::string_view> all{"kind", "thickness"};
    for (const auto& k : kinds())
      for (auto key : k.keys)
        if (std::find(all.begin(), all.end(), key) == all.end()) all.push_back(key);
    return all;
  }();
  return keys;
}

bool readToolShape(const toml::table& table, const std::string& name, ToolDefinition& tool,
                   std::vector<ToolKeyProblem>& problems) {
  ToolReader r(table, name, problems);
  if (table.contains("thickness")) tool.thicknessMm = r.number("thickness", std::nullopt, false, "mm");
  const toml::node* kindNode = table.get("kind");
  std::string kind;
  if (kindNode) {
    const auto* text = kindNode->as_string();
    const bool known = text && std::any_of(kinds().begin(), kinds().end(), [&](const KindKeys& k) { return k.kind == text->get(); });
    if (!known) {
      r.error(*kindNode, name + ".kind must be \"turning\", \"groove\", \"thread\" or \"drill\", got " + spelled(*kindNode));
      return true;
    }
    kind = text->get();
  } else if (table.contains("insert") || table.contains("holder")) {
    // A laydown threading insert's code starts with its size digits, an ISO 1832 one with a letter.
    const auto* insert = table.get("insert") ? table.get("insert")->as_string() : nullptr;
    kind = insert && !table.contains("holder") && looksLikeThreadInsert(insert->get()) ? "thread" : "turning";
  }

  if (kind.empty()) {  // a polygon tool (or the default outline): only tip may be added
    if (table.contains("polygon")) tool.facts.kind = "polygon";
    for (auto&& [key, node] : table) {
      const std::string_view k = key.str();
      if (k == "number" || k == "polygon" || k == "tip" || k == "thickness") continue;
      for (const auto& kk : kinds())
        if (std::find(kk.keys.begin(), kk.keys.end(), k) != kk.keys.end()) {
          r.error(node, name + "." + std::string(k) + " needs kind = \"" + std::string(kk.kind) + "\"");
          break;
        }
    }
    if (const auto tip = r.tip()) tool.tipNumber = *tip;
    return false;
  }

  r.setKind(kind);
  tool.facts.kind = kind;
  if (const auto* polygon = table.get("polygon"))
    r.error(*polygon, name + ".polygon cannot be combined with a " + kind + " tool's keys; give one or the other");
  const auto& allowed = std::find_if(kinds().begin(), kinds().end(), [&](const KindKeys& k) { return k.kind == kind; })->keys;
  for (auto&& [key, node] : table) {
    const std::string_view k = key.str();
    if (k == "number" || k == "polygon" || k == "kind" || k == "thickness") continue;
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end() &&
        std::find(toolShapeKeys().begin(), toolShapeKeys().end(), k) != toolShapeKeys().end())
      r.error(node, name + "." + std::string(k) + " does not apply to a " + kind + " tool");
  }
  if (r.failed()) return true;

  if (kind == "turning") {
    readTurning(r, tool);
  } else if (kind == "groove") {
    const auto width = r.number("width", std::nullopt, false, "mm");
    const auto corners = r.cornerRadii();
    const auto depth = r.number("depth", std::nullopt, false, "mm");
    const auto tip = r.tip();
    if (width && corners && depth && !r.failed()) {
      take(grooveTool(*width, corners->first, corners->second, *depth, tip), table, r, tool);
      tool.facts.insertShape = fmt::format("a blade {:g} mm wide, {:g} mm deep", *width, *depth);
    }
  } else if (kind == "thread" && table.contains("insert")) {
    readThreadInsert(r, tool);
  } else if (kind == "thread") {
    const auto angle = r.number("angle", 60.0, false, "degrees");
    const auto pitch = r.number("pitch", std::nullopt, false, "mm");
    // The root radius when none is given: ISO metric 0.125·P (60°), Whitworth 0.137·P (55°), else sharp.
    const double rootFactor = angle == 60.0 ? 0.125 : angle == 55.0 ? 0.137329 : 0.0;
    const auto nose = pitch ? r.number("nose_radius", rootFactor * *pitch, true, "mm") : std::nullopt;
    const auto tip = r.tip();
    if (angle && pitch && nose && !r.failed()) {
      take(threadTool(*angle, *pitch, *nose, tip), table, r, tool);
      tool.facts.insertShape = fmt::format("threading insert, pitch {:g} mm", *pitch);
      tool.facts.insertAngleDeg = *angle;
    }
  } else {  // drill
    const auto diameter = r.number("diameter", std::nullopt, false, "mm");
    const auto point = r.number("point_angle", 118.0, false, "degrees");
    const auto length = diameter ? r.number("length", 10.0 * *diameter, false, "mm") : std::nullopt;
    if (diameter && point && length && !r.failed()) {
      take(drillTool(*diameter, *point, *length), table, r, tool);
      tool.facts.insertShape = fmt::format("a Φ{:g} drill, {:g}° point, {:g} mm long", *diameter, *point, *length);
      tool.facts.insertAngleDeg = *point;
    }
  }
  return true;
}

}  // namespace lathesim::setup
