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

}  // namespace lathesim::render
