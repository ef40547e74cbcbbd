#include "render/toolpath_vtp.hpp"

#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "render/move_points.hpp"
#include "render/zlib_appended_array.hpp"

namespace lathesim::render {
namespace {

static_assert(std::endian::native == std::endian::little, "the file says LittleEndian; add byte swapping for this platform");

// The `kind` cell value.
std::int32_t vtpKind(interp::MoveKind kind) {
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

}  // namespace

void writeToolpathVtp(const interp::MoveSpool& moves, const std::filesystem::path& vtp) {
  // The one pass over the moves, each array compressed as it fills.
  ZLibAppendedArray line("toolpath.vtp's line numbers"), kind("toolpath.vtp's move kinds"), feed("toolpath.vtp's feeds");
  ZLibAppendedArray xyz("toolpath.vtp's points"), connectivity("toolpath.vtp's connectivity"), offsets("toolpath.vtp's offsets");
  std::int64_t points = 0;
  moves.forEach([&](const interp::Move& m) {
    line.add(static_cast<std::int32_t>(m.line));
    kind.add(vtpKind(m.kind));
    feed.add(m.feed);
    for (const RZ& p : movePoints(m)) {
      xyz.add(p.x()), xyz.add(0.0), xyz.add(p.y());
      connectivity.add(points++);  // each move's own points, in the order written
    }
    offsets.add(points);  // where the move's cell ends
  });

  // Each array's element, with its place in the appended data: made in the order the arrays
  // are copied there below.
  std::uint64_t appended = 0;
  const auto element = [&appended](ZLibAppendedArray& data, const char* type, const char* name, const char* components = "") {
    data.finish();
    const std::string xml = std::string("        <DataArray type=\"") + type + "\" Name=\"" + name + "\"" + components +
                                " format=\"appended\" offset=\"" + std::to_string(appended) + "\"/>\n";
    appended += data.appendedBytes();
    return xml;
  };
  std::string header = "<?xml version=\"1.0\"?>\n"
                       "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\""
                       " compressor=\"vtkZLibDataCompressor\">\n"
                       "  <PolyData>\n"
                       "    <Piece NumberOfPoints=\"" + std::to_string(points) + "\" NumberOfVerts=\"0\" NumberOfLines=\"" +
                       std::to_string(moves.size()) + "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
                       "      <CellData>\n";
  header += element(line, "Int32", "line");
  header += element(kind, "Int32", "kind");
  header += element(feed, "Float64", "feed");
  header += "      </CellData>\n      <Points>\n";
  header += element(xyz, "Float64", "Points", " NumberOfComponents=\"3\"");
  header += "      </Points>\n      <Lines>\n";
  header += element(connectivity, "Int64", "connectivity");
  header += element(offsets, "Int64", "offsets");
  header += "      </Lines>\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

  std::ofstream out(vtp, std::ios::binary | std::ios::trunc);
  out << header;
  for (const ZLibAppendedArray* data : {&line, &kind, &feed, &xyz, &connectivity, &offsets}) data->copyTo(out);
  out << "\n  </AppendedData>\n</VTKFile>\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + vtp.string() + ": " + std::strerror(errno));
}

}  // namespace lathesim::render
