// stl.cpp — the STL reader (read_stl), binary and ASCII (3D Systems, "StereoLithography Interface
// Specification", 1989). An STL stores every triangle's corners separately: they are welded by exact
// equality of their coordinates (util/point_table.h). Binary or ASCII is decided by the content,
// not by the "solid" many binary headers start with.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "io/numbers.h"
#include "io/reader.h"
#include "io/text_scan.h"
#include "kergen/io.h"
#include "util/plural.h"
#include "util/point_table.h"

namespace kergen {

using namespace io;  // the readers' shared parts: reader.h, text_scan.h, numbers.h

namespace io {

bool starts_with_solid(std::string_view bytes) {
  if (bytes.size() >= 3 && bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  size_t i = 0;
  while (i < bytes.size() && (is_blank(bytes[i]) || bytes[i] == '\n')) ++i;
  return bytes.size() - i >= 5 && equals_ignore_case(bytes.substr(i, 5), "solid") &&
         (bytes.size() - i == 5 || is_blank(bytes[i + 5]) || bytes[i + 5] == '\n');
}

}  // namespace io

namespace {

// Welds vertices that have exactly the same coordinates (an STL stores every triangle's corners
// separately), numbered in the order they are first met. -0.0 and 0.0 are the same point.
class VertexWelder {
 public:
  explicit VertexWelder(std::vector<double>& positions, size_t expected_vertices)
      : positions_(positions), table_(expected_vertices) {}
  // A corner, its coordinates with -0.0 turned into +0.0 (adding +0.0 does it, round-to-nearest),
  // and its hash: what add() needs, computed ahead of it by binary STL's blocks.
  struct Corner {
    double xyz[3];
    uint64_t hash;
  };
  static Corner corner(double x, double y, double z) {
    Corner c{{x + 0.0, y + 0.0, z + 0.0}, 0};
    c.hash = PointTable::hash(c.xyz);
    return c;
  }
  void prefetch(const Corner& c) const { table_.prefetch_slot(c.hash); }
  void prefetch_held(const Corner& c) const { table_.prefetch_held(positions_.data(), c.hash); }
  uint32_t add(double x, double y, double z) { return add(corner(x, y, z)); }
  uint32_t add(const Corner& c) {
    const size_t count = positions_.size() / 3;
    if (count >= std::numeric_limits<uint32_t>::max()) {
      const uint32_t found = table_.find(positions_.data(), c.xyz, c.hash);
      if (found != PointTable::kEmpty) return found;
      fail(Error::TooLarge, "more than 4294967295 distinct vertices");
    }
    const uint32_t id = table_.find_or_insert(positions_.data(), c.xyz, c.hash, uint32_t(count));
    if (id == count) positions_.insert(positions_.end(), c.xyz, c.xyz + 3);
    return id;
  }

 private:
  std::vector<double>& positions_;
  PointTable table_;
};

float read_le_float(const unsigned char* p) {
  uint32_t bits = read_le32(p);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// Triangles are read in blocks: their corners hashed and their table slots prefetched first,
// then welded in order (the table is larger than the caches on big files).
void parse_binary_stl(std::string_view bytes, uint32_t triangle_count, const std::string& name, Mesh& mesh) {
  if (triangle_count == 0) fail(Error::EmptyInput, name + ": no triangles");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  // A closed mesh has about half as many vertices as triangles.
  const size_t expected_vertices = std::min<size_t>(triangle_count / 2 + 16, size_t(1) << 24);
  VertexWelder welder(mesh.positions, expected_vertices);
  mesh.positions.reserve(3 * expected_vertices);
  mesh.indices.resize(3 * size_t(triangle_count));
  uint32_t* index_out = mesh.indices.data();
  constexpr uint32_t kBlock = 32;
  VertexWelder::Corner corners[3 * kBlock];
  for (uint32_t first = 0; first < triangle_count; first += kBlock) {
    const uint32_t n = std::min(kBlock, triangle_count - first);
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t t = first + i;
      const size_t record = 84 + 50 * size_t(t);
      for (int corner = 0; corner < 3; ++corner) {
        const size_t offset = record + 12 + 12 * size_t(corner);  // after the 12-byte normal
        double xyz[3];
        for (int k = 0; k < 3; ++k) {
          float value = read_le_float(data + offset + 4 * k);
          if (!std::isfinite(value))
            fail_at_byte(
                name, offset + 4 * k,
                "non-finite coordinate in triangle " + std::to_string(t) + " (vertex " + std::to_string(corner) + ")");
          xyz[k] = static_cast<double>(value);  // exact: every float is a double
        }
        corners[3 * i + corner] = VertexWelder::corner(xyz[0], xyz[1], xyz[2]);
        welder.prefetch(corners[3 * i + corner]);
      }
    }
    for (uint32_t c = 0; c < 3 * n; ++c) welder.prefetch_held(corners[c]);
    for (uint32_t c = 0; c < 3 * n; ++c) *index_out++ = welder.add(corners[c]);
  }
}

// "normal nx ny nz" after "facet". The normal is recomputed by everyone; it only has to be three
// numbers (some exporters write nan for degenerate facets, which is harmless here).
void read_facet_normal(Tokens& tokens, const std::string& name, size_t line_number) {
  std::string_view word;
  if (!tokens.next(word) || !equals_ignore_case(word, "normal"))
    fail_at_line(name, line_number, "expected 'facet normal nx ny nz'");
  for (int k = 0; k < 3; ++k) {
    std::string_view token;
    double ignored;
    if (!tokens.next(token)) fail_at_line(name, line_number, "facet normal needs 3 components");
    if (parse_double(token, ignored) == NumberStatus::Invalid)
      fail_at_line(name, line_number, "invalid number " + quoted(token));
  }
}

void parse_ascii_stl(std::string_view text, const std::string& name, Mesh& mesh) {
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  enum class State { OutsideSolid, InSolid, InFacet, InLoop, AfterLoop };
  State state = State::OutsideSolid;
  LineReader lines(text);
  std::string_view line;
  // A facet line is about 200 bytes of text; a generous guess keeps rehashing rare.
  VertexWelder welder(mesh.positions, text.size() / 200 + 16);
  VertexWelder::Corner corners[3];
  // Finished facets' corners are welded a block at a time, their table slots prefetched when the
  // facet ends (binary STL's scheme). The weld's only failure, more than 2^32 - 1 distinct
  // vertices, then shows up to kBlock facets later, which no file under ~400 GB can reach.
  constexpr size_t kBlock = 32;
  std::vector<VertexWelder::Corner> pending;
  pending.reserve(3 * kBlock);
  auto weld_pending = [&] {
    for (const auto& c : pending) mesh.indices.push_back(welder.add(c));
    pending.clear();
  };
  int corner_count = 0;
  auto expect_end = [&](Tokens& tokens, std::string_view keyword) {
    std::string_view extra;
    if (tokens.next(extra))
      fail_at_line(name, lines.line_number(), "unexpected " + quoted(extra) + " after '" + std::string(keyword) + "'");
  };
  while (lines.next(line)) {
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    const size_t line_number = lines.line_number();
    auto unexpected = [&](const char* expected) {
      fail_at_line(name, line_number, "expected " + std::string(expected) + ", found " + quoted(keyword));
    };
    switch (state) {
      case State::OutsideSolid:
        if (!equals_ignore_case(keyword, "solid")) unexpected("'solid'");
        state = State::InSolid;  // the rest of the line is the solid's name
        break;
      case State::InSolid:
        if (equals_ignore_case(keyword, "endsolid")) {
          state = State::OutsideSolid;
        } else if (equals_ignore_case(keyword, "facet")) {
          read_facet_normal(tokens, name, line_number);
          expect_end(tokens, "facet normal");
          state = State::InFacet;
        } else {
          unexpected("'facet' or 'endsolid'");
        }
        break;
      case State::InFacet: {
        std::string_view word;
        if (!equals_ignore_case(keyword, "outer") || !tokens.next(word) || !equals_ignore_case(word, "loop"))
          fail_at_line(name, line_number, "expected 'outer loop', found " + quoted(keyword));
        expect_end(tokens, "outer loop");
        state = State::InLoop;
        corner_count = 0;
        break;
      }
      case State::InLoop:
        if (equals_ignore_case(keyword, "vertex")) {
          if (corner_count == 3) fail_at_line(name, line_number, "facet has more than 3 vertices");
          double xyz[3];
          read_coordinates(tokens, xyz, name, line_number, "vertex");
          expect_end(tokens, "vertex x y z");
          corners[corner_count++] = VertexWelder::corner(xyz[0], xyz[1], xyz[2]);
        } else if (equals_ignore_case(keyword, "endloop")) {
          if (corner_count != 3)
            fail_at_line(name, line_number,
                         "facet has " + count_of(corner_count, "vertex", "vertices") + " (3 needed)");
          expect_end(tokens, "endloop");
          state = State::AfterLoop;
        } else {
          unexpected("'vertex' or 'endloop'");
        }
        break;
      case State::AfterLoop:
        if (!equals_ignore_case(keyword, "endfacet")) unexpected("'endfacet'");
        expect_end(tokens, "endfacet");
        for (const auto& c : corners) {
          welder.prefetch(c);
          pending.push_back(c);
        }
        if (pending.size() == 3 * kBlock) weld_pending();
        state = State::InSolid;
        break;
    }
  }
  weld_pending();
  // A missing final "endsolid" is tolerated (common in hand-written files); a cut facet is not.
  if (state != State::OutsideSolid && state != State::InSolid)
    fail_at_line(name, lines.line_number(), "unexpected end of file inside a facet");
  if (mesh.indices.empty()) fail(Error::EmptyInput, name + ": no facets");
}

[[noreturn]] void fail_binary_size(std::string_view bytes, const std::string& name) {
  const uint64_t declared = read_le32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
  const uint64_t room = (bytes.size() - 84) / 50;
  fail_at_byte(name, 80,
               "binary STL header declares " + count_of(declared, "triangle", "triangles") + " (" +
                   count_of(84 + 50 * declared, "byte", "bytes") + ") but the file has " +
                   count_of(bytes.size(), "byte", "bytes") + " (room for " + count_of(room, "triangle", "triangles") +
                   ")");
}

void parse_stl(std::string_view bytes, const std::string& name, Mesh& mesh) {
  if (bytes.empty()) fail(Error::EmptyInput, name + ": empty file");
  // Binary vs ascii is decided by content: many binary files start their header with "solid" too.
  if (bytes.size() >= 84) {
    const uint32_t declared = read_le32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
    if (84 + 50 * uint64_t(declared) == bytes.size()) return parse_binary_stl(bytes, declared, name, mesh);
  }
  if (starts_with_solid(bytes)) {
    try {
      parse_ascii_stl(bytes, name, mesh);
      return;
    } catch (const ReadFailure& failure) {
      // A NUL byte means binary data whose header happens to start with "solid": the real problem
      // is then its triangle count, not its "text".
      if (failure.error == Error::ParseError && bytes.size() >= 84 &&
          std::memchr(bytes.data(), '\0', bytes.size()) != nullptr)
        fail_binary_size(bytes, name);
      throw;
    }
  }
  if (bytes.size() < 84)
    fail_at_byte(name, 0,
                 "not an STL file: " + count_of(bytes.size(), "byte", "bytes") +
                     " is shorter than a binary STL header (84 bytes) and the text does not start with 'solid'");
  fail_binary_size(bytes, name);
}

}  // namespace

ReadResult read_stl(std::string_view bytes, const std::string& name) {
  return run_reader([&](ReadResult& r) { parse_stl(bytes, name, r.mesh); });
}

}  // namespace kergen
