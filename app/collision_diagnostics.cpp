#include "app/collision_diagnostics.hpp"

#include <fmt/format.h>

namespace lathesim::app {

std::string collisionMessage(const sim::Collision& c) {
  // Where the tool stood as a program writes it: X a diameter.
  const std::string where = fmt::format("the tool ends at X{:g} Z{:g}", 2.0 * c.at.x(), c.at.y());
  if (c.kind == "rapid_into_stock")
    return fmt::format("rapid into the stock removes {:.1f} mm³ ({})", c.volumeMm3, where);
  if (c.kind == "holder_into_stock")
    return fmt::format("the holder of tool {} runs into the stock, {:.1f} mm³ of material inside it ({})", c.tool,
                       c.volumeMm3, where);
  if (c.kind == "into_chuck")
    return fmt::format("tool {} runs into the chuck, {:.1f} mm³ of the chuck inside the tool or its holder ({})", c.tool,
                       c.volumeMm3, where);
  if (c.kind == "into_tailstock")
    return fmt::format("tool {} runs into the tailstock's centre or quill, {:.1f} mm³ of it inside the tool or its holder "
                       "({})",
                       c.tool, c.volumeMm3, where);
  return fmt::format("collision ({}), {:.1f} mm³ ({})", c.kind, c.volumeMm3, where);
}

interp::Diagnostic collisionDiagnostic(const setup::Job& job, const sim::Collision& collision) {
  const auto severity = job.setup.collisionsWarn ? interp::Severity::Warning : interp::Severity::Error;
  return job.diagnosticAt(severity, collision.line, collision.column, collisionMessage(collision), collision.source);
}

render::CrashMark crashMarkOf(const sim::Collision& collision) {
  return {collision.at, "crash, line " + std::to_string(collision.line)};
}

std::vector<render::CrashMark> crashMarksOf(const std::vector<sim::Collision>& collisions) {
  std::vector<render::CrashMark> marks;
  for (const sim::Collision& c : collisions) marks.push_back(crashMarkOf(c));
  return marks;
}

}  // namespace lathesim::app
