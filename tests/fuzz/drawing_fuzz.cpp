// libFuzzer harness: a drawing's profile (TOML) read into an outline — points, arcs by radius
// or centre, closed via the axis or as given — then made into the profile check measures
// against, and asked a distance. Errors are answers; a crash, a hang, a leak or undefined
// behaviour is a finding.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/meridian_profile.hpp"
#include "measure/drawing.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  lathesim::measure::DrawingResult drawing = lathesim::measure::parseDrawing(text, "drawing.toml");
  for (const auto& d : drawing.diagnostics) lathesim::interp::format(d);
  if (!drawing.outline) return 0;
  const auto profile = lathesim::MeridianProfile::fromPolygon(std::move(*drawing.outline));
  profile.signedDistance(lathesim::RZ(10.0, -5.0));
  return 0;
}
