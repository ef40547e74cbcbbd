#pragma once
// The tool drawn in the part image: its insert and holder as slabs on the meridian plane
// (y = 0) at the tool's position, so a machinist sees where it stands by the part.
// Private to render (it speaks VTK); the public ToolPicture is in part_image.hpp.

#include <vector>

#include <vtkSmartPointer.h>

#include "render/overlay_2d.hpp"
#include "render/part_image.hpp"

class vtkActor;

namespace lathesim::render {

/// The insert and (if any) holder as solid slabs with dark edges. With the tool's own sizes
/// (ToolPicture::holderHeightMm, insertThicknessMm) at their real thickness behind the plane,
/// the insert's rake face a hair in front of it (so it shows on the holder's face, as it sits
/// at centre height on the shank); without, `thinMm` thick about the plane (the insert a
/// little thicker, so it shows in front of the holder it sits in).
std::vector<vtkSmartPointer<vtkActor>> toolActors(const ToolPicture& tool, double thinMm);

/// The corners of the tool drawn at `position` in 3D: every corner of the insert and the
/// holder on the meridian plane and, drawn at their real size, on their back faces behind it
/// (slabs drawn thin stand a fraction of a millimetre off the plane: left out).
std::vector<Eigen::Vector3d> toolCorners(const ToolPicture& tool, const RZ& position);

// Colours (RGB 0–1). The render tests look for the insert's gold.
inline constexpr Rgb kInsertColour{0.98, 0.76, 0.10};
inline constexpr Rgb kHolderColour{0.30, 0.33, 0.37};

/// How far the insert's rake face stands in front of the holder's (mm).
inline constexpr double kRakeFaceProudMm = 0.05;

}  // namespace lathesim::render
