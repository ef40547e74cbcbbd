// ISO 5608 holder designations against ../shared/spec/iso-tools.md §2 (style table §2.3,
// lengths §2.8, f ≈ 1.25·b with 25 → 32 in §2.11).

#include "geometry/iso_holder.hpp"

#include <gtest/gtest.h>

namespace lathesim {
namespace {

IsoHolder holderOf(std::string_view code) {
  const auto parsed = parseIsoHolder(code);
  EXPECT_TRUE(parsed.value) << code << ": " << (parsed.problem ? parsed.problem->message : "");
  return parsed.value.value_or(IsoHolder{});
}

CodeProblem holderProblemOf(std::string_view code) {
  const auto parsed = parseIsoHolder(code);
  EXPECT_FALSE(parsed.value) << code;
  return parsed.problem.value_or(CodeProblem{});
}

TEST(IsoHolder, PCLNR2525M12) {
  const IsoHolder h = holderOf("PCLNR2525M12");
  EXPECT_EQ(h.clamping, 'P');
  EXPECT_EQ(h.insertShape, 'C');
  EXPECT_EQ(h.style, 'L');
  EXPECT_DOUBLE_EQ(h.enteringAngleDeg, 95.0);
  EXPECT_EQ(h.family, HolderFamily::Side);
  EXPECT_TRUE(h.offsetShank);
  EXPECT_EQ(h.clearance, 'N');
  EXPECT_EQ(h.hand, 'R');
  EXPECT_DOUBLE_EQ(h.shankHeightMm, 25.0);
  EXPECT_DOUBLE_EQ(h.shankWidthMm, 25.0);
  EXPECT_DOUBLE_EQ(h.lengthMm, 150.0);  // M
  EXPECT_EQ(h.edgeSizeCode, "12");
  EXPECT_DOUBLE_EQ(h.functionalWidthMm(), 32.0);  // PCLNR 2525M12: f = 32 (§2.11)
}

TEST(IsoHolder, SeedsSTFCR2525M11) {
  // §5: screw clamp, T insert, style F (90°, end-cutting: facing), C 7°, right hand, 25×25, M 150, edge 11.
  const IsoHolder h = holderOf("STFCR2525M11");
  EXPECT_EQ(h.clamping, 'S');
  EXPECT_EQ(h.insertShape, 'T');
  EXPECT_EQ(h.style, 'F');
  EXPECT_DOUBLE_EQ(h.enteringAngleDeg, 90.0);
  EXPECT_EQ(h.family, HolderFamily::End);
  EXPECT_EQ(h.clearance, 'C');
  EXPECT_EQ(h.hand, 'R');
  EXPECT_DOUBLE_EQ(h.lengthMm, 150.0);
  EXPECT_EQ(h.edgeSizeCode, "11");
}

TEST(IsoHolder, JStylesAndLeftHand) {
  const IsoHolder v = holderOf("SVJBR2525M16");
  EXPECT_EQ(v.insertShape, 'V');
  EXPECT_DOUBLE_EQ(v.enteringAngleDeg, 93.0);
  EXPECT_EQ(v.family, HolderFamily::Side);
  EXPECT_EQ(v.clearance, 'B');
  const IsoHolder t = holderOf("MTJNR2525M16");
  EXPECT_EQ(t.clamping, 'M');
  EXPECT_DOUBLE_EQ(t.enteringAngleDeg, 93.0);
  const IsoHolder l = holderOf("DCLNL2020K12");
  EXPECT_EQ(l.clamping, 'D');
  EXPECT_EQ(l.hand, 'L');
  EXPECT_DOUBLE_EQ(l.shankHeightMm, 20.0);
  EXPECT_DOUBLE_EQ(l.lengthMm, 125.0);            // K
  EXPECT_DOUBLE_EQ(l.functionalWidthMm(), 25.0);  // 20 → 25
}

TEST(IsoHolder, SymmetricStylesTakeKappaFromTheInsert) {
  // κr = (180° − ε)/2: D + S 45°, N + D 62.5°, V + V 72.5° (§2.3).
  EXPECT_DOUBLE_EQ(holderOf("PSDNN2525M12").enteringAngleDeg, 45.0);
  EXPECT_DOUBLE_EQ(holderOf("PDNNN2525M15").enteringAngleDeg, 62.5);
  const IsoHolder v = holderOf("SVVBN2525M16");
  EXPECT_DOUBLE_EQ(v.enteringAngleDeg, 72.5);
  EXPECT_EQ(v.family, HolderFamily::Symmetric);
  EXPECT_DOUBLE_EQ(v.functionalWidthMm(), 12.5);  // b/2
}

TEST(IsoHolder, OtherLengthsAndEndStyles) {
  EXPECT_DOUBLE_EQ(holderOf("PSKNR3232P19").lengthMm, 170.0);  // P
  EXPECT_DOUBLE_EQ(holderOf("PSKNR3232P19").enteringAngleDeg, 75.0);
  EXPECT_EQ(holderOf("PSKNR3232P19").family, HolderFamily::End);
  EXPECT_DOUBLE_EQ(holderOf("PTGNR1616H16").lengthMm, 100.0);  // H
  EXPECT_DOUBLE_EQ(holderOf("PTGNR1616H16").functionalWidthMm(), 20.0);  // 16 → 20
}

TEST(IsoHolderErrors, EachPositionNamesItsCharacter) {
  CodeProblem p = holderProblemOf("QCLNR2525M12");
  EXPECT_EQ(p.message, "holder QCLNR2525M12: position 1 'Q' is not a clamping system; expected one of C M P S D W");
  p = holderProblemOf("PCZNR2525M12");
  EXPECT_EQ(p.index, 2u);
  EXPECT_EQ(p.message, "holder PCZNR2525M12: position 3 'Z' is not a holder style; expected one of A B C D E F G H J K L M N P Q R S T U V W Y");
  p = holderProblemOf("PCLNX2525M12");
  EXPECT_EQ(p.message, "holder PCLNX2525M12: position 5 'X' is not a hand for style L; expected R or L");
  p = holderProblemOf("PSDNR2525M12");
  EXPECT_EQ(p.message, "holder PSDNR2525M12: position 5 'R' is not the hand of a symmetric style; expected N");
  p = holderProblemOf("PCLNR25A5M12");
  EXPECT_EQ(p.index, 7u);
  EXPECT_EQ(p.message, "holder PCLNR25A5M12: position 7 'A5' is not a shank width; expected two digits (mm)");
  p = holderProblemOf("PCLNR2525I12");
  EXPECT_EQ(p.index, 9u);
  EXPECT_NE(p.message.find("position 8 'I' is not a tool length letter"), std::string::npos) << p.message;
  p = holderProblemOf("PCLNR2525X12");
  EXPECT_NE(p.message.find("position 8 'X' is a special length"), std::string::npos) << p.message;
  p = holderProblemOf("PCLNR2525M1A");
  EXPECT_EQ(p.index, 10u);
  EXPECT_NE(p.message.find("position 9 '1A' is not a cutting-edge length"), std::string::npos) << p.message;
  // H is 107.5°: with an 80° C insert κr + ε = 187.5° > 180°.
  p = holderProblemOf("SCHCR2525M12");
  EXPECT_EQ(p.message, "holder SCHCR2525M12: position 3 'H' has κr 107.5°, which leaves no room for a 80° insert (κr + ε must stay below 180°)");
  EXPECT_NE(holderProblemOf("PCLNR2525").message.find("too short"), std::string::npos);
}

}  // namespace
}  // namespace lathesim
