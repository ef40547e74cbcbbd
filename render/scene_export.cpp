#include "render/scene_export.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>
#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkCamera.h>
#include <vtkGLTFExporter.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "render/offscreen_display.hpp"
#include "render/picture_annotations.hpp"
#include "render/scene_actors.hpp"
#include "render/move_points.hpp"
#include "render/vtk_scene.hpp"

namespace lathesim::render {
namespace {

using Json = nlohmann::json;

std::string decodeBase64(const std::string& text) {
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  int table[256];
  std::fill(std::begin(table), std::end(table), -1);
  for (std::size_t i = 0; i < alphabet.size(); ++i) table[static_cast<unsigned char>(alphabet[i])] = static_cast<int>(i);
  std::string out;
  out.reserve(text.size() * 3 / 4);
  unsigned value = 0;
  int bits = 0;
  for (char c : text) {
    const int digit = table[static_cast<unsigned char>(c)];
    if (digit < 0) continue;  // '=' padding, line breaks
    value = (value << 6) | static_cast<unsigned>(digit);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((value >> bits) & 0xFF));
    }
  }
  return out;
}

/// How a move is drawn, each in its own colour as in the pictures (picture_annotations.hpp).
enum class DrawnAs { Feed, Thread, Rapid };

DrawnAs drawnAs(const interp::Move& move) {
  if (move.kind == interp::MoveKind::Thread) return DrawnAs::Thread;
  return interp::isCutting(move.kind) ? DrawnAs::Feed : DrawnAs::Rapid;
}

/// The moves drawn as `kind` as polylines at (r, 0, z).
vtkSmartPointer<vtkPolyData> toolpathPolyData(const interp::Toolpath& toolpath, DrawnAs kind) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (const interp::Move& move : toolpath.moves) {
    if (drawnAs(move) != kind || move.kind == interp::MoveKind::Dwell) continue;
    const std::vector<RZ> drawn = movePoints(move);
    lines->InsertNextCell(static_cast<vtkIdType>(drawn.size()));
    for (const RZ& p : drawn) lines->InsertCellPoint(points->InsertNextPoint(p.x(), 0.0, p.y()));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  return data;
}

vtkSmartPointer<vtkActor> colouredActor(vtkPolyData* data, const Rgb& colour) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetSpecular(0.3);
  return actor;
}

}  // namespace

std::string partGltf(const TriangleMesh& part, const interp::Toolpath& toolpath) {
  ensureDisplay();  // a VTK window, though nothing is drawn
  vtkNew<vtkRenderer> renderer;
  if (!part.triangles.empty()) renderer->AddActor(colouredActor(toPolyData(part), kMetalColour));
  for (const auto& [kind, colour] : {std::pair{DrawnAs::Feed, kFeedColour}, std::pair{DrawnAs::Thread, kThreadColour},
                                      std::pair{DrawnAs::Rapid, kRapidColour}}) {
    const auto lines = toolpathPolyData(toolpath, kind);
    if (lines->GetNumberOfCells() > 0) renderer->AddActor(colouredActor(lines, colour));
  }
  // The exporter puts the scene under a node holding the camera's view matrix: an identity
  // camera (at the origin, looking down −Z) leaves the coordinates as they are.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 0);
  camera->SetFocalPoint(0, 0, -1);
  camera->SetViewUp(0, 1, 0);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  vtkNew<vtkGLTFExporter> exporter;
  exporter->SetRenderWindow(window);
  exporter->InlineDataOn();
  Json gltf = Json::parse(exporter->WriteToString());

  // One root in metres, glTF's Y up: part (x, y, z) mm → glTF (z, x, y) / 1000. The camera
  // goes: a viewer frames the part itself.
  Json& scene = gltf["scenes"][0];
  Json root = {{"name", "lathesim part"},
               {"matrix", {0, 0.001, 0, 0, 0, 0, 0.001, 0, 0.001, 0, 0, 0, 0, 0, 0, 1}},  // column-major
               {"children", scene["nodes"]}};
  for (Json& node : gltf["nodes"]) node.erase("camera");
  gltf.erase("cameras");
  gltf["nodes"].push_back(root);
  scene["nodes"] = Json::array({gltf["nodes"].size() - 1});
  gltf["asset"]["generator"] = "lathesim (VTK glTF exporter)";
  return gltf.dump();
}

std::string gltfToGlb(const std::string& text) {
  Json gltf = Json::parse(text);
  // Every buffer into one binary chunk, each started on a multiple of 4 bytes.
  std::string binary;
  std::vector<std::size_t> offsets;
  for (const Json& buffer : gltf.value("buffers", Json::array())) {
    const std::string uri = buffer.value("uri", "");
    const auto comma = uri.find(',');
    if (uri.rfind("data:", 0) != 0 || comma == std::string::npos)
      throw std::runtime_error("glTF buffer is not inline data");
    while (binary.size() % 4) binary.push_back('\0');
    offsets.push_back(binary.size());
    binary += decodeBase64(uri.substr(comma + 1));
  }
  while (binary.size() % 4) binary.push_back('\0');
  for (Json& view : gltf["bufferViews"]) {
    const std::size_t index = view.value("buffer", 0u);
    view["byteOffset"] = offsets.at(index) + view.value("byteOffset", 0u);
    view["buffer"] = 0;
  }
  gltf["buffers"] = Json::array({{{"byteLength", binary.size()}}});
  std::string json = gltf.dump();
  while (json.size() % 4) json.push_back(' ');

  std::string glb;
  auto put32 = [&glb](std::uint32_t v) {
    char bytes[4];
    std::memcpy(bytes, &v, 4);  // GLB is little-endian, as this machine
    glb.append(bytes, 4);
  };
  put32(0x46546C67);  // "glTF"
  put32(2);
  put32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + binary.size()));
  put32(static_cast<std::uint32_t>(json.size()));
  put32(0x4E4F534A);  // "JSON"
  glb += json;
  put32(static_cast<std::uint32_t>(binary.size()));
  put32(0x004E4942);  // "BIN\0"
  glb += binary;
  return glb;
}

void writeFileBytes(const std::string& bytes, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  // With the system's reason (a full disk: "No space left on device").
  if (!out) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
}

void writePartGltf(const TriangleMesh& part, const interp::Toolpath& toolpath, const std::filesystem::path& file) {
  writeFileBytes(partGltf(part, toolpath), file);
}

void writePartPly(const TriangleMesh& part, const std::filesystem::path& file) {
  const std::string name = file.string();
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(toPolyData(part));
  writer->SetFileName(name.c_str());
  writer->SetFileTypeToBinary();
  writer->SetDataByteOrderToLittleEndian();
  if (writer->Write() != 1) throw std::runtime_error("cannot write " + name);
}

void writePartObj(const TriangleMesh& part, const std::filesystem::path& file) {
  const std::string name = file.string();
  vtkNew<vtkOBJWriter> writer;
  writer->SetInputData(toPolyData(part));
  writer->SetFileName(name.c_str());
  if (writer->Write() != 1) throw std::runtime_error("cannot write " + name);
}

}  // namespace lathesim::render
