#include "render/mesh_files.hpp"

#include <array>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include "render/move_points.hpp"

namespace lathesim::render {
namespace {

static_assert(std::endian::native == std::endian::little,
              "binary STL is little-endian; add byte swapping for this platform");
static_assert(std::numeric_limits<float>::is_iec559, "binary STL stores IEEE 754 floats");

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kFacetBytes = 50;  // normal, 3 vertices (12 floats), uint16 attribute

void put(char*& out, const Eigen::Vector3f& v) {
  std::memcpy(out, v.data(), 3 * sizeof(float));
  out += 3 * sizeof(float);
}

}  // namespace

// Written by hand rather than with vtkSTLWriter: that would first copy the mesh into
// vtkPolyData (points + 64-bit connectivity, ~2× the mesh in memory) and then writes one
// facet at a time through its own normal computation. Here facets are packed into a 3 MB
// buffer and written in large blocks, so the cost is the disk, not the formatting.
void writeBinaryStl(const TriangleMesh& mesh, const std::filesystem::path& stl) {
  if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::runtime_error("cannot write " + stl.string() + ": " +
                             std::to_string(mesh.triangles.size()) +
                             " triangles exceed binary STL's 32-bit count");
  }
  std::ofstream out(stl, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + stl.string() + ": " + std::strerror(errno));

  // The header must not begin with "solid": some readers would take the file for ASCII STL.
  std::array<char, kHeaderBytes> header{};
  const std::string text = "lathesim binary STL, mm, Z = spindle axis";
  std::memcpy(header.data(), text.data(), std::min(text.size(), header.size()));
  out.write(header.data(), header.size());
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof count);

  constexpr std::size_t kFacetsPerChunk = 65536;
  std::vector<char> buffer(kFacetsPerChunk * kFacetBytes);
  std::size_t done = 0;
  while (done < mesh.triangles.size()) {
    const std::size_t n = std::min(kFacetsPerChunk, mesh.triangles.size() - done);
    char* p = buffer.data();
    for (std::size_t i = done; i < done + n; ++i) {
      const auto& t = mesh.triangles[i];
      for (std::uint32_t index : t) {
        if (index >= mesh.vertices.size()) {
          throw std::runtime_error("cannot write " + stl.string() + ": triangle " +
                                   std::to_string(i) + " refers to vertex " +
                                   std::to_string(index) + " of " +
                                   std::to_string(mesh.vertices.size()));
        }
      }
      const Eigen::Vector3f& a = mesh.vertices[t[0]];
      const Eigen::Vector3f& b = mesh.vertices[t[1]];
      const Eigen::Vector3f& c = mesh.vertices[t[2]];
      // Counter-clockwise seen from outside, so (b − a) × (c − a) points outwards.
      Eigen::Vector3f normal = (b - a).cross(c - a);
      const float length = normal.norm();
      normal = length > 0.0f ? Eigen::Vector3f(normal / length) : Eigen::Vector3f::Zero();
      put(p, normal);
      put(p, a);
      put(p, b);
      put(p, c);
      *p++ = 0;  // attribute byte count
      *p++ = 0;
    }
    out.write(buffer.data(), static_cast<std::streamsize>(n * kFacetBytes));
    done += n;
  }
  out.close();
  if (!out) throw std::runtime_error("cannot write " + stl.string() + ": " + std::strerror(errno));
}

// The `kind` cell value: 0 rapid, 1 feed, 2 clockwise arc (G02), 3 counter-clockwise arc
// (G03), 4 dwell, 5 thread.
int vtpKind(interp::MoveKind kind) {
  switch (kind) {
    case interp::MoveKind::Rapid: return 0;
    case interp::MoveKind::Feed: return 1;
    case interp::MoveKind::ArcCW: return 2;
    case interp::MoveKind::ArcCCW: return 3;
    case interp::MoveKind::Dwell: return 4;
    case interp::MoveKind::Thread: return 5;
  }
  return 1;
}

void writeToolpathVtp(const interp::Toolpath& toolpath, const std::filesystem::path& vtp) {
  const auto moveCount = static_cast<vtkIdType>(toolpath.moves.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> line;
  line->SetName("line");
  line->SetNumberOfValues(moveCount);
  vtkNew<vtkIntArray> kind;
  kind->SetName("kind");
  kind->SetNumberOfValues(moveCount);
  vtkNew<vtkDoubleArray> feed;
  feed->SetName("feed");
  feed->SetNumberOfValues(moveCount);

  for (vtkIdType i = 0; i < moveCount; ++i) {
    const interp::Move& m = toolpath.moves[static_cast<std::size_t>(i)];
    // One cell per move: a line, or for an arc a polyline through points along it.
    std::vector<vtkIdType> ids;
    for (const RZ& p : movePoints(m)) ids.push_back(points->InsertNextPoint(p.x(), 0.0, p.y()));
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    line->SetValue(i, m.line);
    kind->SetValue(i, vtpKind(m.kind));
    feed->SetValue(i, m.feed);
  }

  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetCellData()->AddArray(line);
  polyData->GetCellData()->AddArray(kind);
  polyData->GetCellData()->AddArray(feed);

  vtkNew<vtkXMLPolyDataWriter> writer;
  const std::string path = vtp.string();
  writer->SetFileName(path.c_str());
  writer->SetInputData(polyData);
  writer->SetDataModeToBinary();  // base64 inside the XML; zlib-compressed (small data)
  // Written to memory and then to the file here: VTK's own file writing reports a full disk
  // only on stderr and leaves the file short.
  writer->WriteToOutputStringOn();
  if (writer->Write() != 1) throw std::runtime_error("cannot write " + path + ": VTK could not encode the toolpath");
  const std::string xml = writer->GetOutputString();
  std::ofstream out(vtp, std::ios::binary | std::ios::trunc);
  out << xml;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

}  // namespace lathesim::render
