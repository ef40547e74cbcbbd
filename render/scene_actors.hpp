#pragma once
// Inside render only: the solid things of the part pictures besides the part — the bar's
// ghost, the chuck, the section view's cut faces — as VTK actors.

#include <vector>

#include <vtkSmartPointer.h>

#include "geometry/meridian_profile.hpp"
#include "render/overlay_2d.hpp"
#include "render/part_image.hpp"

class vtkActor;
class vtkPlane;

namespace lathesim::render {

// The colours the pictures share (tests look for them at known places).
inline constexpr Rgb kMetalColour{0.74, 0.76, 0.79};
inline constexpr Rgb kGhostColour{1.00, 0.55, 0.08};     // the bar before cutting, faint
inline constexpr double kGhostOpacity = 0.30;
inline constexpr Rgb kGhostLineColour{0.80, 0.45, 0.10}; // its outline
inline constexpr Rgb kChuckColour{0.20, 0.27, 0.40};     // dark blue steel: the body
inline constexpr Rgb kJawColour{0.34, 0.42, 0.58};       // the jaws, a lighter blue steel
inline constexpr Rgb kTailstockColour{0.30, 0.50, 0.38};  // the tailstock's centre and quill: green steel
inline constexpr Rgb kCutFaceColour{0.62, 0.70, 0.82};   // the section view's cut through the part
inline constexpr Rgb kDimensionColour{0.55, 0.08, 0.60};
inline constexpr Rgb kInkColour{0.15, 0.15, 0.18};

/// The bar as a faint see-through ghost: only its far side is drawn, so it tints what lies
/// behind the removed material and leaves the part in front untouched.
vtkSmartPointer<vtkActor> ghostActor(const BarOutline& bar);

/// The chuck: three jaws (the first straight up, +X) on the body. `keepBelowAxis`: only x ≤ 0
/// (the section view cuts the rest away and draws the cut).
std::vector<vtkSmartPointer<vtkActor>> chuckActors(const ChuckPicture& chuck, bool keepBelowAxis);

/// The tailstock's centre and quill, whole in every view (nothing of it is cut open).
vtkSmartPointer<vtkActor> tailstockActor(const TailstockPicture& tailstock);

/// The section view's cut faces in the plane y = 0, r ≥ 0: the part's (from its sampled
/// section: the samples inside, as runs of squares) and the chuck's jaws and body.
vtkSmartPointer<vtkActor> partCutActor(const SampledSection& section);
std::vector<vtkSmartPointer<vtkActor>> chuckCutActors(const ChuckPicture& chuck);

/// The plane that keeps x ≤ 0 (the lower half, below the axis, in the front view).
vtkSmartPointer<vtkPlane> belowAxisPlane();

}  // namespace lathesim::render
