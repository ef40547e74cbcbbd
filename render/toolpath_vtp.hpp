#pragma once
// toolpath.vtp: the toolpath for ParaView and other VTK readers, written by hand as VTK XML
// PolyData straight from a move spool, so that a long program's toolpath is never built in
// memory (vtkXMLPolyDataWriter needs the whole polydata). Its arrays are compressed as that
// writer compresses them by default (render/zlib_appended_array.hpp): some ten times smaller.

#include <filesystem>

#include "interp/output/move_spool.hpp"

namespace lathesim::render {

/// One polyline cell per primitive move (X as radius, in part coordinates, Y = 0; an arc
/// through points along it, render/move_points.hpp), with cell data "line" (int), "kind"
/// (0 rapid, 1 feed, 2 G02, 3 G03, 4 dwell, 5 thread) and "feed": zlib-compressed appended
/// binary. Reads the spool once; memory stays flat in the number of moves (the compressed
/// arrays wait in temporary files). Throws std::runtime_error on I/O failure.
void writeToolpathVtp(const interp::MoveSpool& moves, const std::filesystem::path& vtp);

}  // namespace lathesim::render
