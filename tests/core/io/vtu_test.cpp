// The VTU reader (read_vtu): the linear cells and polyhedra in ascii, inline base64 (header and
// values encoded together or apart), appended raw and base64 data, UInt32/UInt64 headers, both
// byte orders, several pieces; its refusals (compressed, another dataset type, bad ids).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kergen/volume.h"
#include "volume/volume_test_util.h"

namespace {

using namespace volume_test;

// Each cell's kernel volume is its analytic volume (the linear cells are convex).
void expect_linear_cells(const kergen::VolumeReadResult& r) {
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.mesh.num_cells(), 5u);
  EXPECT_EQ(r.mesh.num_vertices(), 23u);
  const std::vector<double> want = LinearCells().volumes(), got = kernel_volumes(r.mesh);
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-15) << "cell " << i;
}

TEST(Vtu, AsciiLinearCellsAndPolyhedron) { expect_linear_cells(kergen::read_vtu(vtu_ascii(LinearCells()), "a.vtu")); }

// The same file in binary forms, written here from the same arrays.
std::string vtu_binary(const LinearCells& c, const std::string& mode, bool header64, bool big_endian) {
  const size_t h = header64 ? 8 : 4;
  std::string appended, xml;
  auto header = [&](size_t n) {
    std::string out;
    for (size_t i = 0; i < h; ++i) out.push_back(char(uint64_t(n) >> (8 * (big_endian ? h - 1 - i : i)) & 0xff));
    return out;
  };
  auto swap = [&](std::string bytes, size_t size) {
    if (big_endian)
      for (size_t i = 0; i < bytes.size(); i += size) std::reverse(bytes.begin() + i, bytes.begin() + i + size);
    return bytes;
  };
  auto array = [&](const std::string& attrs, std::string bytes, size_t size) {
    bytes = swap(bytes, size);
    std::string a = "<DataArray " + attrs;
    if (mode == "together" || mode == "apart") {
      const std::string text =
          mode == "together" ? base64(header(bytes.size()) + bytes) : base64(header(bytes.size())) + base64(bytes);
      return a + " format=\"binary\">\n  " + text + "\n</DataArray>\n";
    }
    a += " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>\n";
    appended += mode == "raw" ? header(bytes.size()) + bytes : base64(header(bytes.size()) + bytes);
    return a;
  };
  std::vector<int64_t> conn(c.connectivity.begin(), c.connectivity.end()), offs(c.offsets.begin(), c.offsets.end()),
      faces(c.faces.begin(), c.faces.end()), fo(c.faceoffsets.begin(), c.faceoffsets.end());
  std::vector<uint8_t> types(c.types.begin(), c.types.end());
  xml = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" byte_order=\"") +
        (big_endian ? "BigEndian" : "LittleEndian") + "\" header_type=\"" + (header64 ? "UInt64" : "UInt32") +
        "\">\n<UnstructuredGrid><Piece NumberOfPoints=\"" + std::to_string(c.points.size() / 3) +
        "\" NumberOfCells=\"5\">\n<Points>" +
        array("type=\"Float64\" NumberOfComponents=\"3\"", le_bytes(c.points, 8), 8) + "</Points><Cells>" +
        array("type=\"Int64\" Name=\"connectivity\"", le_bytes(conn, 8), 8) +
        array("type=\"Int64\" Name=\"offsets\"", le_bytes(offs, 8), 8) +
        array("type=\"UInt8\" Name=\"types\"", le_bytes(types, 1), 1) +
        array("type=\"Int64\" Name=\"faces\"", le_bytes(faces, 8), 8) +
        array("type=\"Int64\" Name=\"faceoffsets\"", le_bytes(fo, 8), 8) + "</Cells></Piece></UnstructuredGrid>\n";
  if (!appended.empty())
    xml += std::string("<AppendedData encoding=\"") + (mode == "raw" ? "raw" : "base64") + "\">\n _" + appended +
           "\n</AppendedData>\n";
  return xml + "</VTKFile>\n";
}

TEST(Vtu, BinaryForms) {
  for (const char* mode : {"together", "apart", "raw", "base64"})
    for (bool header64 : {false, true})
      for (bool big : {false, true}) {
        SCOPED_TRACE(std::string(mode) + (header64 ? " UInt64" : " UInt32") + (big ? " big" : " little"));
        expect_linear_cells(kergen::read_vtu(vtu_binary(LinearCells(), mode, header64, big), "b.vtu"));
      }
}

TEST(Vtu, SeveralPiecesConcatenate) {
  std::string one = vtu_ascii(LinearCells());
  const size_t begin = one.find("<Piece "), end = one.find("</Piece>") + 8;
  std::string two = one.substr(0, end) + one.substr(begin, end - begin) + one.substr(end);
  const kergen::VolumeReadResult r = kergen::read_vtu(two, "two.vtu");
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_cells(), 10u);
  EXPECT_EQ(r.mesh.num_vertices(), 46u);
  const std::vector<double> got = kernel_volumes(r.mesh);
  for (size_t i = 0; i < 5; ++i) EXPECT_EQ(got[i], got[i + 5]);
}

TEST(Vtu, Refusals) {
  const std::string good = vtu_ascii(LinearCells());
  auto expect = [](const std::string& text, const std::string& fragment) {
    const kergen::VolumeReadResult r = kergen::read_vtu(text, "x.vtu");
    EXPECT_EQ(r.error, kergen::Error::ParseError) << r.message;
    EXPECT_NE(r.message.find(fragment), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("x.vtu"), std::string::npos) << r.message;
  };
  std::string s = good;
  s.replace(s.find("10 12"), 2, "5 ");
  expect(s, "VTK cell type 5");
  s = good;
  s.replace(s.find("NumberOfCells=\"5\""), 17, "NumberOfCells=\"6\"");
  expect(s, "values, expected 6");
  s = good;
  s.replace(s.find("0 1 2 3 4"), 1, "99");
  expect(s, "point id 99 out of range");
  expect(good.substr(0, good.size() / 2), "truncated");
  expect("<VTKFile type=\"UnstructuredGrid\"></VTKFile>", "no <Piece>");
  expect("plain text </VTKFile>", "not a VTK XML file");
  EXPECT_EQ(kergen::read_vtu("  \n", "e.vtu").error, kergen::Error::EmptyInput);
}

}  // namespace
