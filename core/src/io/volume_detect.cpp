// volume_detect.cpp — which volume reader a file goes to (volume_format_from_path,
// detect_volume_format) and the entry points that dispatch on it: read_volume_mesh (bytes in
// memory) and read_volume_mesh_file (a file, or the .node/.ele pair by either name).
#include <string>
#include <string_view>

#include "io/reader.h"
#include "io/text_scan.h"
#include "kergen/volume.h"

namespace kergen {

using namespace io;

namespace {

std::string_view extension_of(const std::string& path) {
  const size_t slash = path.find_last_of("/\\");
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  return std::string_view(path).substr(dot + 1);
}

VolumeReadResult failure(Error error, std::string message) {
  VolumeReadResult result;
  result.error = error;
  result.message = std::move(message);
  return result;
}

}  // namespace

VolumeFormat volume_format_from_path(const std::string& path) {
  const std::string_view extension = extension_of(path);
  if (equals_ignore_case(extension, "vtu")) return VolumeFormat::Vtu;
  if (equals_ignore_case(extension, "vtk")) return VolumeFormat::VtkLegacy;
  if (equals_ignore_case(extension, "node") || equals_ignore_case(extension, "ele")) return VolumeFormat::NodeEle;
  return VolumeFormat::Unknown;
}

VolumeFormat detect_volume_format(std::string_view bytes) {
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  size_t i = 0;
  while (i < bytes.size() && (is_blank(bytes[i]) || bytes[i] == '\n')) ++i;
  bytes.remove_prefix(i);
  if (bytes.substr(0, 5) == "<?xml" || bytes.substr(0, 8) == "<VTKFile") return VolumeFormat::Vtu;
  if (bytes.substr(0, 14) == "# vtk DataFile") return VolumeFormat::VtkLegacy;
  return VolumeFormat::Unknown;
}

VolumeReadResult read_volume_mesh(std::string_view bytes, VolumeFormat format, const std::string& name) {
  if (format == VolumeFormat::Unknown) format = detect_volume_format(bytes);
  switch (format) {
    case VolumeFormat::Vtu: return read_vtu(bytes, name);
    case VolumeFormat::VtkLegacy: return read_vtk_legacy(bytes, name);
    case VolumeFormat::NodeEle:
      return failure(Error::InvalidArgument, name + ": the .node/.ele format needs both files (read_node_ele)");
    case VolumeFormat::Unknown: break;
  }
  if (only_blank(bytes)) return failure(Error::EmptyInput, name + ": empty file");
  return failure(Error::ParseError,
                 name + ": unknown volume mesh format: the content is neither VTK XML (.vtu) nor legacy VTK (.vtk)");
}

VolumeReadResult read_volume_mesh_file(const std::string& path, size_t max_bytes) {
  VolumeFormat format = volume_format_from_path(path);
  VolumeReadResult result;
  if (format == VolumeFormat::NodeEle) {
    const std::string stem = path.substr(0, path.size() - extension_of(path).size());
    const std::string node_path = stem + "node", ele_path = stem + "ele";
    std::string node, ele;
    if (!read_file_bytes(node_path, max_bytes, node, result.error, result.message)) return result;
    if (!read_file_bytes(ele_path, max_bytes, ele, result.error, result.message)) return result;
    return read_node_ele(node, ele, node_path, ele_path);
  }
  std::string bytes;
  if (!read_file_bytes(path, max_bytes, bytes, result.error, result.message)) return result;
  if (format == VolumeFormat::Unknown) format = detect_volume_format(bytes);
  if (format == VolumeFormat::Unknown && !only_blank(bytes))
    return failure(Error::ParseError, path +
                                          ": unknown volume mesh format: the name does not end in .vtu, .vtk, .node "
                                          "or .ele and the content is neither VTK XML nor legacy VTK");
  return read_volume_mesh(bytes, format, path);
}

}  // namespace kergen
