#pragma once
// ISO 5608 external turning-tool holder designations (PCLNR2525M12, STFCR2525M11, …): what
// is needed to place the insert and give the holder a body. Reference:
// ../shared/spec/iso-tools.md §2.
//
//   P C L N R 25 25 M 12 [option] [-maker suffix]
//   1 2 3 4 5  6  7 8  9
//   clamping, insert shape, style, insert clearance, hand, shank height, shank width,
//   length letter, cutting-edge length (the insert's size code).

#include <string>
#include <string_view>

#include "geometry/iso_code.hpp"

namespace lathesim {

/// How a style's entering angle is measured (§2.3): against a feed across the shank (side:
/// longitudinal turning on an external holder), along the shank (end: facing), or the
/// straight symmetric styles whose tip lies on the shank's centre line (hand N).
enum class HolderFamily { Side, End, Symmetric };

struct IsoHolder {
  std::string code;             // as given (upper case)
  char clamping = 'P';          // position 1: C M P S D
  char insertShape = 'C';       // position 2 (ISO 1832 position 1)
  char style = 'L';             // position 3
  double enteringAngleDeg = 95; // κr; for symmetric styles (180° − ε)/2 of the insert shape
  HolderFamily family = HolderFamily::Side;
  bool offsetShank = true;      // false: straight shank
  char clearance = 'N';         // position 4, the insert's clearance letter
  char hand = 'R';              // position 5: R L N
  double shankHeightMm = 25;    // position 6 (h; the cutting edge sits at this height)
  double shankWidthMm = 25;     // position 7 (b)
  double lengthMm = 150;        // position 8 (l1)
  std::string edgeSizeCode;     // position 9, e.g. "12": the insert size code it seats

  /// f: from the tip to the shank's back face (§2.11). Offset styles 1.25·b (16→20, 20→25,
  /// 25→32, 32→40); symmetric styles b/2; other straight styles b (an approximation).
  double functionalWidthMm() const;
};

/// Reads an ISO 5608 designation (case-insensitive). Only external holders: boring bars
/// (A25T-…, S20S-…) are not read.
ParsedCode<IsoHolder> parseIsoHolder(std::string_view code);

}  // namespace lathesim
