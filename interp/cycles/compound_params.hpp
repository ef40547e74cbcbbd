#pragma once
// The first-block values of the compound cycles (G71 U R, G72 W R, G73 U W R, G74/G75 R):
// modal, kept until a first block changes them. Before any is given the control uses its
// parameters; these stand for those GSK980TDi parameters. Lengths in mm.

#include <optional>

namespace lathesim::interp {

constexpr double kDefaultRoughingDepthMm = 1.0;    // GSK No.51: G71/G72 Δd (G71: a radius)
constexpr double kDefaultRoughingRetractMm = 0.5;  // GSK No.52: G71/G72 e
// G73 and G74/G75 defaults are our assumption (the parameter values were not at hand):
constexpr double kDefaultPatternReliefXMm = 0.0;   // GSK No.53: G73 Δi, a radius
constexpr double kDefaultPatternReliefZMm = 0.0;   // GSK No.54: G73 Δk
constexpr int kDefaultPatternPasses = 1;           // GSK No.55: G73 d (1 runs as 2)
constexpr double kDefaultPeckRetractMm = 0.5;      // GSK No.56: G74/G75 e
// G76's first block (GSK No.57–60; Fanuc No.5142, 5143, 5140, 5141 ⚠); values assumed:
constexpr int kDefaultThreadFinishingPasses = 1;     // GSK No.57: m
constexpr double kDefaultThreadToolAngleDeg = 60.0;  // GSK No.58: a
constexpr double kDefaultThreadMinDepthMm = 0.0;     // GSK No.59: Δdmin
constexpr double kDefaultThreadAllowanceMm = 0.0;    // GSK No.60: d

struct CompoundCycleParams {
  double roughingDepthMm = kDefaultRoughingDepthMm;      // G71 U / G72 W, first block
  double roughingRetractMm = kDefaultRoughingRetractMm;  // G71/G72 R, first block
  double patternReliefXMm = kDefaultPatternReliefXMm;    // G73 U (Δi), radius, signed
  double patternReliefZMm = kDefaultPatternReliefZMm;    // G73 W (Δk), signed
  int patternPasses = kDefaultPatternPasses;             // G73 R (d)
  double peckRetractMm = kDefaultPeckRetractMm;          // G74/G75 R (e)
  // G76 P(m)(r)(a) Q(Δdmin) R(d) [J K] (first block)
  int threadFinishingPasses = kDefaultThreadFinishingPasses;
  std::optional<double> threadRunoutLeads;  // r/10: the run-out in leads; unset: the machine's
  double threadToolAngleDeg = kDefaultThreadToolAngleDeg;
  double threadMinDepthMm = kDefaultThreadMinDepthMm;
  double threadAllowanceMm = kDefaultThreadAllowanceMm;
  std::optional<double> threadRunoutAcrossMm;  // GSK J, K: for the next second block only
  std::optional<double> threadRunoutAlongMm;
};

}  // namespace lathesim::interp
