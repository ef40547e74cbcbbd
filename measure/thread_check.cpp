#include "measure/thread_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lathesim::measure {
namespace {

std::string mm(double value, int decimals = 4) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

ThreadCheckItem limitsItem(const char* name, const DiameterLimits& limits, const Spread& measured) {
  return {name, "Φ" + mm(limits.least, 3) + "…Φ" + mm(limits.greatest, 3),
          "Φ" + mm(measured.min, 3) + "…Φ" + mm(measured.max, 3),
          measured.min >= limits.least && measured.max <= limits.greatest};
}

}  // namespace

bool ThreadCheck::within() const {
  return line && std::all_of(items.begin(), items.end(), [](const ThreadCheckItem& i) { return i.within; });
}

ThreadCheck checkThread(const ThreadCallout& callout, const std::vector<MeasuredThread>& threads, double voxelMm) {
  ThreadCheck check{callout, std::nullopt, {}};
  const auto found = std::find_if(threads.begin(), threads.end(), [&](const MeasuredThread& t) {
    return t.programmed.leadAlongZ && t.programmed.zMaxMm >= callout.zLowMm && t.programmed.zMinMm <= callout.zHighMm;
  });
  if (found == threads.end()) {
    check.items.push_back({"thread", "a thread in Z" + mm(callout.zLowMm, 3) + "…Z" + mm(callout.zHighMm, 3),
                           "no thread cut there", false});
    return check;
  }
  check.line = found->programmed.line;
  const ThreadMeasurement& m = found->measured;
  if (m.problem) {
    check.items.push_back({"thread", "measurable", *m.problem, false});
    return check;
  }
  const double pitchOff = std::max(std::abs(m.pitchMm.min - callout.pitchMm), std::abs(m.pitchMm.max - callout.pitchMm));
  check.items.push_back({"pitch", mm(callout.pitchMm) + " mm", mm(m.pitchMm.mean) + " mm", pitchOff <= 0.1 * voxelMm});
  check.items.push_back({"starts", std::to_string(callout.starts), std::to_string(m.starts), m.starts == callout.starts});
  if (callout.rightHand)
    check.items.push_back({"hand", *callout.rightHand ? "right" : "left", m.rightHand ? "right" : "left",
                           m.rightHand == *callout.rightHand});
  if (callout.major) check.items.push_back(limitsItem("major", *callout.major, m.majorDiameterMm));
  if (callout.minor) check.items.push_back(limitsItem("minor", *callout.minor, m.minorDiameterMm));
  if (callout.pitchDiameter) check.items.push_back(limitsItem("pitch_diameter", *callout.pitchDiameter, m.pitchDiameterMm));
  return check;
}

}  // namespace lathesim::measure
