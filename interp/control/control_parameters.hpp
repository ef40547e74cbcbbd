#pragma once
// What the control's parameters decide about a program's meaning (lathe-cycles.md §10), as
// the interpreter reads them. Which values a control has is in control_preset.cpp: a preset
// per control, each value with the manual's parameter it stands for. The dialect (how the
// codes are written, dialect.hpp) is a separate setting.

#include <string>
#include <vector>

#include "interp/control/machine_m_codes.hpp"
#include "interp/base/move.hpp"

namespace lathesim::interp {

/// G00 and every other rapid: each axis at its own rapid rate (the short axis arrives first,
/// then the other goes on alone: a dog-leg), or interpolated in a straight line.
enum class RapidPath { NonLinear, Linear };

/// A length written without a decimal point: in mm (inch), "calculator" input, or counted in
/// least input increments (Fanuc DPI = 0: X20 is 0.020 mm at IS-B).
enum class DecimalPointInput { Calculator, LeastIncrements };

/// How the P/Q/R words marked [LII] in lathe-cycles.md (G74/G75/G76) count when written
/// without a point: least input increments, or mm (GSK No.182#7).
enum class IncrementWordInput { LeastIncrements, Calculator };

/// The way G74/G75 relieve by R(Δd) at the bottom when the block moves only the peck axis.
enum class PeckReliefWithoutShift { TowardPlus, BySign };

/// G73 with d = 1: two passes (GSK) or one pass carrying only the allowance.
enum class PatternSinglePass { RunsTwice, RunsOnce };

/// A G02/G03 by I/K whose end point lies off the circle I/K give.
enum class ArcEndOffCircle { MoveCentre, Alarm };

/// The tool offset after G28 reaches the reference point.
enum class OffsetAfterReturn { Cancelled, Kept };

/// X and U (Z and W) in one block.
enum class AbsoluteWithIncremental { AbsoluteWins, Alarm };

/// The word that gives a direct drawing dimension's angle: Q (GSK), A or ,A (Fanuc, by CCR).
enum class DrawingAngleWord { Q, A, CommaA };

/// The words that ask for a chamfer or a corner radius between two moves: L and D (GSK §3.11),
/// or ,C and ,R (Fanuc).
enum class CornerWords { LD, CommaCR };

/// What the GSK's chamfer L measures (No.181#0): the chamfer's own length, or the distance
/// from the corner along each line (Fanuc's ,C always measures that).
enum class ChamferSize { Length, FromCorner };

/// What an E word in a thread block (G32, G92, G76) gives, on a dialect where E is not the
/// run-out (hnc): not a thread word (GSK), the lead like F but with more digits (Fanuc ⚠),
/// or threads per inch.
enum class ThreadEWord { None, Lead, ThreadsPerInch };

/// G04 P: always milliseconds (GSK, Fanuc), or seconds when P has a decimal point and
/// milliseconds when not (Haas).
enum class DwellPWord { Milliseconds, SecondsWithPoint };
/// Cutting (a feed move, an arc, a thread or a cycle) before any T word has named a tool: the
/// machine cuts with whatever its turret was left at (a warning), or the control (a trainer's
/// software) refuses to cut with no tool selected (an error).
enum class CutWithoutTool { Warning, Error };

/// The defaults are the gsk980tdi preset's values (control_preset.cpp; a test keeps them equal).
struct ControlParameters {
  RapidPath rapidPath{};
  DecimalPointInput decimalPointInput{};
  double leastIncrementMm = 0.001;  // IS-B 0.001 mm (0.0001 inch), IS-C 0.0001 mm
  IncrementWordInput incrementWordInput{};
  bool blockSkip = true;                // the operator's block skip switch: '/' blocks skipped
  FeedMode powerOnFeedMode{};           // G98 or G99 before the program names one
  bool powerOnMetric = true;            // G21 (mm) or G20 (inch) before the program names one
  bool roughingRetractAtFeed = true;    // G71/G72 step 4, the 45° retract: at F, or rapid
  bool peckXWordsAreDiameters = true;   // G74/G75 P(Δi) and G74 R(Δd): diameters or radii
  PeckReliefWithoutShift peckReliefWithoutShift{};
  PatternSinglePass patternSinglePass{};
  ArcEndOffCircle arcEndOffCircle{};
  double arcRadiusToleranceMm = 0.01;   // how far an arc's end may lie off its circle
  OffsetAfterReturn offsetAfterReturn{};
  AbsoluteWithIncremental absoluteWithIncremental{};
  DrawingAngleWord drawingAngleWord{};
  CornerWords cornerWords{};
  ChamferSize chamferSize{};
  std::vector<std::string> toolWordForms{"2+2"};  // the T word's forms (tool_word.hpp)
  MachineMCodes machineMCodes{};    // whose machine M codes are accepted and ignored
  DwellPWord dwellPWord{};          // G04 P: milliseconds, or seconds when written with a point
  // The compound cycles' first-block values before a program gives them:
  double roughingDepthMm = 1.0;     // G71/G72 Δd
  double roughingRetractMm = 0.5;   // G71/G72 e
  double patternReliefXMm = 0.0;    // G73 Δi, a radius
  double patternReliefZMm = 0.0;    // G73 Δk
  int patternPasses = 1;            // G73 d
  double peckRetractMm = 0.5;       // G74/G75 e
  int threadFinishingPasses = 1;    // G76 m
  int threadToolAngleDeg = 60;      // G76 a
  double threadMinDepthMm = 0.0;    // G76 Δdmin, a radius
  double threadAllowanceMm = 0.0;   // G76 d, a radius
  // The thread run-out of G92 and G76 when the program gives none, in leads (GSK No.19 and
  // Fanuc No.5130 count it in 0.1 lead): as long along the axis as it pulls out.
  double threadRunoutLeads = 0.0;
  // The angle of that run-out to the Z axis, in whole degrees 1–89; 0 means 45° (Fanuc No.5131).
  int threadRunoutAngleDeg = 0;
  ThreadEWord threadEWord{};
  CutWithoutTool cutWithoutTool{};  // a cut before any tool is called: warned of, or refused
};

}  // namespace lathesim::interp
