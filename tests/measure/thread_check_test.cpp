// A thread callout against a measured thread: each diameter within its limits at every angle
// measured — both limits, the least as well as the greatest.

#include "measure/thread_check.hpp"

#include <gtest/gtest.h>

namespace lathesim::measure {
namespace {

/// An M30×2 thread measured with each diameter spread over [least, greatest].
MeasuredThread measured(Spread major, Spread minor, Spread pitchDiameter) {
  MeasuredThread t;
  t.programmed.line = 13;
  t.programmed.leadMm = 2;
  t.programmed.zMinMm = -30;
  t.programmed.zMaxMm = 0;
  t.measured.pitchMm = {2, 2, 2};
  t.measured.starts = 1;
  t.measured.majorDiameterMm = major;
  t.measured.minorDiameterMm = minor;
  t.measured.pitchDiameterMm = pitchDiameter;
  return t;
}

ThreadCallout callout() {
  ThreadCallout c;
  c.zLowMm = -30;
  c.pitchMm = 2;
  c.major = DiameterLimits{29.7, 30.0};
  c.minor = DiameterLimits{27.4, 27.8};
  c.pitchDiameter = DiameterLimits{28.5, 28.8};
  return c;
}

const ThreadCheckItem& item(const ThreadCheck& check, const std::string& name) {
  for (const auto& i : check.items)
    if (i.name == name) return i;
  throw std::runtime_error("no item " + name);
}

TEST(ThreadCheck, EachDiameterWithinBothLimits) {
  const ThreadCheck ok = checkThread(callout(), {measured({29.8, 29.75, 29.9}, {27.6, 27.5, 27.7}, {28.6, 28.55, 28.7})}, 0.1);
  EXPECT_TRUE(ok.within());
  // One angle's diameter under the least limit fails that diameter, whichever it is — and
  // one over the greatest.
  for (const char* name : {"major", "minor", "pitch_diameter"}) {
    Spread major{29.8, 29.75, 29.9}, minor{27.6, 27.5, 27.7}, pitch{28.6, 28.55, 28.7};
    Spread& spread = std::string(name) == "major" ? major : std::string(name) == "minor" ? minor : pitch;
    const DiameterLimits limits = std::string(name) == "major" ? *callout().major
                                  : std::string(name) == "minor" ? *callout().minor
                                                                 : *callout().pitchDiameter;
    Spread under = spread;
    under.min = limits.least - 0.01;
    std::swap(spread, under);
    const ThreadCheck low = checkThread(callout(), {measured(major, minor, pitch)}, 0.1);
    EXPECT_FALSE(item(low, name).within) << name << " under its least";
    EXPECT_FALSE(low.within());
    std::swap(spread, under);
    spread.max = limits.greatest + 0.01;
    const ThreadCheck high = checkThread(callout(), {measured(major, minor, pitch)}, 0.1);
    EXPECT_FALSE(item(high, name).within) << name << " over its greatest";
  }
}

}  // namespace
}  // namespace lathesim::measure
