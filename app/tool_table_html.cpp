#include "app/tool_table_html.hpp"

#include <fmt/format.h>

#include "batch/html_text.hpp"

namespace lathesim::app {
namespace {

using Json = nlohmann::ordered_json;
using batch::escaped;

std::string mm(const Json& value, const char* unit = " mm") {
  return value.is_number() ? fmt::format("{:g}{}", value.get<double>(), unit) : std::string("—");
}

std::string text(const Json& value) { return value.is_string() ? escaped(value.get<std::string>()) : "—"; }

std::string stockRow(const Json& s) {
  std::string bar = "Φ" + mm(s.at("diameter_mm"), "") + " × " + mm(s.at("length_mm"));
  if (s.value("bore_mm", 0.0) > 0) bar += ", bore Φ" + mm(s.at("bore_mm"));
  return "<table class=\"stock\">\n<tr><th>bar</th><td>" + bar + "</td><td>" + text(s.at("from")) +
         "</td></tr>\n<tr><th>face</th><td>Z" + mm(s.at("face_z_mm"), "") + "</td><td>" + text(s.at("face_z_from")) +
         "</td></tr>\n<tr><th>material</th><td>" + text(s.at("material")) + "</td><td>" +
         (s.at("material").is_null() ? "not stated" : text(s.at("from"))) + "</td></tr>\n</table>\n";
}

std::string insertCell(const Json& t) {
  std::string cell = t.at("insert").is_string() ? "<b>" + text(t.at("insert")) + "</b> " : "";
  if (t.at("insert_shape").is_string()) cell += text(t.at("insert_shape"));
  if (t.at("cutting_edge_length_mm").is_number()) cell += ", edge " + mm(t.at("cutting_edge_length_mm"));
  if (t.at("insert_angle_deg").is_number()) cell += ", " + mm(t.at("insert_angle_deg"), "°");
  if (cell.empty()) cell = t.value("kind", "") == "polygon" ? "a polygon outline" : "the default outline";
  return cell;
}

std::string holderCell(const Json& t) {
  if (!t.at("holder").is_string()) return "—";
  std::string cell = "<b>" + text(t.at("holder")) + "</b>";
  if (t.at("entering_angle_deg").is_number()) cell += ", κr " + mm(t.at("entering_angle_deg"), "°");
  if (t.at("shank_mm").is_object())
    cell += ", shank " + mm(t.at("shank_mm").at("width"), "") + "×" + mm(t.at("shank_mm").at("height"));
  return cell;
}

std::string offsetsCell(const Json& t) {
  if (t.at("offsets_used").empty()) return "not used";
  std::string cell;
  for (const Json& o : t.at("offsets_used")) {
    cell += (cell.empty() ? "" : "<br>") + text(o.at("t_word")) + " from line <a href=\"#L" +
            std::to_string(o.value("first_line", 0)) + "\">" + std::to_string(o.value("first_line", 0)) + "</a>: ";
    std::string shifts;
    for (const Json& s : o.at("shifts_used"))
      shifts += (shifts.empty() ? "" : ", then ") + fmt::format("X{:+g} Z{:+g}", s.value("x_diameter_mm", 0.0), s.value("z_mm", 0.0));
    cell += shifts + " <span class=\"hint\">(" + text(o.at("from")) + ")</span>";
  }
  return cell;
}

}  // namespace

std::string toolTableHtml(const Json& report) {
  if (!report.contains("tools") || !report.contains("stock")) return "";
  std::string html = "<h2>Stock and tools</h2>\n" + stockRow(report.at("stock"));
  html += "<table class=\"tools\">\n<tr><th>tool</th><th>insert</th><th class=\"num\">nose r</th><th>holder</th>"
          "<th class=\"num\">tip</th><th>offsets used (X diameter, Z as the moves were shifted)</th><th>from</th></tr>\n";
  for (const Json& t : report.at("tools")) {
    html += "<tr><td>T" + fmt::format("{:02d}", t.value("number", 0)) + "</td>";
    if (t.at("kind").is_null()) {
      html += "<td colspan=\"4\">not declared</td>";
    } else {
      html += "<td>" + insertCell(t) + "</td><td class=\"num\">" + mm(t.at("nose_radius_mm")) + "</td><td>" +
              holderCell(t) + "</td><td class=\"num\">" + std::to_string(t.value("tip", 0)) + "</td>";
    }
    html += "<td>" + offsetsCell(t) + "</td><td>" + text(t.at("from")) + "</td></tr>\n";
  }
  return html + "</table>\n";
}

}  // namespace lathesim::app
