#include "setup/machine_assumptions.hpp"

#include <fmt/format.h>

namespace lathesim::setup {

std::vector<MachineAssumption> machineAssumptions(const Setup& setup) {
  std::vector<MachineAssumption> assumed;
  const RZ start = setup.startPosition;
  if (!setup.startGiven)
    assumed.push_back({"start", {2 * start.x(), start.y()}, fmt::format("start X{:g} Z{:g}", 2 * start.x(), start.y())});
  const interp::TravelLimits travel = travelOf(setup);
  if (travel.xDerived)
    assumed.push_back({"travel_x", {travel.xMinDiameterMm, travel.xMaxDiameterMm},
                       fmt::format("X travel X{:g} to X{:g}", travel.xMinDiameterMm, travel.xMaxDiameterMm)});
  if (travel.zDerived)
    assumed.push_back({"travel_z", {travel.zMinMm, travel.zMaxMm},
                       fmt::format("Z travel Z{:g} to Z{:g}", travel.zMinMm, travel.zMaxMm)});
  if (!setup.stockGiven)
    assumed.push_back({"stock", {setup.stock.diameterMm, setup.stock.lengthMm},
                       fmt::format("bar Φ{:g} × {:g}", setup.stock.diameterMm, setup.stock.lengthMm)});
  if (!setup.stockFaceGiven)
    assumed.push_back({"stock_face_z", {setup.stock.faceZMm}, fmt::format("bar face at Z{:g}", setup.stock.faceZMm)});
  return assumed;
}

std::string assumptionsText(const std::vector<MachineAssumption>& assumptions) {
  std::string text;
  for (const MachineAssumption& a : assumptions) text += (text.empty() ? "" : ", ") + a.text;
  return text;
}

}  // namespace lathesim::setup
