// The public name functions and tables (kergen.h): how each enum value, option and Stats field is
// spelt, once, so that the CLI's JSON, the wasm module and the JS package never spell one of
// their own.
#include <array>
#include <vector>

#include "kergen/kergen.h"

namespace kergen {

const char* error_name(Error e) {
  switch (e) {
    case Error::Ok: return "OK";
    case Error::EmptyInput: return "EMPTY_INPUT";
    case Error::NonFiniteCoordinate: return "NON_FINITE_COORDINATE";
    case Error::IndexOutOfRange: return "INDEX_OUT_OF_RANGE";
    case Error::FaceTooSmall: return "FACE_TOO_SMALL";
    case Error::OpenMesh: return "OPEN_MESH";
    case Error::NonManifoldEdge: return "NON_MANIFOLD_EDGE";
    case Error::InconsistentOrientation: return "INCONSISTENT_ORIENTATION";
    case Error::MultipleComponents: return "MULTIPLE_COMPONENTS";
    case Error::DegenerateInput: return "DEGENERATE_INPUT";
    case Error::TooLarge: return "TOO_LARGE";
    case Error::ParseError: return "PARSE_ERROR";
    case Error::IoError: return "IO_ERROR";
    case Error::InvalidArgument: return "INVALID_ARGUMENT";
    case Error::CoordinateRange: return "COORDINATE_RANGE";
    case Error::Internal: return "INTERNAL_ERROR";
    case Error::SelfIntersection: return "SELF_INTERSECTION";
  }
  return "UNKNOWN";
}

const char* kernel_type_name(KernelType t) {
  switch (t) {
    case KernelType::Empty: return "EMPTY";
    case KernelType::Point: return "POINT";
    case KernelType::Segment: return "SEGMENT";
    case KernelType::Polygon: return "POLYGON";
    case KernelType::Polyhedron: return "POLYHEDRON";
    case KernelType::Unbounded: return "UNBOUNDED";
  }
  return "UNKNOWN";
}

const std::vector<OptionName>& option_names() {
  static const std::vector<OptionName> names = {
      {"allow_open", "--allow-open", "allowOpen: true"},
      {"open_boundary", "--open perpendicular", "open: 'perpendicular'"},
      {"weld_relative", "--weld-relative", "weld: { relative }"},
      {"weld", "--weld", "weld: true"},
      {"repair", "--repair", "repair: true"},
      {"flip_faces", "--flip-faces", "flipFaces: true"},
      {"deepest_point", "--deepest", "deepestPoint: true"},
      {"max_steps", "--max-steps", "maxSteps"},
      {"cull_faces", "--no-cull-faces", "cullFaces"},
      {"seed", "--seed", "seed"},
      {"max_faces", nullptr, "options.maxFaces"},
      {"max_vertices", nullptr, "options.maxVertices"},
      {"on_step", nullptr, "onStep"},
      {"on_progress", nullptr, "onProgress"},
      {"from", "--from", "from"},
  };
  return names;
}

const char* open_boundary_name(OpenBoundary o) {
  switch (o) {
    case OpenBoundary::Clip: return "clip";
    case OpenBoundary::Perpendicular: return "perpendicular";
  }
  return "unknown";
}

const char* warning_kind_name(Warning::Kind k) {
  switch (k) {
    case Warning::Kind::OrientationFlipped: return "ORIENTATION_FLIPPED";
    case Warning::Kind::DegenerateFacesDropped: return "DEGENERATE_FACES_DROPPED";
    case Warning::Kind::NonPlanarFacesSplit: return "NON_PLANAR_FACES_SPLIT";
    case Warning::Kind::UnusedVertices: return "UNUSED_VERTICES";
    case Warning::Kind::VerticesWelded: return "VERTICES_WELDED";
    case Warning::Kind::DuplicateFacesRemoved: return "DUPLICATE_FACES_REMOVED";
    case Warning::Kind::CancellingFacesRemoved: return "CANCELLING_FACES_REMOVED";
    case Warning::Kind::TJunctionsSplit: return "T_JUNCTIONS_SPLIT";
    case Warning::Kind::SeparateShells: return "SEPARATE_SHELLS";
    case Warning::Kind::FacesPointInward: return "FACES_POINT_INWARD";
    case Warning::Kind::CrossingsUnchecked: return "CROSSINGS_UNCHECKED";
  }
  return "UNKNOWN";
}

std::array<StatsField, 14> stats_fields(const Stats& s) {
  return {{{"input_vertices", double(s.input_vertices)},
           {"input_faces", double(s.input_faces)},
           {"dropped_faces", double(s.dropped_faces)},
           {"culled_faces", double(s.culled_faces)},
           {"distinct_planes", double(s.distinct_planes)},
           {"active_planes", double(s.active_planes)},
           {"traced_lines", double(s.traced_lines)},
           {"exact_fallbacks", double(s.exact_fallbacks)},
           {"ms_validate", s.ms_validate},
           {"ms_planes", s.ms_planes},
           {"ms_lp", s.ms_lp},
           {"ms_trace", s.ms_trace},
           {"ms_assemble", s.ms_assemble},
           {"ms_total", s.ms_total}}};
}

const char* progress_phase_name(Progress::Phase p) {
  switch (p) {
    case Progress::Phase::Validating: return "validating";
    case Progress::Phase::Planes: return "planes";
    case Progress::Phase::Lp: return "lp";
    case Progress::Phase::Tracing: return "tracing";
    case Progress::Phase::Assembling: return "assembling";
  }
  return "unknown";
}

}  // namespace kergen
