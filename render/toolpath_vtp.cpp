#include "render/toolpath_vtp.hpp"

#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/move_points.hpp"

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

// One array of the appended data: its byte count (the UInt64 header), then its values,
// written through a buffer as a pass over the moves makes them.
class AppendedArray {
 public:
  AppendedArray(std::ofstream& out, std::uint64_t bytes) : out_(out) { out_.write(reinterpret_cast<const char*>(&bytes), sizeof bytes); }
  ~AppendedArray() { flush(); }
  template <typename T>
  void add(T value) {
    const std::size_t at = buffer_.size();
    buffer_.resize(at + sizeof value);
    std::memcpy(buffer_.data() + at, &value, sizeof value);
    if (buffer_.size() >= kBufferBytes) flush();
  }

 private:
  static constexpr std::size_t kBufferBytes = 1 << 16;
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }
  std::ofstream& out_;
  std::vector<char> buffer_;
};

}  // namespace

void writeToolpathVtp(const interp::MoveSpool& moves, const std::filesystem::path& vtp) {
  const std::uint64_t cells = moves.size();
  std::uint64_t points = 0;
  moves.forEach([&](const interp::Move& m) { points += movePoints(m).size(); });

  // Where each array's header starts in the appended data, in the order they are written.
  const std::uint64_t header = sizeof(std::uint64_t);
  const std::uint64_t lineAt = 0, kindAt = lineAt + header + 4 * cells, feedAt = kindAt + header + 4 * cells;
  const std::uint64_t pointsAt = feedAt + header + 8 * cells, connectivityAt = pointsAt + header + 24 * points;
  const std::uint64_t offsetsAt = connectivityAt + header + 8 * points;
  const auto array = [](const char* type, const char* name, std::uint64_t offset, const char* components = "") {
    return std::string("        <DataArray type=\"") + type + "\" Name=\"" + name + "\"" + components +
           " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
  };
  std::ofstream out(vtp, std::ios::binary | std::ios::trunc);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << points << "\" NumberOfVerts=\"0\" NumberOfLines=\"" << cells
      << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "      <CellData>\n"
      << array("Int32", "line", lineAt) << array("Int32", "kind", kindAt) << array("Float64", "feed", feedAt)
      << "      </CellData>\n"
      << "      <Points>\n"
      << array("Float64", "Points", pointsAt, " NumberOfComponents=\"3\"") << "      </Points>\n"
      << "      <Lines>\n"
      << array("Int64", "connectivity", connectivityAt) << array("Int64", "offsets", offsetsAt) << "      </Lines>\n"
      << "    </Piece>\n"
      << "  </PolyData>\n"
      << "  <AppendedData encoding=\"raw\">\n   _";
  {
    AppendedArray line(out, 4 * cells);
    moves.forEach([&](const interp::Move& m) { line.add(static_cast<std::int32_t>(m.line)); });
  }
  {
    AppendedArray kind(out, 4 * cells);
    moves.forEach([&](const interp::Move& m) { kind.add(vtpKind(m.kind)); });
  }
  {
    AppendedArray feed(out, 8 * cells);
    moves.forEach([&](const interp::Move& m) { feed.add(m.feed); });
  }
  {
    AppendedArray xyz(out, 24 * points);
    moves.forEach([&](const interp::Move& m) {
      for (const RZ& p : movePoints(m)) xyz.add(p.x()), xyz.add(0.0), xyz.add(p.y());
    });
  }
  {
    AppendedArray connectivity(out, 8 * points);  // each move's own points, in the order written
    for (std::uint64_t id = 0; id < points; ++id) connectivity.add(static_cast<std::int64_t>(id));
  }
  {
    AppendedArray offsets(out, 8 * cells);  // where each cell's points end
    std::int64_t end = 0;
    moves.forEach([&](const interp::Move& m) { offsets.add(end += static_cast<std::int64_t>(movePoints(m).size())); });
  }
  out << "\n  </AppendedData>\n</VTKFile>\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + vtp.string() + ": " + std::strerror(errno));
}

}  // namespace lathesim::render
