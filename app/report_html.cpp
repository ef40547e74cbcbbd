#include "app/report_html.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <string_view>
#include <stdexcept>

#include "app/inspection_text.hpp"
#include "app/report_steps.hpp"
#include "app/staged_output.hpp"
#include "app/tool_table_html.hpp"
#include "batch/html_text.hpp"
#include "viewer/viewer_script.hpp"

namespace lathesim::app {
namespace {

using Json = nlohmann::ordered_json;
using batch::escaped;

constexpr const char* kStyle = R"css(
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, Arial, sans-serif; margin: 0; color: #1f2329; background: #f6f7f9; }
header { background: #24313f; color: #fff; padding: 14px 24px; }
header h1 { margin: 0; font-size: 20px; font-weight: 600; }
header p { margin: 4px 0 0; color: #c9d3de; }
main { padding: 16px 24px 40px; max-width: 1400px; }
h2 { font-size: 17px; margin: 26px 0 8px; }
table { border-collapse: collapse; background: #fff; }
th, td { padding: 4px 10px; text-align: left; border-bottom: 1px solid #e3e6ea; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
.figures { display: grid; grid-template-columns: repeat(auto-fill, minmax(190px, 1fr)); gap: 10px; }
.figure { background: #fff; border: 1px solid #dde1e6; border-radius: 6px; padding: 8px 12px; }
.figure .value { font-size: 20px; font-weight: 600; font-variant-numeric: tabular-nums; }
.figure .name { color: #5b6572; font-size: 13px; }
.figure.bad { border-color: #c5221f; background: #fdecea; }
.figure.warn { border-color: #e37400; background: #fff4e5; }
.figure.good { border-color: #1e8e3e; background: #e6f4ea; }
.pictures { display: flex; flex-wrap: wrap; gap: 14px; }
.pictures figure { margin: 0; background: #fff; border: 1px solid #dde1e6; border-radius: 6px; padding: 6px; flex: 1 1 420px; max-width: 680px; }
.pictures img { width: 100%; height: auto; display: block; }
.pictures figcaption { color: #5b6572; font-size: 13px; padding: 4px 2px 0; }
#view3d { width: 100%; height: 520px; background: #f4f6f9; border: 1px solid #dde1e6; border-radius: 6px; position: relative; }
#view3d canvas { display: block; border-radius: 6px; }
.view3d-note { padding: 20px; color: #5b6572; }
.hint { color: #5b6572; font-size: 13px; }
.problem-collision td:first-child { border-left: 4px solid #c5221f; }
.problem-warning td:first-child { border-left: 4px solid #e37400; }
.listing { font: 13px/1.35 ui-monospace, "DejaVu Sans Mono", Menlo, Consolas, monospace; width: 100%; }
.listing td { border-bottom: none; padding: 1px 8px; white-space: pre; }
.listing td.text { width: 100%; }
.listing tr.collision td.no { background: #c5221f; color: #fff; }
.listing tr.warning td.no { background: #e37400; color: #fff; }
.listing td.no { color: #8a939e; text-align: right; }
.listing .bar { display: inline-block; height: 9px; background: #3b6fd8; vertical-align: middle; margin-right: 4px; }
.legend span { display: inline-block; margin-right: 14px; }
.swatch { display: inline-block; width: 12px; height: 12px; vertical-align: -1px; margin-right: 4px; border-radius: 2px; }
)css";

std::string grouped(double value, int decimals) {  // 620 466.2
  std::string text = batch::fixed(std::abs(value), decimals);
  const auto point = text.find('.');
  for (long i = static_cast<long>(point == std::string::npos ? text.size() : point) - 3; i > 0; i -= 3)
    text.insert(static_cast<std::size_t>(i), "\u202f");
  return (value < 0 ? "−" : "") + text;
}

std::string duration(double seconds) {
  const int whole = static_cast<int>(seconds);
  char text[64];
  if (whole >= 3600) std::snprintf(text, sizeof text, "%d:%02d:%04.1f", whole / 3600, whole / 60 % 60, seconds - 60 * (whole / 60));
  else std::snprintf(text, sizeof text, "%d:%04.1f", whole / 60, seconds - 60 * (whole / 60));
  return text;
}

std::string figure(const std::string& name, const std::string& value, const std::string& cls = "") {
  return "<div class=\"figure" + (cls.empty() ? "" : " " + cls) + "\"><div class=\"value\">" + value +
         "</div><div class=\"name\">" + escaped(name) + "</div></div>\n";
}

/// "width=\"W\" height=\"H\"" from a PNG's header, so that the page is laid out before its
/// pictures are decoded (a link to #view3d then lands on the view); empty if it is no PNG.
std::string pngSizeAttributes(const std::string& png) {
  static constexpr char kSignature[] = "\x89PNG\r\n\x1a\n";
  if (png.size() < 24 || png.compare(0, 8, kSignature, 8) != 0 || png.compare(12, 4, "IHDR") != 0) return "";
  auto bigEndian = [&png](std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) value = value << 8 | static_cast<unsigned char>(png[at + i]);
    return value;
  };
  return "width=\"" + std::to_string(bigEndian(16)) + "\" height=\"" + std::to_string(bigEndian(20)) + "\" ";
}

std::string summary(const Json& r) {
  std::string html = "<h2>Summary</h2>\n<div class=\"figures\">\n";
  const double removed = r.value("removed_volume_mm3", 0.0), stock = r.value("stock_volume_mm3", 0.0);
  html += figure("cycle time (machine)", duration(r.value("cycle_time_s", 0.0)));
  html += figure("final volume, mm³", grouped(r.value("final_volume_mm3", 0.0), 1));
  html += figure("removed, mm³ (" + batch::fixed(stock > 0 ? 100 * removed / stock : 0, 1) + " % of the bar)", grouped(removed, 1));
  html += figure("bar volume, mm³", grouped(stock, 1));
  html += figure("STL's own volume, mm³", grouped(r.value("mesh_volume_mm3", 0.0), 1));
  html += figure("moves", std::to_string(r.value("moves", 0)));
  html += figure("voxel, mm", batch::fixed(r.value("voxel_mm", 0.0), 3));
  const std::size_t collisions = r.at("collisions").size(), warnings = r.at("warnings").size();
  html += figure("collisions", std::to_string(collisions), collisions ? "bad" : "good");
  html += figure("warnings", std::to_string(warnings), warnings ? "warn" : "good");
  if (r.contains("check")) {
    const Json& c = r.at("check");
    const std::string verdict = c.value("verdict", "out");
    html += figure("against the drawing", verdict == "within" ? "within tolerance" : verdict == "undecided" ? "UNDECIDED at this voxel" : "OUT OF tolerance",
                   verdict == "within" ? "good" : verdict == "undecided" ? "warn" : "bad");
  }
  return html + "</div>\n";
}

std::string problems(const Json& r) {
  if (r.at("collisions").empty() && r.at("warnings").empty()) return "";
  std::string html = "<h2>Collisions and warnings</h2>\n<table>\n<tr><th>line</th><th>what</th></tr>\n";
  for (const Json& c : r.at("collisions"))
    html += "<tr class=\"problem-collision\"><td><a href=\"#L" + std::to_string(c.value("line", 0)) + "\">" +
            std::to_string(c.value("line", 0)) + "</a></td><td>" +
            (c.value("severity", "error") == "error" ? "crash: " : "collision: ") + escaped(c.value("message", "")) +
            "</td></tr>\n";
  for (const Json& w : r.at("warnings"))
    html += "<tr class=\"problem-warning\"><td><a href=\"#L" + std::to_string(w.value("line", 0)) + "\">" +
            std::to_string(w.value("line", 0)) + "</a></td><td>" + escaped(w.value("message", "")) + "</td></tr>\n";
  return html + "</table>\n";
}

std::string lineLink(int line) {
  return "<a href=\"#L" + std::to_string(line) + "\">" + std::to_string(line) + "</a>";
}

// check.sizes as the text inspection report gives them: each size drawn and measured, its
// tolerance and where that came from, the verdict, and for a size not within, the line that
// made it and the line its X (or Z) came from.
std::string sizesTable(const Json& sizes) {
  if (sizes.empty()) return "";
  std::string html = "<h3>Sizes</h3>\n<table class=\"sizes\">\n<tr><th>size</th><th class=\"num\">drawn</th><th>tolerance</th>"
                     "<th class=\"num\">measured</th><th>at</th><th>verdict</th><th>made by line</th><th>value from line</th></tr>\n";
  for (const Json& s : sizes) {
    const bool face = s.value("kind", "") == "face";
    const std::string sign = face ? "Z" : "Ø";
    const std::string verdict = s.value("verdict", "out");
    const Json& at = s.at("worst_at");
    std::string lines;
    for (const Json& l : s.value("lines", Json::array())) lines += (lines.empty() ? "" : ", ") + lineLink(l.get<int>());
    const int valueLine = s.value("value_line", 0);
    const bool told = verdict != "within";
    const Json& t = s.at("tolerance");
    const std::string limits = limitsText(t.value("upper_mm", 0.0), t.value("lower_mm", 0.0));
    const std::string source = s.value("tolerance_source", "");
    html += std::string("<tr") + (verdict == "out" ? " class=\"problem-collision\"" : verdict == "undecided" ? " class=\"problem-warning\"" : "") +
            "><td>" + escaped(s.value("kind", "")) + " (drawing line " + std::to_string(s.value("drawing_line", 0)) +
            ")</td><td class=\"num\">" + sign + batch::fixed(s.value("nominal_mm", 0.0), 3) + "</td><td>" + escaped(limits) +
            (source == limits ? "" : " (" + escaped(source) + ")") + "</td><td class=\"num\">" +
            (s.value("probed", true) ? sign + batch::fixed(s.value("worst_mm", 0.0), 3) + " ±" + batch::fixed(s.value("uncertainty_mm", 0.0), 3)
                                     : std::string("not measured")) +
            "</td><td>" +
            (face ? "Ø" + batch::fixed(at.value("diameter", 0.0), 3) : "Z" + batch::fixed(at.value("z", 0.0), 3)) + "</td><td>" +
            (verdict == "within" ? "within" : verdict == "undecided" ? "UNDECIDED" : "OUT, " + batch::fixed(s.value("beyond_mm", 0.0), 3) + " beyond") +
            "</td><td>" + (told ? lines : "") + "</td><td>" + (told && valueLine > 0 ? lineLink(valueLine) : "") + "</td></tr>\n";
  }
  return html + "</table>\n";
}

std::string checkSection(const Json& r) {
  if (!r.contains("check")) return "";
  const Json& c = r.at("check");
  std::string html = "<h2>Against the drawing</h2>\n<p>" + escaped(c.value("target", "")) + ": max excess " +
                     batch::fixed(c.value("max_excess_mm", 0.0), 3) + " mm, max gouge " + batch::fixed(c.value("max_gouge_mm", 0.0), 3) +
                     " mm; tolerances as the drawing states them, else " + escaped(c.value("general_tolerance", "")) + ".</p>\n";
  html += sizesTable(c.value("sizes", Json::array()));
  if (c.at("regions").empty()) return html + "<p>No region is out of tolerance.</p>\n";
  html += "<table>\n<tr><th>kind</th><th class=\"num\">max, mm</th><th>at</th><th>Z range</th><th>Ø range</th><th>lines</th></tr>\n";
  for (const Json& g : c.at("regions")) {
    std::string lines;
    for (const Json& l : g.value("lines", Json::array()))
      lines += (lines.empty() ? "" : ", ") + std::string("<a href=\"#L") + std::to_string(l.get<int>()) + "\">" +
               std::to_string(l.get<int>()) + "</a>";
    const Json& at = g.at("at");
    html += "<tr class=\"problem-" + std::string(g.value("kind", "") == "gouge" ? "collision" : "warning") + "\"><td>" +
            escaped(g.value("kind", "")) + "</td><td class=\"num\">" + batch::fixed(g.value("max_mm", 0.0), 3) + "</td><td>Z" +
            batch::fixed(at.value("z", 0.0), 3) + " Ø" + batch::fixed(at.value("diameter", 0.0), 3) + "</td><td>" +
            batch::fixed(g.at("z_range")[0].get<double>(), 2) + " … " + batch::fixed(g.at("z_range")[1].get<double>(), 2) + "</td><td>" +
            batch::fixed(g.at("diameter_range")[0].get<double>(), 2) + " … " + batch::fixed(g.at("diameter_range")[1].get<double>(), 2) +
            "</td><td>" + lines + "</td></tr>\n";
  }
  return html + "</table>\n";
}

/// report.json's threads: each as programmed and as measured (the means over the angles).
std::string threadsSection(const Json& r) {
  if (!r.contains("threads") || r.at("threads").empty()) return "";
  std::string html = "<h2>Threads</h2>\n<table>\n<tr><th>line</th><th>code</th><th>kind</th><th class=\"num\">lead, mm "
                     "(programmed)</th><th>measured</th></tr>\n";
  for (const Json& t : r.at("threads")) {
    const Json& p = t.at("programmed");
    const Json& m = t.at("measured");
    auto mean = [&m](const char* key) { return batch::fixed(m.at(key).value("mean", 0.0), 3); };
    const std::string measured =
        m.contains("problem")
            ? "not measured: " + escaped(m.value("problem", ""))
            : "lead " + batch::fixed(m.at("lead_mm").value("mean", 0.0), 4) + " mm, " + std::to_string(m.value("starts", 0)) +
                  " start(s), " + escaped(m.value("hand", "")) + "-hand, major Ø" + mean("major_diameter_mm") +
                  ", minor Ø" + mean("minor_diameter_mm") + ", pitch Ø" + mean("pitch_diameter_mm");
    const int line = t.value("line", 0);
    html += "<tr><td><a href=\"#L" + std::to_string(line) + "\">" + std::to_string(line) + "</a></td><td>" +
            escaped(t.value("code", "")) + "</td><td>" + escaped(t.value("kind", "")) + "</td><td class=\"num\">" +
            batch::fixed(p.value("lead_mm", 0.0), 4) + "</td><td>" + measured + "</td></tr>\n";
  }
  return html + "</table>\n";
}

struct LineFigures {
  double timeS = 0, removedMm3 = 0;
};

// A row of the listing.
void writeListingRow(std::ostream& out, int line, std::string_view text, const LineFigures* figures, const char* flag,
                     double mostTime, double mostRemoved) {
  std::string time, removed, style;
  if (figures) {
    const LineFigures& f = *figures;
    const int barPx = mostTime > 0 ? static_cast<int>(std::lround(60.0 * f.timeS / mostTime)) : 0;
    time = "<span class=\"bar\" style=\"width:" + std::to_string(barPx) + "px\"></span>" + batch::fixed(f.timeS, 2);
    removed = f.removedMm3 > 0 ? grouped(f.removedMm3, 1) : "";
    if (f.removedMm3 > 0 && mostRemoved > 0)
      style = " style=\"background:rgba(240,140,30," + batch::fixed(0.08 + 0.47 * f.removedMm3 / mostRemoved, 3) + ")\"";
  }
  out << "<tr id=\"L" << line << "\"" << (flag ? std::string(" class=\"") + flag + "\"" : std::string()) << style
      << "><td class=\"no\">" << line << "</td><td class=\"num\">" << time << "</td><td class=\"num\">" << removed
      << "</td><td class=\"text\">" << escaped(std::string(text)) << "</td></tr>\n";
}

// Whether a row is read in step with the text: its line is run once, after every line run once
// before it. The others (a subprogram's lines, a loop's, a line jumped back to) are summed apart.
class InStep {
 public:
  explicit InStep(const sim::MetTwice& repeated) : repeated_(repeated) {}
  bool operator()(const sim::BlockRemoval& row) {
    if (repeated_.has(row.line) || row.line <= last_) return false;
    last_ = row.line;
    return true;
  }

 private:
  const sim::MetTwice& repeated_;
  int last_ = 0;
};

/// The program, one row per source line: its number, text, machine time and removed volume
/// (its blocks' sums), a bar for the time and a warm tint for the removal; lines with a
/// collision or a warning flagged at their number. Three passes over the rows.
void writeListing(std::ostream& out, const Json& r, const sim::BlockRows& blocks, const interp::PagedText& programText) {
  sim::MetTwice repeated;
  blocks.forEach([&](const sim::BlockRemoval& b) { repeated.note(b.line); });
  std::map<int, LineFigures> apart;
  double mostTime = 0, mostRemoved = 0;
  InStep sums(repeated);
  blocks.forEach([&](const sim::BlockRemoval& b) {
    if (sums(b)) {
      mostTime = std::max(mostTime, b.timeS), mostRemoved = std::max(mostRemoved, b.removedMm3);
      return;
    }
    LineFigures& f = apart[b.line];
    f.timeS += b.timeS;
    f.removedMm3 += b.removedMm3;
  });
  for (const auto& [line, f] : apart) mostTime = std::max(mostTime, f.timeS), mostRemoved = std::max(mostRemoved, f.removedMm3);
  std::map<int, const char*> flags;
  for (const Json& w : r.at("warnings")) flags[w.value("line", 0)] = "warning";
  for (const Json& c : r.at("collisions")) flags[c.value("line", 0)] = "collision";

  out << "<h2>Program</h2>\n<p class=\"legend\"><span><span class=\"swatch\" style=\"background:#3b6fd8\"></span>machine time"
         "</span><span><span class=\"swatch\" style=\"background:rgba(240,140,30,.55)\"></span>material removed (the deeper, "
         "the more)</span><span><span class=\"swatch\" style=\"background:#c5221f\"></span>collision</span><span><span "
         "class=\"swatch\" style=\"background:#e37400\"></span>warning</span></p>\n<table class=\"listing\">\n"
         "<tr><th class=\"num\">line</th><th class=\"num\">time, s</th><th class=\"num\">removed, mm³</th><th>program</th></tr>\n";
  const std::string_view text = programText.view();
  std::size_t begin = 0;
  int line = 0;
  // The text's lines up to `last` (all: -1), the last with `figures` if given.
  const auto writeLines = [&](int last, const LineFigures* figures) {
    while (begin < text.size() && line != last) {
      programText.readingAt(begin);
      std::size_t end = text.find('\n', begin);
      if (end == std::string_view::npos) end = text.size();
      std::string_view lineText = text.substr(begin, end - begin);
      if (!lineText.empty() && lineText.back() == '\r') lineText.remove_suffix(1);
      begin = end + 1;
      ++line;
      const auto summed = apart.find(line);
      const LineFigures* f = line == last ? figures : summed != apart.end() ? &summed->second : nullptr;
      const auto flag = flags.find(line);
      writeListingRow(out, line, lineText, f, flag != flags.end() ? flag->second : nullptr, mostTime, mostRemoved);
    }
  };
  InStep rows(repeated);
  blocks.forEach([&](const sim::BlockRemoval& b) {
    if (!rows(b)) return;
    const LineFigures figures{b.timeS, b.removedMm3};
    writeLines(b.line, &figures);
  });
  writeLines(-1, nullptr);
  out << "</table>\n";
}

}  // namespace

void writeReportHtml(const Json& report, const sim::BlockRows& blocks, const interp::PagedText& programText,
                     const std::vector<HtmlPicture>& pictures, bool video, const std::string& glb, const Json& steps,
                     const std::filesystem::path& html) {
  const std::string program = report.value("program", "");
  writeTextFile(html, [&](std::ostream& out) {
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>lathesim: "
        << escaped(program) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<header><h1>" << escaped(program)
        << "</h1><p>setup " << escaped(report.value("setup", "")) << " · voxel " << batch::fixed(report.value("voxel_mm", 0.0), 3)
        << " mm"
        << (report.contains("at_line") ? " · stopped after line " + std::to_string(report.value("at_line", 0)) : "")
        << "</p></header>\n<main>\n";
    out << summary(report) << problems(report) << toolTableHtml(report);
    // The part in 3D first, where the page opens; the pictures and the drawing check below.
    if (!glb.empty()) {
      out << "<h2>3D view</h2>\n<div id=\"view3d\" data-state=\"loading\"></div>\n<p class=\"hint\">The part and its "
             "toolpath (feeds blue, rapids red). Drag to turn, scroll to zoom, right-drag to move.</p>\n";
      // The red markers the model holds (render::partGlb), each named.
      for (const Json& c : report.at("collisions")) {
        const Json& at = c.at("position");
        out << "<p class=\"crash-mark\"><span class=\"swatch\" style=\"background:#ff0000\"></span> crash, line "
            << c.value("line", 0) << ": the red marker at X" << batch::fixed(at.value("x_diameter_mm", 0.0), 3) << " Z"
            << batch::fixed(at.value("z_mm", 0.0), 3) << " (" << escaped(c.value("message", "")) << ")</p>\n";
      }
    }
    const std::string stepping = stepSection(steps, report);
    out << stepping;
    if (!pictures.empty()) {
      out << "<h2>Pictures</h2>\n<div class=\"pictures\">\n";
      for (const HtmlPicture& p : pictures) {
        const std::string bytes = batch::fileBytes(p.png);
        if (bytes.empty()) throw std::runtime_error("cannot read " + p.png.string() + " for report.html");
        out << "<figure><img " << pngSizeAttributes(bytes) << "alt=\"" << escaped(p.caption) << "\" src=\"data:image/png;base64,"
            << batch::base64(bytes) << "\"><figcaption>" << escaped(p.caption) << "</figcaption></figure>\n";
      }
      out << "</div>\n";
    }
    if (video)  // beside the page, as the run wrote it: too large to carry inside
      out << "<h2>The cut</h2>\n<video controls preload=\"metadata\" src=\"cut.mp4\" style=\"max-width:100%\"></video>\n"
             "<p class=\"hint\"><a href=\"cut.mp4\">cut.mp4</a>, beside this page.</p>\n";
    out << threadsSection(report) << checkSection(report);
    writeListing(out, report, blocks, programText);
    out << "</main>\n";
    if (!stepping.empty() && !steps.is_null()) out << stepScript();
    if (!glb.empty()) out << "<script type=\"application/octet-stream\" id=\"part-model\">" << batch::base64(glb)
                          << "</script>\n<script>" << viewer::viewerScript() << "</script>\n";
    out << "</body>\n</html>\n";
  });
}

}  // namespace lathesim::app
