#pragma once
// Laydown threading inserts (the Iscar/Vargus scheme most makers follow, iso-tools.md §4.1):
//
//   16 E R [M] 2.00 ISO        16 I R 1.5 ISO        16 E R 14 W        16 E R AG 60
//   │  │ │  │   │    └ thread standard: ISO (metric 60°), UN (60°), W (Whitworth 55°),
//   │  │ │  │   │      BSPT (55°), NPT (60°); or 60 / 55, a partial profile of that angle
//   │  │ │  │   └ full profile: the pitch, in mm for ISO (written 2.00, 2.0 or 200 = hundredths),
//   │  │ │  │     in threads per inch for the inch standards; partial profile: a range letter,
//   │  │ │  │     A 0.5–1.5, AG 0.5–3.0, G 1.75–3.0, N 3.5–5.0, Q 5.5–6.0, U 5.5–9.0 mm
//   │  │ │  └ M: a pressed chipbreaker (no effect on the outline)
//   │  │ └ hand R, L or RL (the V is symmetric: no effect on the outline)
//   │  └ E external, I internal (U-type UE, UI, UEI read as E, I, E)
//   └ size: 06 08 11 16 22 27 = IC 5/32, 3/16, 1/4, 3/8, 1/2, 5/8 in
//
// Spaces are ignored. The nose radius is not in the code: full-profile ISO and UN inserts are
// taken with the external thread's root radius 0.125·P (internal: 0.0625·P, the nut's root ⚠),
// Whitworth and BSPT with BS 84's 0.137329·P, NPT 0.0 (its root is flat ⚠); a partial profile
// with the radius of the smallest pitch of its range ⚠. A setup's nose_radius overrides it.

#include <optional>
#include <string>
#include <string_view>

#include "geometry/iso_code.hpp"

namespace lathesim {

struct ThreadInsert {
  std::string code;           // as given, upper case, spaces removed
  std::string sizeCode;       // "16"
  double inscribedCircleMm = 0;
  bool internal = false;      // I: an internal (boring) insert, its point toward +X
  std::string hand;           // "R", "L" or "RL"
  std::string standard;       // "ISO", "UN", "W", "BSPT", "NPT", or "60" / "55" (partial)
  double profileDeg = 60;     // the included angle
  bool partialProfile = false;
  double pitchMm = 0;         // full profile: the pitch; partial: the largest of its range
  double minPitchMm = 0;      // partial: the smallest of its range (full: = pitchMm)
  double noseRadiusMm = 0;    // derived (see above)
};

ParsedCode<ThreadInsert> parseThreadInsert(std::string_view code);

/// Whether `code` reads as a laydown threading insert rather than an ISO 1832 one: it starts
/// with its two-digit size.
bool looksLikeThreadInsert(std::string_view code);

}  // namespace lathesim
