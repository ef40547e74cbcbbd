#pragma once
// The two pictures of a drawing check: the part coloured by its signed deviation from the
// drawing, and a half-section of the part's profile against the drawing's line.

#include <filesystem>
#include <string>
#include <vector>

#include "geometry/meridian_profile.hpp"
#include "geometry/triangle_mesh.hpp"
#include "render/rgb_image.hpp"

namespace lathesim::render {

// The colour scale: gouge (material missing) blue, within tolerance green, excess red.
// Tests look for these at known places.
inline constexpr double kGougeRgb[3] = {0.10, 0.30, 0.95};
inline constexpr double kWithinRgb[3] = {0.20, 0.72, 0.30};
inline constexpr double kExcessRgb[3] = {0.92, 0.12, 0.10};

struct DeviationImageOptions {
  int widthPx = 1600;
  int heightPx = 1200;
  std::string title;
  double toleranceMm = 0.1;
  std::string caption;  // a line of figures under the title (max excess, max gouge)
};

/// The shaded part, each vertex coloured by `deviationMm` (one per mesh vertex; > 0 excess,
/// < 0 gouge): green within ±tolerance, blue shades for gouge and red shades for excess, up
/// to the largest |deviation| (at least twice the tolerance), with a labelled colour bar.
/// Throws std::runtime_error unless there is one deviation per vertex.
RgbImage deviationImage(const TriangleMesh& part, const std::vector<float>& deviationMm,
                        const DeviationImageOptions& options);
/// The same picture as the PNG file `png`.
void writeDeviationImagePng(const TriangleMesh& part, const std::vector<float>& deviationMm,
                            const DeviationImageOptions& options, const std::filesystem::path& png);

struct SectionLabel {
  RZ at{0, 0};
  std::string text;
  bool gouge = false;
};

struct SectionImage {
  int widthPx = 1600;
  int heightPx = 900;
  std::string title;
  std::string caption;           // a line of figures under the title
  std::vector<Segment> drawing;  // the drawing's line (r, z)
  std::vector<Segment> part;     // the simulated profile
  double cellMm = 0;             // the size of the squares below
  std::vector<RZ> excessCells;   // centres of the section's samples that are excess / gouge
  std::vector<RZ> gougeCells;
  std::vector<SectionLabel> labels;  // every finding not within its tolerance, worst first
};

/// Where a point of the half-plane lands in the section picture: Z to the right, r up, both
/// at the same scale, everything drawn framed with a margin. Pixel (0, 0) is the lower left.
struct SectionFrame {
  RZ centre{0, 0};  // (r, z) at the picture's centre
  double pxPerMm = 1;
  int widthPx = 0, heightPx = 0;
  Eigen::Vector2d pixelOf(const RZ& p) const {
    return {widthPx / 2.0 + (p.y() - centre.y()) * pxPerMm, heightPx / 2.0 + (p.x() - centre.x()) * pxPerMm};
  }
};
SectionFrame sectionFrame(const SectionImage& image);

/// A label's box in the section picture, pixels from the lower left.
struct LabelBox {
  double left = 0, bottom = 0, right = 0, top = 0;
  bool intersects(const LabelBox& o) const { return left < o.right && o.left < right && bottom < o.top && o.bottom < top; }
};

/// Where each of image.labels stands (in order; the first get the places nearest their
/// points): above the profile, in slots of a grid that no two share, so that none overprints
/// another. Labels beyond the grid's slots get none (fewer boxes than labels).
std::vector<LabelBox> sectionLabelBoxes(const SectionImage& image, const SectionFrame& frame);

/// The half-section (r ≥ 0): the drawing's line in black, the part's profile in blue, excess
/// filled red and gouge filled blue, each label in its kind's colour with a leader to its point.
void writeSectionImagePng(const SectionImage& image, const std::filesystem::path& png);

}  // namespace lathesim::render
