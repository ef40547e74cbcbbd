#pragma once

#include <optional>

namespace lathesim::sim {

/// The chuck holding the bar (setup [chuck]): jaws of length gripLengthMm along Z, their
/// right-hand face at faceZMm, reaching from the bar's surface out to jawDiameterMm; the
/// chuck's body fills everything behind the jaws out to that diameter.
struct ChuckSpec {
  double gripLengthMm = 20.0;
  std::optional<double> jawDiameterMm;  // default: the bar's diameter + 40 mm
  std::optional<double> faceZMm;        // default: the bar's left end (the stock is what sticks out of the jaws)
};

}  // namespace lathesim::sim
