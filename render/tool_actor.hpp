#pragma once
// The tool drawn in the part image: its insert and holder as thin slabs in the meridian
// plane (y = 0) at the tool's position, so a machinist sees where it stands by the part.
// Private to render (it speaks VTK); the public ToolPicture is in part_image.hpp.

#include <vector>

#include <vtkSmartPointer.h>

#include "render/part_image.hpp"

class vtkActor;

namespace lathesim::render {

/// The insert and (if any) holder as solid slabs `thicknessMm` thick (the insert a little
/// thicker, so it shows in front of the holder it sits in), with dark edges.
std::vector<vtkSmartPointer<vtkActor>> toolActors(const ToolPicture& tool, double thicknessMm);

}  // namespace lathesim::render
