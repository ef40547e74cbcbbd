#pragma once
// toolpath.vtp: the toolpath for ParaView and other VTK readers, written by hand as VTK XML
// PolyData straight from a move spool, so that a long program's toolpath is never built in
// memory (vtkXMLPolyDataWriter needs the whole polydata).

#include <filesystem>

#include "interp/move_spool.hpp"

namespace lathesim::render {

/// One polyline cell per primitive move (X as radius, in part coordinates, Y = 0; an arc
/// through points along it, render/move_points.hpp), with cell data "line" (int), "kind"
/// (0 rapid, 1 feed, 2 G02, 3 G03, 4 dwell, 5 thread) and "feed": raw appended binary. Reads
/// the spool a few times over. Throws std::runtime_error on I/O failure.
void writeToolpathVtp(const interp::MoveSpool& moves, const std::filesystem::path& vtp);

}  // namespace lathesim::render
