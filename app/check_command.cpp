// lathesim check: simulate a program, then measure the part against its drawing (see
// deviation.hpp for how), attribute each gouge to the moves that cut it, and write the run's
// files plus the deviation pictures and report.json's "check" section.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "interp/printable_text.hpp"
#include "measure/deviation.hpp"
#include "measure/drawing.hpp"
#include "measure/gouge_causes.hpp"
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

/// The drawing's outline from a profile file, or nullopt with the diagnostics printed; its
/// thread callouts into `threads`.
std::optional<MeridianProfile> loadProfile(const std::filesystem::path& file, std::vector<measure::ThreadCallout>& threads) {
  measure::DrawingResult drawing = measure::loadDrawing(file);
  for (const auto& d : drawing.diagnostics) std::cerr << interp::format(d) << '\n';
  if (!drawing.outline) return std::nullopt;
  threads = std::move(drawing.threads);
  return MeridianProfile::fromPolygon(std::move(*drawing.outline));
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

bool allWithin(const measure::DeviationReport& d, const std::vector<measure::ThreadCheck>& threads) {
  return d.withinTolerance() &&
         std::all_of(threads.begin(), threads.end(), [](const measure::ThreadCheck& t) { return t.within(); });
}

Json checkJson(const CheckOptions& options, const measure::DeviationReport& d, const std::vector<measure::ThreadCheck>& threadChecks,
               const measure::ProcessFigures& p, double checkS) {
  Json check;
  check["target"] = options.drawing ? options.drawing->string() : options.targetProgram->string();
  check["target_kind"] = targetKind(options);
  check["tolerance_mm"] = d.toleranceMm;
  check["within_tolerance"] = allWithin(d, threadChecks);
  check["max_excess_mm"] = d.maxExcessMm;
  check["max_excess_at"] = place(d.maxExcessAt);
  check["max_gouge_mm"] = d.maxGougeMm;
  check["max_gouge_at"] = place(d.maxGougeAt);
  check["excess_volume_mm3"] = d.excessVolumeMm3;
  check["gouge_volume_mm3"] = d.gougeVolumeMm3;
  auto& regions = check["regions"] = Json::array();
  for (const auto& r : d.regions)
    regions.push_back({{"kind", r.gouge ? "gouge" : "excess"},
                       {"max_mm", r.maxMm},
                       {"at", place(r.at)},
                       {"z_range", {r.lower.y(), r.upper.y()}},
                       {"diameter_range", {diameterOf(r.lower), diameterOf(r.upper)}},
                       {"lines", r.lines}});
  auto& threads = check["threads"] = Json::array();
  for (const auto& t : threadChecks) {
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

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string where(const RZ& p) {
  char text[96];
  std::snprintf(text, sizeof text, "Z%.3f Ø%.3f", p.y(), diameterOf(p));
  return text;
}

void printSummary(const CheckOptions& options, const measure::DeviationReport& d,
                  const std::vector<measure::ThreadCheck>& threads) {
  const std::string target = options.drawing ? options.drawing->string() : options.targetProgram->string();
  std::cout << interp::printable(options.run.program.string()) << " against " << interp::printable(target) << ": "
            << (allWithin(d, threads) ? "within" : "OUT OF") << " tolerance ±" << fixed(d.toleranceMm, 3) << " mm\n";
  for (const auto& t : threads) {
    std::cout << "  thread Z" << fixed(t.callout.zLowMm, 3) << "..Z" << fixed(t.callout.zHighMm, 3);
    if (t.line) std::cout << " (line " << *t.line << ")";
    std::cout << ": " << (t.within() ? "as called out" : "NOT as called out");
    for (const auto& i : t.items)
      std::cout << (&i == &t.items.front() ? "; " : ", ") << i.name << " " << i.measured
                << (i.within ? "" : " (expected " + i.expected + ")");
    std::cout << '\n';
  }
  std::cout << "  max excess " << fixed(d.maxExcessMm, 3) << " mm";
  if (d.maxExcessMm >= 0.0005) std::cout << " at " << where(d.maxExcessAt);
  std::cout << ", excess volume " << fixed(d.excessVolumeMm3, 1) << " mm³\n";
  std::cout << "  max gouge " << fixed(d.maxGougeMm, 3) << " mm";
  if (d.maxGougeMm >= 0.0005) std::cout << " at " << where(d.maxGougeAt);
  std::cout << ", gouge volume " << fixed(d.gougeVolumeMm3, 1) << " mm³\n";
  for (const auto& r : d.regions) {
    std::cout << "  " << (r.gouge ? "gouge " : "excess ") << fixed(r.maxMm, 3) << " mm at " << where(r.at) << " (Z"
              << fixed(r.lower.y(), 3) << "..Z" << fixed(r.upper.y(), 3) << ", Ø" << fixed(diameterOf(r.lower), 3)
              << "..Ø" << fixed(diameterOf(r.upper), 3) << ")";
    if (r.gouge) {
      std::cout << (r.lines.size() == 1 ? ", cut by line" : r.lines.empty() ? ", not cut: the bar had no material there" : ", cut by lines");
      for (std::size_t n = 0; n < r.lines.size(); ++n) std::cout << (n ? ", " : " ") << r.lines[n];
    }
    std::cout << '\n';
  }
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

std::string regionLabel(const measure::DeviationRegion& r) {
  std::string text = (r.gouge ? "gouge " : "excess ") + fixed(r.maxMm, 3) + " mm\n" + where(r.at);
  if (r.gouge && !r.lines.empty()) {
    text += r.lines.size() == 1 ? ", line" : ", lines";
    for (std::size_t n = 0; n < r.lines.size() && n < 6; ++n) text += (n ? ", " : " ") + std::to_string(r.lines[n]);
  }
  return text;
}

constexpr std::size_t kLabelledRegions = 4;

render::SectionImage sectionImage(const std::string& title, const SampledSection& section, const MeridianProfile& part,
                                  const MeridianProfile& drawing, const measure::DeviationReport& d,
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
  for (std::size_t n = 0; n < d.regions.size() && n < kLabelledRegions; ++n)
    image.labels.push_back({d.regions[n].at, regionLabel(d.regions[n]), d.regions[n].gouge});
  return image;
}

/// Stages deviation.png and section.png; returns deviation.png's pixels (for a thumbnail).
render::RgbImage stageDeviationImages(const CheckOptions& options, const TriangleMesh& mesh, const SampledSection& section,
                                      const MeridianProfile& part, const MeridianProfile& drawing,
                                      const measure::DeviationReport& d, const std::vector<measure::ZRange>& threadZones,
                                      StagedOutput& out, std::vector<HtmlPicture>& pictures) {
  const std::string target = options.drawing ? options.drawing->string() : options.targetProgram->string();
  render::DeviationImageOptions image;
  image.title = options.run.program.string() + " against " + target;
  image.toleranceMm = d.toleranceMm;
  image.caption = std::string(d.withinTolerance() ? "within" : "OUT OF") + " tolerance ±" + fixed(d.toleranceMm, 3) +
                  " mm; max excess " + fixed(d.maxExcessMm, 3) + " mm, max gouge " + fixed(d.maxGougeMm, 3) + " mm";
  render::RgbImage deviationPixels;
  const auto deviationPng = out.write("deviation.png", [&](const std::filesystem::path& file) {
    deviationPixels = render::deviationImage(mesh, vertexDeviations(mesh, drawing, threadZones), image);
    render::writeFileBytes(render::encodePng(deviationPixels), file);
  });
  pictures.push_back({"deviation.png: the part coloured by its deviation from the drawing", deviationPng});
  render::SectionImage half = sectionImage(image.title + ", half-section", section, part, drawing, d, threadZones);
  half.caption = image.caption;
  const auto sectionPng =
      out.write("section.png", [&](const std::filesystem::path& file) { render::writeSectionImagePng(half, file); });
  pictures.push_back({"section.png: the half-section against the drawing", sectionPng});
  return deviationPixels;
}

}  // namespace

int checkCommand(const CheckOptions& options) {
  std::optional<MeridianProfile> drawing;
  std::vector<measure::ThreadCallout> callouts;
  if (options.drawing &&
      !(drawing = isStl(*options.drawing) ? loadStl(*options.drawing) : loadProfile(*options.drawing, callouts)))
    return job::kExitBadInput;  // before the long part
  Stopwatch clock;
  StagedOutput out(options.run.out);
  // The gouges' causes and the process figures read every move: spooled.
  std::optional<SimulatedRun> run = simulateProgram(options.run, clock, &out, true);
  if (!run) return job::kExitBadInput;
  std::future<double> stockFile = stageStockFile(*run, out);
  const double voxel = run->figures.voxelMm;
  Stopwatch checkClock;
  if (!drawing && !(drawing = simulateTarget(options, voxel, checkClock))) return job::kExitBadInput;
  const double tolerance = options.toleranceMm.value_or(2 * voxel);

  run->progress->stage("measuring against the drawing");
  SampledSection section = run->partStock().meridianSection();
  const MeridianProfile part = MeridianProfile::fromSection(section);
  // A thread's zone is checked by its callout, not by one meridian section.
  std::vector<measure::ZRange> threadZones;
  std::vector<measure::ThreadCheck> threadChecks;
  for (const auto& callout : callouts) {
    threadZones.push_back({callout.zLowMm, callout.zHighMm});
    threadChecks.push_back(measure::checkThread(callout, run->figures.threads, voxel));
  }
  measure::DeviationReport deviation = measure::measureDeviation(section, part, *drawing, tolerance, threadZones);
  measure::attributeGouges(deviation, *run->moves, outlinesOf(run->job.setup), run->job.setup.stock, run->figures.voxelMm);
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
    deviationPixels = stageDeviationImages(options, everyVoxel ? *everyVoxel : run->part, section, part, *drawing,
                                           deviation, threadZones, out, run->pictures);
    out.syncWritten();
  }
  run->figures.timing.renderS += clock.lap();
  run->figures.peakMemoryMb = peakMemoryMb();
  run->figures.timing.totalS = clock.total();
  // Outside the timings: a batch's own work, which its benchmark counts as per-job overhead.
  stageThumbnail(options.run, deviationPixels, out);
  Json report = reportJson(run->figures);
  report["check"] = checkJson(options, deviation, threadChecks, process, checkS);
  stageReports(*run, report, out);
  out.commit();
  run->progress->stage("done");
  run->progress->finish();

  printSummary(options, deviation, threadChecks);
  const bool crashed = run->figures.crashed();
  keepUntilExit(std::move(*run));
  if (crashed) return job::kExitCrash;  // the worse news, over a part out of tolerance
  return allWithin(deviation, threadChecks) ? job::kExitOk : job::kExitOutOfTolerance;
}

}  // namespace lathesim::app
