#pragma once

namespace lathesim::sim {

/// A round bar on the spindle axis spanning Z = faceZMm − lengthMm … faceZMm.
struct StockSpec {
  double diameterMm = 125.0;
  double lengthMm = 112.0;
  double faceZMm = 2.0;  // Z of the right-hand end face
};

}  // namespace lathesim::sim
