#include "batch/summary_html.hpp"

#include "batch/html_text.hpp"
#include "batch/number_text.hpp"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace lathesim::batch {
namespace {

/// A relative path as it goes into an href: '/'-separated, each part percent-encoded.
std::string href(const std::filesystem::path& path) {
  std::string url;
  for (unsigned char c : path.generic_string()) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      url += static_cast<char>(c);
    } else {
      char code[4];
      std::snprintf(code, sizeof code, "%%%02X", c);
      url += code;
    }
  }
  return url;
}

/// A table cell sorted by `value` (empty: sorts last), showing `html`.
std::string cell(const std::string& value, const std::string& html, const std::string& cls = "") {
  return "<td" + (cls.empty() ? std::string() : " class=\"" + cls + "\"") + " data-value=\"" + escaped(value) + "\">" +
         html + "</td>";
}

std::string numberCell(const std::optional<double>& value, int decimals, const std::string& cls = "num") {
  return value ? cell(shortestText(*value), fixed(*value, decimals), cls) : cell("", "", cls);
}

/// Worst last when sorted ascending: the order a teacher scans a class in.
int statusRank(JobStatus status) {
  switch (status) {
    case JobStatus::Ok: return 0;
    case JobStatus::OutOfTolerance: return 1;
    case JobStatus::Collision: return 2;
    case JobStatus::Timeout: return 3;
    case JobStatus::Failed: return 4;
    case JobStatus::Crashed: return 5;
    case JobStatus::NotRun: return 6;
  }
  return 6;
}

std::string statusLabel(JobStatus status) {
  switch (status) {
    case JobStatus::Ok: return "ok";
    case JobStatus::OutOfTolerance: return "out of tolerance";
    case JobStatus::Collision: return "collision";
    case JobStatus::Failed: return "failed";
    case JobStatus::Timeout: return "time limit";
    case JobStatus::Crashed: return "crashed";
    case JobStatus::NotRun: return "not run";
  }
  return "";
}

std::string messageHtml(const JobResult& r) {
  if (!r.message) return "";
  const JobMessage& m = *r.message;
  std::string where;
  if (m.line > 0) {
    where = "line " + std::to_string(m.line);
    if (m.column > 0) where.append(":").append(std::to_string(m.column));
    where += ' ';
  }
  // A long message is cut to a few lines so that one row does not fill the screen; the whole
  // of it shows on hover (and in the job's report).
  std::string html = "<div class=\"clamp\" title=\"" + escaped(where + m.kind + ": " + m.text) + "\"><span class=\"" +
                     m.kind + "\">" + escaped(where + m.kind + ": ") + "</span>" + escaped(m.text) + "</div>";
  if (m.kind == "warning" && r.warnings > 1)
    html += "<span class=\"more\">(+" + std::to_string(r.warnings - 1) + " more)</span>";
  return html;
}

std::string pictureHtml(const JobResult& r, const std::filesystem::path& folder) {
  if (!r.thumbnail) return "";
  const std::string png = fileBytes(folder / r.folder / *r.thumbnail);
  if (png.empty()) return "";
  const std::string full = r.command == "check" ? "deviation.png" : "part.png";
  return "<a href=\"" + href(std::filesystem::path(r.folder) / full) + "\"><img alt=\"" + escaped(r.name) +
         "\" src=\"data:image/png;base64," + base64(png) + "\"></a>";
}

std::string row(const JobResult& r, const std::filesystem::path& folder) {
  std::string html = "<tr>";
  html += cell(std::to_string(r.index + 1), std::to_string(r.index + 1), "num");
  html += cell("", pictureHtml(r, folder), "picture");
  html += cell(r.name, "<a href=\"" + href(std::filesystem::path(r.folder)) + "/\">" + escaped(r.name) +
                           "</a><div class=\"path\">" + escaped(r.program) + "</div>");
  html += cell(std::to_string(statusRank(r.status)),
               "<span class=\"badge " + std::string(statusName(r.status)) + "\">" + statusLabel(r.status) + "</span>");
  html += cell(r.message ? r.message->text : "", messageHtml(r), "message");
  html += numberCell(r.finalVolumeMm3, 1);
  html += numberCell(r.removedVolumeMm3, 1);
  html += numberCell(r.cycleTimeS, 1);
  const bool ran = r.finalVolumeMm3.has_value();
  const int collisions = static_cast<int>(r.collisions.size());
  html += ran ? cell(std::to_string(collisions), std::to_string(collisions), collisions ? "num bad" : "num")
              : cell("", "", "num");
  // The piece that fell: its volume, and the Z and line of the cut that parted it.
  html += r.partedOff ? cell(shortestText(r.partedOff->volumeMm3),
                             fixed(r.partedOff->volumeMm3, 1) + "<div class=\"path\">Z" + fixed(r.partedOff->zMm, 3) +
                                 ", line " + std::to_string(r.partedOff->line) + "</div>",
                             "num")
                      : cell("", "", "num");
  const CheckFigures* c = r.check ? &*r.check : nullptr;
  const auto beyond = [&](double mm) { return c && mm > c->toleranceMm ? "num bad" : "num"; };
  html += c ? numberCell(c->maxGougeMm, 3, beyond(c->maxGougeMm)) : cell("", "", "num");
  html += c ? numberCell(c->maxExcessMm, 3, beyond(c->maxExcessMm)) : cell("", "", "num");
  html += c ? numberCell(c->toleranceMm, 3) : cell("", "", "num");
  html += numberCell(r.elapsedS, 1);
  return html + "</tr>\n";
}

constexpr const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.3em; margin: 0 0 .2em; }
p.counts { margin: 0 0 1em; }
table { border-collapse: collapse; }
th, td { padding: .35em .6em; border-bottom: 1px solid #ddd; text-align: left; vertical-align: middle; }
th { background: #f3f3f3; cursor: pointer; user-select: none; white-space: nowrap; position: sticky; top: 0; }
th[aria-sort=ascending]::after { content: " \25B2"; }
th[aria-sort=descending]::after { content: " \25BC"; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.bad { color: #b00020; font-weight: 600; }
td.message { max-width: 28em; }
.clamp { display: -webkit-box; -webkit-box-orient: vertical; -webkit-line-clamp: 4; overflow: hidden; }
.path { color: #777; font-size: .85em; }
.error { color: #b00020; font-weight: 600; }
.warning { color: #8a5a00; font-weight: 600; }
.more { color: #777; }
.badge { display: inline-block; padding: .1em .5em; border-radius: .8em; color: #fff; white-space: nowrap; }
.badge.ok { background: #1e8e3e; }
.badge.out_of_tolerance { background: #e37400; }
.badge.failed, .badge.crashed, .badge.timeout, .badge.collision { background: #c5221f; }
.badge.not_run { background: #777; }
td.picture img { width: 160px; display: block; }
td.picture { padding: 2px; }
)";

// Sorts the rows by a column: numbers as numbers, blanks last either way, ties by place.
constexpr const char* kScript = R"(
(function () {
  var table = document.getElementById('jobs');
  var body = table.tBodies[0];
  var heads = Array.prototype.slice.call(table.tHead.rows[0].cells);
  function sortBy(key, descending) {
    var column = heads.findIndex(function (h) { return h.dataset.key === key; });
    if (column < 0) return;
    var numeric = heads[column].dataset.type === 'number';
    var rows = Array.prototype.slice.call(body.rows);
    function value(row) { return row.cells[column].dataset.value; }
    function place(row) { return Number(row.cells[0].dataset.value); }
    rows.sort(function (a, b) {
      var x = value(a), y = value(b);
      if (x === '' || y === '') return x === y ? place(a) - place(b) : (x === '' ? 1 : -1);
      var order = numeric ? Number(x) - Number(y) : x.localeCompare(y);
      if (descending) order = -order;
      return order !== 0 ? order : place(a) - place(b);
    });
    rows.forEach(function (row) { body.appendChild(row); });
    heads.forEach(function (h) { h.removeAttribute('aria-sort'); });
    heads[column].setAttribute('aria-sort', descending ? 'descending' : 'ascending');
  }
  function sortFromAddress() {
    var match = /^#sort=(-?)([a-z0-9_]+)$/.exec(window.location.hash);
    if (match) sortBy(match[2], match[1] === '-');
  }
  heads.forEach(function (h) {
    if (!h.dataset.key) return;
    function choose() {
      var descending = h.getAttribute('aria-sort') === 'ascending';
      window.location.hash = 'sort=' + (descending ? '-' : '') + h.dataset.key;
    }
    h.tabIndex = 0;
    h.addEventListener('click', choose);
    h.addEventListener('keydown', function (e) { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); choose(); } });
  });
  window.addEventListener('hashchange', sortFromAddress);
  sortFromAddress();
})();
)";

}  // namespace

void writeSummaryHtml(const BatchSummary& s, const std::filesystem::path& folder, std::ostream& out) {
  const std::string title = "lathesim batch: " + s.source + (s.shard.whole() ? "" : " (shard " + s.shard.tag() + ")");
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << escaped(title)
      << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>" << escaped(title) << "</h1>\n"
      << "<p class=\"counts\">" << s.jobs.size() << " programs: " << escaped(s.countsText()) << ". Exit status "
      << s.exitStatus() << ". lathesim " << escaped(s.version) << ".</p>\n"
      << "<table id=\"jobs\">\n<thead><tr>";
  const std::pair<const char*, const char*> headings[] = {
      {"index", "#"},
      {"picture", "part"},
      {"name", "program"},
      {"status", "status"},
      {"message", "error or first warning"},
      {"final_volume_mm3", "final volume mm³"},
      {"removed_volume_mm3", "removed mm³"},
      {"cycle_time_s", "cycle time s"},
      {"collisions", "collisions"},
      {"parted_off_volume_mm3", "parted off mm³"},
      {"max_gouge_mm", "max gouge mm"},
      {"max_excess_mm", "max excess mm"},
      {"tolerance_mm", "tolerance mm"},
      {"elapsed_s", "run s"}};
  for (const auto& [key, label] : headings) {
    const std::string k = key;
    if (k == "picture") {
      out << "<th>" << label << "</th>";  // not sortable
      continue;
    }
    const bool text = k == "name" || k == "message";
    out << "<th data-key=\"" << k << "\" data-type=\"" << (text ? "text" : "number") << "\">" << label << "</th>";
  }
  out << "</tr></thead>\n<tbody>\n";
  for (const auto& job : s.jobs) out << row(job, folder);
  out << "</tbody>\n</table>\n<script>" << kScript << "</script>\n</body>\n</html>\n";
}

}  // namespace lathesim::batch
