// lathesim check: simulate a program, then measure the part against its drawing (see
// deviation.hpp for how), attribute each gouge to the moves that cut it, and write the run's
// files plus the deviation pictures and report.json's "check" section.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "app/printed_diagnostics.hpp"
#include "batch/html_text.hpp"
#include "interp/base/printable_text.hpp"
#include "measure/deviation.hpp"
#include "measure/drawing.hpp"
#include "measure/gouge_causes.hpp"
#include "measure/profile_limits.hpp"
#include "measure/size_check.hpp"
#include "measure/surface_causes.hpp"
#include "app/inspection_text.hpp"
#include "measure/process_figures.hpp"
#include "measure/thread_check.hpp"
#include "app/run_pipeline.hpp"
#include "geometry/mesh_slice.hpp"
#include "render/deviation_image.hpp"
#include "render/scene_export.hpp"
#include "render/stl_reader.hpp"

namespace lathesim::app {
namespace {

using Json = nlohmann::ordered_json;

/// The drawing's outline from a profile file, or nullopt with the diagnostics printed; the
/// rest of the file (lines, tolerances, callouts) into `file`.
std::optional<MeridianProfile> loadProfile(const std::filesystem::path& path, measure::DrawingResult& file) {
  file = measure::loadDrawing(path);
  printDiagnostics(file.diagnostics);
  if (!file.outline) return std::nullopt;
  return MeridianProfile::fromPolygon(*file.outline);
}

/// The drawing's outline from an STL of the design: its section in the meridian half-plane.
std::optional<MeridianProfile> loadStl(const std::filesystem::path& file) {
  render::StlRead read = render::readStl(file);
  if (!read.mesh) {
    std::cerr << interp::printable(file.string()) << ": error: " << interp::printable(read.problem) << '\n';
    return std::nullopt;
  }
  std::vector<Segment> slice = meridianSlice(*read.mesh);
  if (slice.empty()) {
    std::cerr << interp::printable(file.string()) << ": error: the design does not cross the half-plane y = 0, x ≥ 0; a turned part's "
              << "STL must have its axis along Z through the origin\n";
    return std::nullopt;
  }
  return MeridianProfile::fromSurface(std::move(slice));
}

bool isStl(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".stl";
}

std::string targetKind(const CheckOptions& options) {
  if (!options.drawing) return "program";
  return isStl(*options.drawing) ? "stl" : "profile";
}

/// The part another program makes with the same setup and voxel, or nullopt (diagnostics printed).
std::optional<MeridianProfile> simulateTarget(const CheckOptions& options, double voxelMm, Stopwatch& clock) {
  RunOptions target = options.run;
  target.program = *options.targetProgram;
  target.voxelMm = voxelMm;
  std::optional<SimulatedRun> run = simulateProgram(target, clock, nullptr);
  if (!run) return std::nullopt;
  return MeridianProfile::fromSection(run->partStock().meridianSection());
}

Json place(const RZ& p) { return {{"z", p.y()}, {"diameter", diameterOf(p)}}; }

/// What `check` found: the sizes, the profile between and around them, the threads.
struct Inspection {
  double voxelMm = 0;
  std::string generalTolerance;  // which applied where the drawing states none, and why
  std::vector<measure::SizeCheck> sizes;
  measure::DeviationReport deviation;
  std::vector<measure::ThreadCheck> threads;
  measure::Verdict verdict() const { return overallVerdict(sizes, deviation, threads); }
};

Json limitsJson(double upperMm, double lowerMm) { return {{"upper_mm", upperMm}, {"lower_mm", lowerMm}}; }

Json sizeJson(const measure::SizeCheck& s) {
  Json size{{"kind", s.diameter ? (s.bore ? "bore" : "diameter") : "face"},
            {"drawing_line", s.drawn.line},
            {"nominal_mm", s.nominalMm},
            {"tolerance", limitsJson(s.tolerance.upperMm, s.tolerance.lowerMm)},
            {"tolerance_source", s.tolerance.source},
            {"probed", s.probed},
            {"least_mm", s.probed ? Json(s.leastMm) : Json()},
            {"greatest_mm", s.probed ? Json(s.greatestMm) : Json()},
            {"worst_mm", s.probed ? Json(s.worstMm) : Json()},
            {"worst_at", place(s.worstAt)},
            {"uncertainty_mm", s.uncertaintyMm},
            {"beyond_mm", s.outsideMm},
            {"verdict", measure::verdictName(s.verdict)},
            {"lines", s.lines},
            {"value_line", s.valueLine}};
  return size;
}

Json checkJson(const CheckOptions& options, const Inspection& inspection, const measure::ProcessFigures& p, double checkS) {
  const measure::DeviationReport& d = inspection.deviation;
  Json check;
  check["target"] = options.drawing ? options.drawing->string() : options.targetProgram->string();
  check["target_kind"] = targetKind(options);
  check["verdict"] = measure::verdictName(inspection.verdict());
  check["tolerance_mm"] = options.toleranceMm.value_or(0.0);  // --tol, if given
  check["general_tolerance"] = inspection.generalTolerance;
  check["surface_uncertainty_mm"] = d.uncertaintyMm;
  check["within_tolerance"] = inspection.verdict() == measure::Verdict::Within;
  check["max_excess_mm"] = d.maxExcessMm;
  check["max_excess_at"] = place(d.maxExcessAt);
  check["max_gouge_mm"] = d.maxGougeMm;
  check["max_gouge_at"] = place(d.maxGougeAt);
  check["excess_volume_mm3"] = d.excessVolumeMm3;
  check["gouge_volume_mm3"] = d.gougeVolumeMm3;
  auto& sizes = check["sizes"] = Json::array();
  for (const auto& s : inspection.sizes) sizes.push_back(sizeJson(s));
  auto& regions = check["regions"] = Json::array();
  for (const auto& r : d.regions)
    regions.push_back({{"kind", r.gouge ? "gouge" : "excess"},
                       {"max_mm", r.maxMm},
                       {"at", place(r.at)},
                       {"allowed", limitsJson(r.band.upperMm, r.band.lowerMm)},
                       {"beyond_mm", r.beyondMm},
                       {"verdict", measure::verdictName(r.verdict)},
                       {"z_range", {r.lower.y(), r.upper.y()}},
                       {"diameter_range", {diameterOf(r.lower), diameterOf(r.upper)}},
                       {"lines", r.lines},
                       {"made_by", r.madeBy}});
  auto& threads = check["threads"] = Json::array();
  for (const auto& t : inspection.threads) {
    Json items = Json::array();
    for (const auto& i : t.items)
      items.push_back({{"name", i.name}, {"expected", i.expected}, {"measured", i.measured}, {"within", i.within}});
    Json thread{{"z_range", {t.callout.zLowMm, t.callout.zHighMm}}, {"within", t.within()}, {"items", items}};
    if (t.line) thread["line"] = *t.line;
    threads.push_back(thread);
  }
  Json process;
  process["rapid_path_mm"] = p.rapidPathMm;
  process["feed_path_mm"] = p.feedPathMm;
  process["rapid_time_s"] = p.rapidTimeS;
  process["feed_time_s"] = p.feedTimeS;
  process["air_feed_moves"] = p.airFeedMoves;
  process["air_feed_path_mm"] = p.airFeedPathMm;
  process["air_feed_time_s"] = p.airFeedTimeS;
  auto& tools = process["removed_per_tool"] = Json::array();
  for (const auto& t : p.removedPerTool) tools.push_back({{"tool", t.tool}, {"removed_volume_mm3", t.removedMm3}});
  check["process"] = process;
  check["timing_s"] = checkS;
  return check;
}

std::string where(const RZ& p) {
  char text[96];
  std::snprintf(text, sizeof text, "Z%.3f Ø%.3f", p.y(), diameterOf(p));
  return text;
}

std::string verdictHeadline(measure::Verdict verdict) {
  return verdict == measure::Verdict::Within ? "within tolerance"
         : verdict == measure::Verdict::Out  ? "OUT OF tolerance"
                                             : "UNDECIDED at this voxel";
}

/// One finding of the report, to list them worst first: a size or a region of the profile.
struct Finding {
  double beyondMm;
  std::string text;
};

void printSummary(const CheckOptions& options, const Inspection& inspection, const BlockText& block,
                  const interp::MachineChoice& machine) {
  const measure::DeviationReport& d = inspection.deviation;
  const std::string target = options.drawing ? options.drawing->string() : options.targetProgram->string();
  std::cout << interp::printable(options.run.program.string()) << " against " << interp::printable(target) << ": "
            << verdictHeadline(inspection.verdict()) << " ("
            << interp::printable(interp::describeMachine(machine)) << ")\n  tolerances: as the drawing states them, else "
            << inspection.generalTolerance << "; voxel " << batch::fixed(inspection.voxelMm, 3) << " mm: a surface is known to ±"
            << batch::fixed(d.uncertaintyMm, 3) << " mm, a diameter to ±" << batch::fixed(2 * d.uncertaintyMm, 3) << " mm\n";
  for (const auto& t : inspection.threads) {
    std::cout << "  thread Z" << batch::fixed(t.callout.zLowMm, 3) << "..Z" << batch::fixed(t.callout.zHighMm, 3);
    if (t.line) std::cout << " (line " << *t.line << ")";
    std::cout << ": " << (t.within() ? "as called out" : "NOT as called out");
    for (const auto& i : t.items)
      std::cout << (&i == &t.items.front() ? "; " : ", ") << i.name << " " << i.measured
                << (i.within ? "" : " (expected " + i.expected + ")");
    std::cout << '\n';
  }
  // Worst first, by how far outside its tolerance each lies; the sizes within after them.
  std::vector<Finding> findings;
  for (const auto& s : inspection.sizes) findings.push_back({s.outsideMm, sizeText(s, inspection.voxelMm, block)});
  for (const auto& r : d.regions) findings.push_back({r.beyondMm, regionText(r, d.uncertaintyMm, inspection.voxelMm, block)});
  std::stable_sort(findings.begin(), findings.end(), [](const Finding& a, const Finding& b) { return a.beyondMm > b.beyondMm; });
  for (const auto& f : findings) std::cout << "  " << f.text << '\n';
  std::cout << "  max excess " << batch::fixed(d.maxExcessMm, 3) << " mm";
  if (d.maxExcessMm >= 0.0005) std::cout << " at " << where(d.maxExcessAt);
  std::cout << ", excess volume " << batch::fixed(d.excessVolumeMm3, 1) << " mm³\n";
  std::cout << "  max gouge " << batch::fixed(d.maxGougeMm, 3) << " mm";
  if (d.maxGougeMm >= 0.0005) std::cout << " at " << where(d.maxGougeAt);
  std::cout << ", gouge volume " << batch::fixed(d.gougeVolumeMm3, 1) << " mm³\n";
  std::cout << "  outputs in " << interp::printable(options.run.out.string()) << "/\n";
}

bool inZones(const std::vector<measure::ZRange>& zones, double z) {
  return std::any_of(zones.begin(), zones.end(), [z](const measure::ZRange& r) { return r.contains(z); });
}

/// Each mesh vertex's deviation: the drawing's signed distance at its (r, z), as for the
/// part's surface samples (the vertex lies on the part's surface); 0 in a thread's zone,
/// which its callout checks.
std::vector<float> vertexDeviations(const TriangleMesh& part, const MeridianProfile& drawing,
                                    const std::vector<measure::ZRange>& threadZones) {
  std::vector<float> deviations;
  deviations.reserve(part.vertices.size());
  for (const Eigen::Vector3f& v : part.vertices) {
    const RZ p(std::hypot(static_cast<double>(v.x()), static_cast<double>(v.y())), v.z());
    deviations.push_back(inZones(threadZones, p.y()) ? 0.0f : static_cast<float>(drawing.signedDistance(p).signedMm));
  }
  return deviations;
}

std::string shortLines(const std::vector<int>& lines) {
  std::string text = lines.size() == 1 ? "line" : "lines";
  for (std::size_t n = 0; n < lines.size() && n < 6; ++n) text += (n ? ", " : " ") + std::to_string(lines[n]);
  return text;
}

std::string regionLabel(const measure::DeviationRegion& r) {
  std::string text = (r.gouge ? "gouge " : "excess ") + batch::fixed(r.maxMm, 3) + " mm, " +
                     (r.verdict == measure::Verdict::Out ? batch::fixed(r.beyondMm, 3) + " beyond" : "undecided") + "\n" + where(r.at);
  const std::vector<int>& lines = r.madeBy.empty() ? r.lines : r.madeBy;
  if (!lines.empty()) text += ", " + shortLines(lines);
  return text;
}

std::string sizeLabel(const measure::SizeCheck& s) {
  if (!s.probed) return "face Z" + batch::fixed(s.nominalMm, 3) + ": not measured, undecided";
  std::string text = s.diameter ? "Ø" + batch::fixed(s.worstMm, 3) + " (Ø" + batch::fixed(s.nominalMm, 3) + " " +
                                      limitsText(s.tolerance.upperMm, s.tolerance.lowerMm) + ")"
                                : "face Z" + batch::fixed(s.worstMm, 3) + " (Z" + batch::fixed(s.nominalMm, 3) + " " +
                                      limitsText(s.tolerance.upperMm, s.tolerance.lowerMm) + ")";
  text += s.verdict == measure::Verdict::Out ? ", " + batch::fixed(s.outsideMm, 3) + " beyond" : ", undecided";
  if (!s.lines.empty()) text += "\n" + shortLines(s.lines);
  return text;
}

render::SectionImage sectionImage(const std::string& title, const SampledSection& section, const MeridianProfile& part,
                                  const MeridianProfile& drawing, const Inspection& inspection,
                                  const std::vector<measure::ZRange>& threadZones) {
  render::SectionImage image;
  image.title = title;
  image.drawing = drawing.surface();
  image.part = part.surface();
  image.cellMm = section.stepMm;
  for (int k = 0; k < section.zCount; ++k)
    for (int i = 0; i < section.rCount; ++i) {
      const RZ p(i * section.stepMm, section.zFirstMm + k * section.stepMm);
      if (inZones(threadZones, p.y())) continue;
      const bool inPart = section.at(i, k) < 0, inDrawing = drawing.contains(p);
      if (inPart && !inDrawing) image.excessCells.push_back(p);
      if (inDrawing && !inPart) image.gougeCells.push_back(p);
    }
  // Every finding not within, worst first (the picture places them apart).
  std::vector<std::pair<double, render::SectionLabel>> labels;
  for (const auto& s : inspection.sizes)
    if (s.verdict != measure::Verdict::Within)
      labels.push_back({s.outsideMm, {s.worstAt, sizeLabel(s), s.worstMm < s.nominalMm}});
  for (const auto& r : inspection.deviation.regions) labels.push_back({r.beyondMm, {r.at, regionLabel(r), r.gouge}});
  std::stable_sort(labels.begin(), labels.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  for (auto& [beyond, label] : labels) image.labels.push_back(std::move(label));
  return image;
}

/// Stages deviation.png and section.png; returns deviation.png's pixels (for a thumbnail).
render::RgbImage stageDeviationImages(const CheckOptions& options, const TriangleMesh& mesh, const SampledSection& section,
                                      const MeridianProfile& part, const MeridianProfile& drawing,
                                      const Inspection& inspection, double colourToleranceMm,
                                      const std::vector<measure::ZRange>& threadZones, StagedOutput& out,
                                      std::vector<HtmlPicture>& pictures) {
  const measure::DeviationReport& d = inspection.deviation;
  const std::string target = options.drawing ? options.drawing->string() : options.targetProgram->string();
  render::DeviationImageOptions image;
  image.title = options.run.program.string() + " against " + target;
  image.toleranceMm = colourToleranceMm;
  image.caption = verdictHeadline(inspection.verdict()) + " (green: within ±" + batch::fixed(colourToleranceMm, 3) +
                  " mm); max excess " + batch::fixed(d.maxExcessMm, 3) + " mm, max gouge " + batch::fixed(d.maxGougeMm, 3) + " mm";
  render::RgbImage deviationPixels;
  const auto deviationPng = out.write("deviation.png", [&](const std::filesystem::path& file) {
    deviationPixels = render::deviationImage(mesh, vertexDeviations(mesh, drawing, threadZones), image);
    render::writeFileBytes(render::encodePng(deviationPixels), file);
  });
  pictures.push_back({"deviation.png: the part coloured by its deviation from the drawing", deviationPng});
  render::SectionImage half = sectionImage(image.title + ", half-section", section, part, drawing, inspection, threadZones);
  half.caption = image.caption;
  const auto sectionPng =
      out.write("section.png", [&](const std::filesystem::path& file) { render::writeSectionImagePng(half, file); });
  pictures.push_back({"section.png: the half-section against the drawing", sectionPng});
  return deviationPixels;
}

/// The lines that made the surface where each size or region is not within: the surface point
/// of its worst figure (surface_causes.hpp), within a voxel of a move's sweep.
void attributeSurfaces(Inspection& inspection, const interp::MoveSpool& moves, const sim::ToolOutlines& tools, double voxelMm) {
  std::vector<measure::SurfacePoint> points;
  for (const auto& s : inspection.sizes) points.push_back({s.worstAt, s.diameter ? RZ(0, 1) : RZ(1, 0)});
  for (const auto& r : inspection.deviation.regions) points.push_back({r.worstOnPart, std::nullopt});
  const auto makers = measure::surfaceMakers(points, moves, tools, voxelMm, voxelMm);
  std::size_t n = 0;
  for (auto& s : inspection.sizes)
    if (const auto& maker = makers[n++]; maker && s.probed)
      s.lines = {maker->line}, s.valueLine = s.diameter ? maker->xLine : maker->zLine;
  for (auto& r : inspection.deviation.regions)
    if (const auto& maker = makers[n++]) r.madeBy = {maker->line};
}

/// Which ISO 2768-1 class applies where the drawing states no tolerance, and the words saying why.
std::pair<char, std::string> generalClassOf(const CheckOptions& options, const measure::DrawingResult& file) {
  if (options.toleranceMm) return {'m', "±" + batch::fixed(*options.toleranceMm, 3) + " mm normal to the surface (--tol)"};
  if (options.generalTolerance) return {*options.generalTolerance, std::string("ISO 2768-") + *options.generalTolerance + " (--general-tolerance)"};
  if (file.generalTolerance) return {*file.generalTolerance, std::string("ISO 2768-") + *file.generalTolerance + " (the drawing's general_tolerance)"};
  return {'m', "ISO 2768-m (the default)"};
}

/// --tol stated on every line that states none, as the drawing would: a diameter's ±2·tol
/// (tol on each radius), a face's ±tol, a taper's or an arc's ±tol normal to it.
void applyFlatTolerance(std::vector<measure::DrawnLine>& lines, double toleranceMm) {
  for (measure::DrawnLine& line : lines) {
    if (line.tolerance) continue;
    const double t = line.diameter() ? 2 * toleranceMm : toleranceMm;
    line.tolerance = measure::Tolerance{t, -t, "--tol " + batch::fixed(toleranceMm, 3) + " normal to the surface"};
  }
}

}  // namespace

int checkCommand(const CheckOptions& options) {
  std::optional<MeridianProfile> drawing;
  measure::DrawingResult file;
  if (options.drawing && !(drawing = isStl(*options.drawing) ? loadStl(*options.drawing) : loadProfile(*options.drawing, file)))
    return setup::kExitBadInput;  // before the long part
  Stopwatch clock;
  StagedOutput out(options.run.out);
  // The gouges' causes, the surfaces' makers and the process figures read every move: spooled.
  std::optional<SimulatedRun> run = simulateProgram(options.run, clock, &out, true);
  if (!run) return setup::kExitBadInput;
  std::future<double> stockFile = stageStockFile(*run, out);
  const double voxel = run->figures.voxelMm;
  Stopwatch checkClock;
  if (!drawing && !(drawing = simulateTarget(options, voxel, checkClock))) return setup::kExitBadInput;

  run->progress->stage("measuring against the drawing");
  SampledSection section = run->partStock().meridianSection();
  const MeridianProfile part = MeridianProfile::fromSection(section);
  Inspection inspection;
  inspection.voxelMm = voxel;
  const auto [generalClass, generalWhy] = generalClassOf(options, file);
  inspection.generalTolerance = generalWhy;
  // A thread's zone is checked by its callout, not by one meridian section.
  std::vector<measure::ZRange> threadZones;
  for (const auto& callout : file.threads) {
    threadZones.push_back({callout.zLowMm, callout.zHighMm});
    inspection.threads.push_back(measure::checkThread(callout, run->figures.threads, voxel));
  }
  const double uncertainty = measure::surfaceUncertaintyMm(voxel);
  std::vector<measure::DrawnLine> lines = file.lines;
  if (options.toleranceMm) applyFlatTolerance(lines, *options.toleranceMm);
  // The picture's green: --tol, else the general tolerance of the part's greatest size, on a radius.
  const double partSize = std::max(diameterOf(drawing->upperBound()), drawing->upperBound().y() - drawing->lowerBound().y());
  const double colourTolerance =
      options.toleranceMm.value_or(measure::generalLinearTolerance(generalClass, partSize).value_or(0.5) / 2);
  if (file.outline) {
    inspection.sizes = measure::checkSizes(section, *drawing, lines, generalClass, file.cornerRadiusMm, threadZones);
    measure::ProfileLimits limits(*drawing, *file.outline, lines, generalClass, file.cornerRadiusMm,
                                  measure::sizeMarginMm(file.cornerRadiusMm, voxel));
    for (const auto& s : inspection.sizes) {
      if (!s.probed) {  // nothing measured: the profile judges the face
        limits.notMeasuredBySize(s.lineIndex);
        continue;
      }
      // The size's offsets normal to its line: a diameter's half, turned by the side the material is on.
      const RZ normal = measure::outwardNormal(*drawing, s.drawn);
      const double scale = s.diameter ? 0.5 * normal.x() : normal.y();
      const double a = scale * (s.leastMm - s.nominalMm), b = scale * (s.greatestMm - s.nominalMm);
      // Widened by twice the uncertainty: a sample at the size's own extreme is then decidedly explained.
      limits.explainedBySize(s.lineIndex, std::min(a, b) - 2 * uncertainty, std::max(a, b) + 2 * uncertainty);
    }
    inspection.deviation = measure::measureDeviation(
        section, part, *drawing, [&](const RZ& p) { return limits.at(p); }, uncertainty, threadZones);
  } else {
    // An STL or another program's part: no lines to tolerance one by one; --tol, else the
    // general tolerance of the part's greatest size, normal to the surface on a radius.
    const measure::Band band{-colourTolerance, colourTolerance};
    inspection.deviation = measure::measureDeviation(
        section, part, *drawing, [&](const RZ&) { return std::optional<measure::Band>(band); }, uncertainty, threadZones);
    if (!options.toleranceMm)
      inspection.generalTolerance = std::string("ISO 2768-") + generalClass + " for the part's greatest size, " +
                                    batch::fixed(partSize, 1) + " mm, halved normal to the surface (±" + batch::fixed(colourTolerance, 3) + " mm)";
  }
  inspection.deviation.toleranceMm = options.toleranceMm.value_or(0.0);
  measure::attributeGouges(inspection.deviation, *run->moves, outlinesOf(run->job.setup), run->job.setup.stock, voxel);
  attributeSurfaces(inspection, *run->moves, outlinesOf(run->job.setup), voxel);
  measure::ProcessFigures process;
  useBlockRows(*run, [&](const sim::BlockRows& rows) { process = measure::processFigures(*run->moves, rows, voxel); });
  const double checkS = checkClock.lap();

  meshPart(*run, clock);
  finishStockFile(*run, stockFile);  // before the other files: they are written in one order, whatever the machine's speed
  stageRunFiles(*run, options.run, out, clock);
  run->partPixels = {};  // the thumbnail is of deviation.png
  render::RgbImage deviationPixels;
  if (options.run.outputs.png) {
    // Coloured vertex by vertex: a revolved part's mesh may have a straight face's two ends only.
    std::optional<TriangleMesh> everyVoxel;
    if (run->partStock().isRevolved()) everyVoxel = run->partStock().meshWithVertexEveryVoxel();
    deviationPixels = stageDeviationImages(options, everyVoxel ? *everyVoxel : run->part, section, part, *drawing, inspection,
                                           colourTolerance, threadZones, out, run->pictures);
    out.syncWritten();
  }
  run->figures.timing.renderS += clock.lap();
  run->figures.peakMemoryMb = peakMemoryMb();
  run->figures.timing.totalS = clock.total();
  // Outside the timings: a batch's own work, which its benchmark counts as per-job overhead.
  stageThumbnail(options.run, deviationPixels, out);
  Json report = reportJson(run->figures);
  report["check"] = checkJson(options, inspection, process, checkS);
  stageReports(*run, report, out);
  out.commit();
  run->progress->stage("done");
  run->progress->finish();

  const std::string_view programText = run->job.programText.text().view();
  const interp::LineStarts starts(programText);
  printSummary(options, inspection, [&](int line) { return starts.lineOf(programText, line); }, run->figures.machine);
  const measure::Verdict verdict = inspection.verdict();
  const bool crashed = run->figures.crashed();
  keepUntilExit(std::move(*run));
  if (crashed) return setup::kExitCrash;  // the worse news, over a part out of tolerance
  return verdict == measure::Verdict::Within ? setup::kExitOk : setup::kExitOutOfTolerance;
}

}  // namespace lathesim::app
