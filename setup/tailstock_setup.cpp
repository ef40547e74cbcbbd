#include "setup/tailstock_setup.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace lathesim::setup {
namespace {

std::optional<double> numberAt(const toml::table& table, const char* key, const ReportProblem& report) {
  const toml::node* node = table.get(key);
  if (!node) {
    report(table.source(), std::string("machine.tailstock needs ") + key +
                               " (e.g. tailstock = { z = 0.0, diameter = 30.0 }: the centre's point Z and the "
                               "quill's diameter, mm)");
    return std::nullopt;
  }
  std::optional<double> value;
  if (const auto* i = node->as_integer()) value = static_cast<double>(i->get());
  if (const auto* f = node->as_floating_point()) value = f->get();
  if (!value || !std::isfinite(*value)) {
    report(node->source(), std::string("machine.tailstock.") + key + " must be a number of mm");
    return std::nullopt;
  }
  return value;
}

}  // namespace

double coneEndZMm(const Tailstock& t) {
  return t.pointZMm + t.quillDiameterMm / 2 / std::tan(kCentrePointAngleDeg / 2 * std::numbers::pi / 180);
}

std::vector<ConvexPolygon> tailstockRegions(const Tailstock& t) {
  const double r = t.quillDiameterMm / 2, cone = coneEndZMm(t), end = cone + kQuillLengthPerDiameter * t.quillDiameterMm;
  const std::vector<RZ> centre{{0, t.pointZMm}, {r, cone}, {0, cone}};
  const std::vector<RZ> quill{{0, cone}, {r, cone}, {r, end}, {0, end}};
  return {ConvexPolygon::hullOf(centre), ConvexPolygon::hullOf(quill)};
}

std::optional<Tailstock> readTailstock(const toml::node& node, const ReportProblem& report) {
  const auto* table = node.as_table();
  if (!table) {
    report(node.source(), "machine.tailstock must be a table: tailstock = { z = 0.0, diameter = 30.0 } (the centre's "
                          "point Z and the quill's diameter, mm)");
    return std::nullopt;
  }
  bool ok = true;
  for (auto&& [key, value] : *table)
    if (key.str() != "z" && key.str() != "diameter") {
      report(key.source(), "unknown key 'machine.tailstock." + std::string(key.str()) + "' (expected z, diameter)");
      ok = false;
    }
  const auto z = numberAt(*table, "z", report);
  const auto diameter = numberAt(*table, "diameter", report);
  if (diameter && *diameter <= 0) {
    report(table->get("diameter")->source(), "machine.tailstock.diameter must be a positive number of mm");
    ok = false;
  }
  if (!ok || !z || !diameter) return std::nullopt;
  return Tailstock{*z, *diameter};
}

}  // namespace lathesim::setup
