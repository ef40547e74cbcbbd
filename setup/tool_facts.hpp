#pragma once
// What a tool is, as a person reads a tool table: the insert and holder it was built from,
// their sizes, and where lathesim got it (report.json's "tools", report.html's tool table).
// Its shape for cutting is ToolDefinition's; these facts are never simulated.

#include <optional>
#include <string>

#include "geometry/iso_holder.hpp"
#include "geometry/iso_insert.hpp"

namespace lathesim::setup {

struct ToolFacts {
  // "turning", "groove", "thread", "drill", "polygon" (a [[tool]] polygon) or "default" (the
  // default setup's placeholder outline: no tool was defined).
  std::string kind = "default";
  std::string insert;                        // the insert's catalogue code, "" when none was given
  std::string insertShape;                   // "C (80° rhombic)", "a 3 mm blade", … ; "" for a polygon
  std::optional<double> cuttingEdgeLengthMm; // an ISO insert's edge length l
  std::optional<double> insertAngleDeg;      // its corner angle ε; a threading insert's profile angle
  std::optional<double> enteringAngleDeg;    // the holder's κr
  std::string holder;                        // the holder's catalogue code, "" when none
  std::optional<double> shankWidthMm;        // b (across the tool's plane)
  std::optional<double> shankHeightMm;       // h
  // Where the tool came from: "setup.toml:12 tool[2]", "the comment '(…)' of the T word at prog.nc:12",
  // "the default setup (no tool defined)".
  std::string source = "the default setup (no tool defined)";
};

/// The facts of an ISO insert in an ISO holder (kind "turning").
ToolFacts turningFacts(const IsoInsert& insert, const IsoHolder& holder);

/// "C (80° rhombic)": an ISO 1832 shape letter and what it is.
std::string insertShapeName(const IsoInsert& insert);

}  // namespace lathesim::setup
