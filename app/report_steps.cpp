#include "app/report_steps.hpp"

#include "app/step_recording.hpp"

namespace lathesim::app {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kMarkup = R"html(
<h2 id="steps">Step through the program</h2>
<style>
#step-view { display: grid; grid-template-columns: minmax(0, 3fr) minmax(260px, 2fr); gap: 12px; }
#step-canvas { width: 100%; height: 420px; background: #fff; border: 1px solid #dde1e6; border-radius: 6px; display: block; }
#step-controls { display: flex; gap: 6px; align-items: center; flex-wrap: wrap; margin: 8px 0; }
#step-track { flex: 1 1 300px; position: relative; }
#step-track input[type=range] { width: 100%; margin: 0; }
#step-marks { position: absolute; left: 8px; right: 8px; top: 100%; height: 6px; }
#step-marks span { position: absolute; width: 3px; height: 6px; margin-left: -1px; }
#step-controls button { font: inherit; padding: 2px 10px; }
#step-info { background: #fff; border: 1px solid #dde1e6; border-radius: 6px; padding: 8px 12px; font-size: 14px; }
#step-info table { width: 100%; }
#step-lines { font: 13px/1.35 ui-monospace, "DejaVu Sans Mono", Menlo, Consolas, monospace; white-space: pre; overflow: hidden; margin-top: 8px; }
#step-lines div.current, .listing tr.current td { background: #fff3b0; }
.listing tr { cursor: pointer; }
</style>
<div id="step-controls">
  <button id="step-first" title="first block (Home)">|◀</button><button id="step-back" title="previous block (←)">◀</button>
  <span id="step-track"><input type="range" id="step-slider" min="0" value="0" aria-label="block"><span id="step-marks"></span></span>
  <button id="step-next" title="next block (→)">▶</button><button id="step-last" title="last block (End)">▶|</button>
  <button id="step-cut">next cut</button><button id="step-collision">next collision</button><button id="step-warning">next warning</button>
</div>
<div id="step-view">
  <canvas id="step-canvas"></canvas>
  <div id="step-info"><div id="step-title"></div><table id="step-figures"></table><div id="step-lines"></div></div>
</div>
<p class="hint" id="step-hint">The stock's section (at C0, both sides of the axis) after the block, the toolpath so far (feeds blue, rapids red, this block's bold) and the tool where the block leaves it. The 3D view above shows the finished part.</p>
)html";

constexpr const char* kScript = R"js(
(function () {
  const data = JSON.parse(document.getElementById('step-data').textContent);
  const steps = data.steps, sections = data.sections, path = data.path;
  // A long program's step covers several blocks (data.blocks_per_step, the last fewer): lines s[0] to s[11].
  const perStep = data.blocks_per_step;
  const linesOf = s => {
    if (s[11] === s[0]) return [s[0]];
    if (s[11] < s[0] || s[11] - s[0] > 1000) return [s[0], s[11]];  // through a subprogram: its ends
    return Array.from({ length: s[11] - s[0] + 1 }, (_, i) => s[0] + i);
  };
  const covers = (s, lines) => linesOf(s).some(l => lines.has(l));
  const slider = document.getElementById('step-slider');
  const canvas = document.getElementById('step-canvas');
  slider.max = String(steps.length - 1);
  // Running totals: time and removed volume up to and with each step.
  const timeSoFar = [], removedSoFar = [];
  steps.reduce((acc, s, i) => { acc[0] += s[4]; acc[1] += s[3]; timeSoFar[i] = acc[0]; removedSoFar[i] = acc[1]; return acc; }, [0, 0]);
  // Sections are kept as changes from the one before: decoded in order, as far as asked.
  const decoded = [];
  function pairs(flat, out) { for (let i = 0; i < flat.length; i += 2) out.push([flat[i] / 1000, flat[i + 1] / 1000]); }
  function section(index) {
    while (decoded.length <= index) {
      const before = decoded.length ? decoded[decoded.length - 1] : [];
      decoded.push(sections[decoded.length][1].map(([from, head, tail, middle]) => {
        const points = [];
        const old = from >= 0 ? before[from] : [];
        for (let i = 0; i < head; i++) points.push(old[i]);
        pairs(middle, points);
        for (let i = old.length - tail; i < old.length && from >= 0; i++) points.push(old[i]);
        return points;
      }));
    }
    return decoded[index];
  }
  function sectionAfter(step) {  // the last section taken at or before the step's end
    const end = steps[step][2];
    let low = 0, high = sections.length - 1;
    while (low < high) { const mid = (low + high + 1) >> 1; if (sections[mid][0] <= end) low = mid; else high = mid - 1; }
    return low;
  }
  // Moves as [kind, r, z, (centre r, z)], from the flat path.
  const moves = [];
  for (let i = 0; i < path.length;) {
    const kind = path[i], arc = kind === 2 || kind === 3;
    moves.push(arc ? [kind, path[i + 1] / 1000, path[i + 2] / 1000, path[i + 3] / 1000, path[i + 4] / 1000]
                   : [kind, path[i + 1] / 1000, path[i + 2] / 1000]);
    i += arc ? 5 : 3;
  }
  // The frame: the bar, the toolpath and the start position.
  let zMin = Infinity, zMax = -Infinity, rMax = 0;
  const widen = (r, z) => { zMin = Math.min(zMin, z); zMax = Math.max(zMax, z); rMax = Math.max(rMax, Math.abs(r)); };
  section(0).forEach(line => line.forEach(([r, z]) => widen(r, z)));
  moves.forEach(m => widen(m[1], m[2]));
  widen(data.start[0] / 1000, data.start[1] / 1000);
  const listingRows = new Map();
  document.querySelectorAll('.listing tr[id^="L"]').forEach(row => listingRows.set(Number(row.id.slice(1)), row));
  const lineText = line => { const row = listingRows.get(line); return row ? row.lastElementChild.textContent : ''; };
  let current = 0;

  function draw(step) {
    const ratio = window.devicePixelRatio || 1;
    const width = canvas.clientWidth, height = canvas.clientHeight;
    canvas.width = width * ratio; canvas.height = height * ratio;
    const g = canvas.getContext('2d');
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.clearRect(0, 0, width, height);
    const margin = 16, spanZ = Math.max(zMax - zMin, 1e-3), spanR = Math.max(2 * rMax, 1e-3);
    const scale = Math.min((width - 2 * margin) / spanZ, (height - 2 * margin) / spanR);
    const x = z => margin + (z - zMin) * scale + (width - 2 * margin - spanZ * scale) / 2;
    const y = r => height / 2 - r * scale;
    g.strokeStyle = '#8a939e'; g.setLineDash([6, 4]); g.beginPath(); g.moveTo(0, y(0)); g.lineTo(width, y(0)); g.stroke(); g.setLineDash([]);
    const trace = (line, side) => line.forEach(([r, z], i) => (i ? g.lineTo(x(z), y(side * r)) : g.moveTo(x(z), y(side * r))));
    // A polyline that comes back to its start (a bored section) is drawn on each side of the
    // axis; one from the axis to the axis goes out above it and back below.
    const outline = (lines, fill, stroke) => {
      g.beginPath();
      for (const line of lines) {
        if (line.length < 2) continue;
        const [r0, z0] = line[0], [r1, z1] = line[line.length - 1];
        if (r0 === r1 && z0 === z1) {
          for (const side of [1, -1]) { trace(line, side); g.closePath(); }
        } else {
          trace(line, 1);
          for (let i = line.length - 1; i >= 0; i--) g.lineTo(x(line[i][1]), y(-line[i][0]));
          g.closePath();
        }
      }
      if (fill) { g.fillStyle = fill; g.fill('evenodd'); }
      if (stroke) { g.strokeStyle = stroke; g.lineWidth = 1.2; g.stroke(); }
    };
    outline(section(0), null, '#c9d3de');
    outline(section(sectionAfter(step)), 'rgba(150,160,172,0.55)', '#44505e');
    const end = steps[step][2], first = steps[step][1];
    let r0 = data.start[0] / 1000, z0 = data.start[1] / 1000;
    for (let m = 0; m < end && m < moves.length; m++) {
      const [kind, r, z] = moves[m];
      g.lineWidth = m >= first ? 2.5 : 1;
      g.strokeStyle = kind === 0 ? 'rgba(197,34,31,0.7)' : 'rgba(59,111,216,0.8)';
      g.setLineDash(kind === 0 ? [4, 3] : []);
      g.beginPath(); g.moveTo(x(z0), y(r0));
      if (kind === 2 || kind === 3) {  // on screen r is up and z right, as the arc's plane
        const cr = moves[m][3], cz = moves[m][4], radius = Math.hypot(r - cr, z - cz) * scale;
        const a0 = Math.atan2(-(r0 - cr), z0 - cz), a1 = Math.atan2(-(r - cr), z - cz);
        g.arc(x(cz), y(cr), radius, a0, a1, kind === 3);
      } else g.lineTo(x(z), y(r));
      g.stroke();
      r0 = r; z0 = z;
    }
    g.setLineDash([]);
    const tool = data.tools[String(steps[step][10])];
    const tipR = steps[step][5] / 1000, tipZ = steps[step][6] / 1000;
    if (tool) for (const [part, fill] of [['holder', '#9aa3ad'], ['insert', '#d4a017']]) {
      const p = tool[part];
      if (p.length < 6) continue;
      g.beginPath();
      for (let i = 0; i < p.length; i += 2) {
        const px = x(tipZ + p[i + 1] / 1000), py = y(tipR + p[i] / 1000);
        i ? g.lineTo(px, py) : g.moveTo(px, py);
      }
      g.closePath(); g.fillStyle = fill; g.fill(); g.strokeStyle = '#333'; g.lineWidth = 0.8; g.stroke();
    }
  }

  function show(step) {
    current = Math.max(0, Math.min(steps.length - 1, step));
    slider.value = String(current);
    const [line, , , removed, time, r, z, feed, spindle, rpm, tool] = steps[current];
    const lastLine = steps[current][11], blocks = steps[current][12];
    document.getElementById('step-title').textContent = perStep === 1
        ? 'block ' + (current + 1) + ' of ' + steps.length + ', line ' + line + ':  ' + lineText(line).trim()
        : 'step ' + (current + 1) + ' of ' + steps.length + ': blocks ' + (current * perStep + 1) + '–' +
          (current * perStep + blocks) + ', lines ' + line + '–' + lastLine + ' (' + perStep + ' blocks a step)';
    const rows = [['removed', removed.toFixed(1) + ' mm³', removedSoFar[current].toFixed(1) + ' mm³ so far'],
                  ['time', time.toFixed(2) + ' s', timeSoFar[current].toFixed(2) + ' s so far'],
                  ['feed', feed ? String(feed) : '—', ''], ['S', String(spindle), Math.round(rpm) + ' rpm at the end'],
                  ['tool', 'T' + String(tool).padStart(2, '0'), ''],
                  ['ends at', 'X' + (2 * r / 1000).toFixed(3) + ' Z' + (z / 1000).toFixed(3), '']];
    // A long program's sections are thinned (to keep the run fast): say which block's is shown.
    const taken = sections[sectionAfter(current)][0];
    let before = current;
    while (before >= 0 && steps[before][2] > taken) before--;
    let cutSince = false;
    for (let s = before + 1; s <= current; s++) cutSince = cutSince || steps[s][3] > 0;
    if (cutSince) rows.push(['section', 'as after ' + (perStep === 1 ? 'block ' : 'step ') + (before + 1), 'sections thinned in a long run']);
    const figures = document.getElementById('step-figures');
    figures.replaceChildren(...rows.map(cells => {
      const tr = document.createElement('tr');
      cells.forEach(text => { const td = document.createElement('td'); td.textContent = text; tr.append(td); });
      return tr;
    }));
    const around = document.getElementById('step-lines');
    around.replaceChildren();
    const shownLines = linesOf(steps[current]), last = shownLines[shownLines.length - 1];
    for (let l = Math.max(1, last - 3); l <= last + 3; l++) {
      if (!listingRows.has(l)) continue;
      const div = document.createElement('div');
      div.textContent = String(l).padStart(5) + '  ' + lineText(l);
      if (shownLines.includes(l)) div.className = 'current';
      around.append(div);
    }
    document.querySelectorAll('.listing tr.current').forEach(row => row.classList.remove('current'));
    for (const l of shownLines) { const row = listingRows.get(l); if (row) row.classList.add('current'); }
    history.replaceState(null, '', '#step=' + (current + 1));
    draw(current);
  }

  const collisionLines = new Set(data.collision_lines), warningLines = new Set(data.warning_lines);
  function nextWhere(test) {
    for (let s = current + 1; s < steps.length; s++) if (test(steps[s])) return show(s);
  }
  slider.addEventListener('input', () => show(Number(slider.value)));
  document.getElementById('step-first').onclick = () => show(0);
  document.getElementById('step-back').onclick = () => show(current - 1);
  document.getElementById('step-next').onclick = () => show(current + 1);
  document.getElementById('step-last').onclick = () => show(steps.length - 1);
  document.getElementById('step-cut').onclick = () => nextWhere(s => s[3] > 0);
  document.getElementById('step-collision').onclick = () => nextWhere(s => covers(s, collisionLines));
  document.getElementById('step-warning').onclick = () => nextWhere(s => covers(s, warningLines));
  document.addEventListener('keydown', event => {
    if (event.target === slider || event.target.tagName === 'INPUT' || event.altKey || event.ctrlKey || event.metaKey) return;
    const to = { ArrowLeft: current - 1, ArrowRight: current + 1, Home: 0, End: steps.length - 1 }[event.key];
    if (to === undefined) return;
    event.preventDefault();
    show(to);
  });
  listingRows.forEach((row, line) => row.addEventListener('click', () => {
    const at = steps.findIndex(s => Math.max(s[0], s[11]) >= line);
    show(at < 0 ? steps.length - 1 : at);
  }));
  window.addEventListener('resize', () => draw(current));
  // Collisions red and warnings amber under the slider, each where its first block is.
  const marks = document.getElementById('step-marks');
  for (const [lines, color, what] of [[warningLines, '#e37400', 'warning'], [collisionLines, '#c5221f', 'collision']])
    steps.forEach((s, i) => {
      if (!covers(s, lines) || (i > 0 && steps[i - 1][0] === s[0])) return;
      const mark = document.createElement('span');
      mark.style.left = (steps.length > 1 ? 100 * i / (steps.length - 1) : 0) + '%';
      mark.style.background = color;
      mark.title = what + ', line ' + linesOf(s).find(l => lines.has(l));
      mark.className = 'mark-' + what;
      marks.append(mark);
    });
  // report.html#measure: the median time of 100 redraws, written on the view (for the tests).
  if (location.hash === '#measure') {
    const times = [];
    for (let i = 0; i < 100; i++) {
      const started = performance.now();
      show(Math.floor(i * (steps.length - 1) / 99));
      times.push(performance.now() - started);
    }
    times.sort((a, b) => a - b);
    document.getElementById('step-view').dataset.redrawMs = ((times[49] + times[50]) / 2).toFixed(2);
  }
  const asked = /#step=(\d+)/.exec(location.hash);
  show(asked ? Number(asked[1]) - 1 : steps.length - 1);
})();
)js";

}  // namespace

std::string stepSection(const Json& steps, const Json& report) {
  if (steps.is_null() || steps.at("steps").empty()) return "";
  // A long program's steps cover several blocks each, and its toolpath may be left out: said
  // plainly above the slider, never shown as if block by block.
  std::string notes;
  const std::size_t perStep = steps.value("blocks_per_step", std::size_t{1});
  if (perStep > 1)
    notes += "<p class=\"hint\" id=\"step-merged\">Each step here covers " + std::to_string(perStep) +
             " blocks (the last may cover fewer): the program runs more than " + std::to_string(StepRecording::kMaxSteps) +
             " blocks, so neighbouring blocks are stepped through together; a step's removed volume and time are "
             "its blocks' sums, and it shows the stock and the tool as its last block leaves them.</p>\n";
  if (steps.value("path_left_out", false))
    notes += "<p class=\"hint\" id=\"step-no-path\">The toolpath is not drawn here: the program makes more than " +
             std::to_string(StepRecording::kMaxMoves) + " moves, too many to keep while it runs.</p>\n";
  Json data = steps;
  Json collisions = Json::array(), warnings = Json::array();
  for (const Json& c : report.at("collisions")) collisions.push_back(c.value("line", 0));
  for (const Json& w : report.at("warnings")) warnings.push_back(w.value("line", 0));
  data["collision_lines"] = collisions;
  data["warning_lines"] = warnings;
  std::string json = data.dump();
  // Inside a script element only "</" could end it early.
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at + 2)) json.replace(at, 2, "<\\/");
  return std::string(kMarkup) + notes + "<script type=\"application/json\" id=\"step-data\">" + json + "</script>\n";
}

std::string stepScript() { return std::string("<script>") + kScript + "</script>\n"; }

}  // namespace lathesim::app
