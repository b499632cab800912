// node_ele.cpp — the face-based .node/.ele pair of polyhedral meshes (read_node_ele), the "RF"
// format of the polyhedral mesh sets used in VEM quality studies and read by HArDCore3D's
// MeshReaderRF (github.com/jdroniou/HArDCore, src/Mesh/.../mesh_reader.cpp):
//   .node  header `nv dim attributes boundary-marker` (dim 3), then per vertex `id x y z`, followed
//          by that many attributes and the marker if the header announces them (TetGen's .node
//          layout, wias-berlin.de/software/tetgen/fformats.node.html);
//   .ele   header `ncells flag`, then per cell `cell-id nfaces` and per face
//          `face-id nverts vertex-id...` (read as a token stream: line breaks do not matter).
// Vertex ids start at the .node's first id (0 or 1) and are consecutive; '#' starts a comment.
// Faces are stored per cell as written (a face listed by two cells is stored twice).
#include <string>
#include <string_view>
#include <vector>

#include "io/numbers.h"
#include "io/reader.h"
#include "io/text_scan.h"
#include "io/volume_reader.h"
#include "kergen/volume.h"

namespace kergen {

using namespace io;

namespace {

// Whitespace-separated tokens across lines, comments stripped, with the line of each token.
class TokenStream {
 public:
  TokenStream(std::string_view text, const std::string& name)
      : lines_(text), tokens_(std::string_view{}), name_(name) {}
  bool next(std::string_view& token) {
    while (!tokens_.next(token)) {
      std::string_view line;
      if (!lines_.next(line)) return false;
      tokens_ = Tokens(strip_comment(line));
    }
    return true;
  }
  long long integer(const char* what) {
    std::string_view token;
    if (!next(token)) fail_at_line(name_, line(), std::string("file ends where ") + what + " was expected");
    long long v = 0;
    if (!parse_integer(token, v)) fail_at_line(name_, line(), std::string("invalid ") + what + " " + quoted(token));
    return v;
  }
  double number(const char* what) {
    std::string_view token;
    if (!next(token)) fail_at_line(name_, line(), std::string("file ends where ") + what + " was expected");
    double v = 0;
    switch (parse_double(token, v)) {
      case NumberStatus::Ok: break;
      case NumberStatus::Invalid: fail_at_line(name_, line(), "invalid number " + quoted(token));
      case NumberStatus::NonFinite: fail_at_line(name_, line(), "non-finite coordinate " + quoted(token));
    }
    return v;
  }
  // The rest of the current line (header lines have optional trailing fields).
  void skip_line() { tokens_ = Tokens(std::string_view{}); }
  bool line_done() { return tokens_.at_end(); }
  size_t line() const { return lines_.line_number(); }
  bool at_end() {
    std::string_view token;
    return !next(token);
  }

 private:
  LineReader lines_;
  Tokens tokens_;
  const std::string& name_;
};

long long header_count(TokenStream& in, const std::string& name, const char* what) {
  const long long n = in.integer(what);
  if (n < 0) fail_at_line(name, in.line(), std::string("negative ") + what);
  return n;
}

// Returns the first vertex id (the base of the .ele's ids).
long long read_nodes(std::string_view text, const std::string& name, VolumeMesh& mesh) {
  text = prepare_text(text, name);
  TokenStream in(text, name);
  const long long count = header_count(in, name, "vertex count");
  const size_t header_line = in.line();
  long long dim = 3, attributes = 0, markers = 0;
  if (!in.line_done()) dim = in.integer("dimension");
  if (dim != 3) fail_at_line(name, header_line, "dimension " + std::to_string(dim) + ", only 3 is read");
  if (!in.line_done()) attributes = header_count(in, name, "attribute count");
  if (!in.line_done()) markers = header_count(in, name, "boundary marker flag");
  in.skip_line();
  if (markers > 1) fail_at_line(name, header_line, "boundary marker flag must be 0 or 1");
  long long base = 0;
  for (long long v = 0; v < count; ++v) {
    const long long id = in.integer("vertex id");
    if (v == 0) {
      if (id != 0 && id != 1)
        fail_at_line(name, in.line(), "the first vertex id must be 0 or 1, not " + std::to_string(id));
      base = id;
    } else if (id != base + v) {
      fail_at_line(name, in.line(),
                   "vertex id " + std::to_string(id) + " where " + std::to_string(base + v) +
                       " was expected (ids are consecutive)");
    }
    for (int k = 0; k < 3; ++k) mesh.positions.push_back(in.number("a coordinate"));
    for (long long k = 0; k < attributes + markers; ++k) in.number("an attribute");
  }
  if (!in.at_end())
    fail_at_line(name, in.line(), "content after the " + std::to_string(count) + " vertices the header declares");
  return base;
}

void read_cells(std::string_view text, const std::string& name, long long base, VolumeMesh& mesh) {
  text = prepare_text(text, name);
  TokenStream in(text, name);
  const long long cells = header_count(in, name, "cell count");
  in.skip_line();
  VolumeBuilder builder(mesh);
  const uint64_t vertices = mesh.num_vertices();
  std::vector<uint32_t> loop;
  for (long long c = 0; c < cells; ++c) {
    in.integer("cell id");
    const long long faces = header_count(in, name, "face count");
    for (long long f = 0; f < faces; ++f) {
      in.integer("face id");
      const long long n = header_count(in, name, "face vertex count");
      loop.clear();
      for (long long k = 0; k < n; ++k) {
        const long long id = in.integer("vertex id");
        if (id < base || uint64_t(id - base) >= vertices)
          fail_at_line(name, in.line(),
                       "cell " + std::to_string(c) + ": vertex id " + std::to_string(id) + " out of range (ids " +
                           std::to_string(base) + " to " + std::to_string(base + (long long)vertices - 1) + ")");
        loop.push_back(static_cast<uint32_t>(id - base));
      }
      builder.add_face(loop.data(), loop.size());
    }
    builder.end_cell();
  }
  if (!in.at_end())
    fail_at_line(name, in.line(), "content after the " + std::to_string(cells) + " cells the header declares");
}

}  // namespace

VolumeReadResult read_node_ele(std::string_view node_text, std::string_view ele_text, const std::string& node_name,
                               const std::string& ele_name) {
  return run_volume_reader([&](VolumeMesh& mesh) {
    const long long base = read_nodes(node_text, node_name, mesh);
    read_cells(ele_text, ele_name, base, mesh);
  });
}

}  // namespace kergen
