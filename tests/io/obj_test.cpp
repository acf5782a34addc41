// OBJ reading: the statement forms Proxima reads or skips, and an error with
// file and line for each kind of bad input.
#include "io/obj.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace prox::io {
namespace {

using Indices = std::vector<std::uint32_t>;

const char kSquare[] =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n";

ObjData parse_ok(const std::string& text) {
  ObjData out;
  const Status status = parse_obj(text, "test.obj", out);
  EXPECT_TRUE(status.is_ok()) << status.message();
  return out;
}

// Parses text that must fail, and returns the message.
std::string parse_error(const std::string& text) {
  ObjData out;
  const Status status = parse_obj(text, "bad.obj", out);
  EXPECT_EQ(status.code(), StatusCode::ParseError) << text;
  EXPECT_TRUE(out.positions.empty() && out.indices.empty());
  return status.message();
}

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

TEST(Obj, NumberForms) {
  const ObjData d = parse_ok("v 1e-3 -0.5 3\nv +2 .25 -1.5E+2\nv 0.1 0.2 0.3 1.0\nf 1 2 3\n");
  const std::vector<double> want = {1e-3, -0.5, 3.0, 2.0, 0.25, -150.0, 0.1, 0.2, 0.3};
  EXPECT_EQ(d.positions, want);  // every literal is read to the nearest double; w is dropped
}

TEST(Obj, FaceVertexForms) {
  const std::string vertices = std::string(kSquare) + "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n";
  for (const char* face : {"f 1 2 3\n", "f 1/1 2/2 3/3\n", "f 1//1 2//1 3//1\n", "f 1/1/1 2/2/1 3/3/1\n"}) {
    const ObjData d = parse_ok(vertices + face);
    EXPECT_EQ(d.indices, (Indices{0, 1, 2})) << face;
    EXPECT_EQ(d.positions.size(), 12u) << face;
  }
}

TEST(Obj, NegativeIndicesCountBackFromTheLastVertex) {
  // -1 is the latest vertex read at that point, not the last in the file.
  const ObjData d = parse_ok(std::string(kSquare) + "f -4 -3 -2\nv 5 5 5\nf -1/1 -4 -3//2\n");
  EXPECT_EQ(d.indices, (Indices{0, 1, 2, 4, 1, 2}));
}

TEST(Obj, PolygonsAreFanTriangulated) {
  const ObjData quad = parse_ok(std::string(kSquare) + "f 1 2 3 4\n");
  EXPECT_EQ(quad.indices, (Indices{0, 1, 2, 0, 2, 3}));
  const ObjData pentagon = parse_ok(std::string(kSquare) + "v 0.5 2 0\nf 1 2 3 5 4\n");
  EXPECT_EQ(pentagon.indices, (Indices{0, 1, 2, 0, 2, 4, 0, 4, 3}));
}

TEST(Obj, CommentsBlankLinesCrlfAndOtherStatements) {
  const std::string text =
      "# exported\r\n"
      "mtllib box.mtl\r\n"
      "\r\n"
      "o box\r\n"
      "g side\r\n"
      "   \t\r\n"
      "v 0 0 0 # a comment after data\r\n"
      "\tv  1\t0  0  \r\n"
      "v 1 1 0\r\n"
      "vt 0.5 0.5\r\n"
      "vn 0 0 1\r\n"
      "vp 0.1\r\n"
      "usemtl red\r\n"
      "s off\r\n"
      "l 1 2\r\n"
      "p 3\r\n"
      "curv 0 1 1 2\r\n"
      "f 1 2 3\r\n"
      "# f 3 2 1\r\n"
      "f 3 2 1";  // no newline at the end
  const ObjData d = parse_ok(text);
  EXPECT_EQ(d.positions, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0}));
  EXPECT_EQ(d.indices, (Indices{0, 1, 2, 2, 1, 0}));
}

TEST(Obj, EmptyTextHasNoTriangles) {
  const ObjData d = parse_ok("");
  EXPECT_TRUE(d.positions.empty());
  EXPECT_TRUE(d.indices.empty());
}

TEST(Obj, ErrorsNameFileAndLine) {
  struct Case {
    const char* text;
    const char* where;
    const char* what;
  };
  const Case cases[] = {
      {"v 0 0 0\nv 1 x 0\n", "bad.obj:2:", "'x'"},
      {"v 0 0 0\n\nv 1 2.5.1 0\n", "bad.obj:3:", "'2.5.1'"},
      {"v 1 2\n", "bad.obj:1:", "3 are needed"},
      {"v 1 2 nan\n", "bad.obj:1:", "non-finite"},
      {"v 1 2 1e999\n", "bad.obj:1:", "'1e999'"},
      {"v 0 0 0\r\nv 1 0 0\r\nf 1 2\r\n", "bad.obj:3:", "face has 2 vertices"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\n# comment\nf 0 1 2\n", "bad.obj:5:", "index 0"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "bad.obj:4:", "index 4"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n", "bad.obj:4:", "index -4"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1/a 2 3\n", "bad.obj:5:", "'1/a'"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/1/1/1\n", "bad.obj:4:", "'3/1/1/1'"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3//\n", "bad.obj:4:", "'3//'"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n", "bad.obj:4:", "'99999999999999999999'"},
  };
  for (const Case& c : cases) {
    const std::string message = parse_error(c.text);
    EXPECT_TRUE(contains(message, c.where)) << c.text << " -> " << message;
    EXPECT_TRUE(contains(message, c.what)) << c.text << " -> " << message;
  }
}

TEST(Obj, ReadsAFile) {
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "proxima_obj_test.obj";
  {
    std::ofstream file(path, std::ios::binary);
    file << kSquare << "f 1 2 3 4\n";
  }
  ObjData d;
  const Status status = read_obj(path.string(), d);
  EXPECT_TRUE(status.is_ok()) << status.message();
  EXPECT_EQ(d.positions.size(), 12u);
  EXPECT_EQ(d.indices, (Indices{0, 1, 2, 0, 2, 3}));
  std::filesystem::remove(path);
}

TEST(Obj, ErrorsInAFileNameThePath) {
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "proxima_obj_bad.obj";
  {
    std::ofstream file(path, std::ios::binary);
    file << kSquare << "f 1 2 7\n";
  }
  ObjData d;
  const Status status = read_obj(path.string(), d);
  EXPECT_EQ(status.code(), StatusCode::ParseError);
  EXPECT_TRUE(contains(status.message(), path.string() + ":5:")) << status.message();
  std::filesystem::remove(path);
}

TEST(Obj, UnreadableFileIsAnIoError) {
  const std::string missing = "/nonexistent/proxima/missing.obj";
  ObjData d;
  d.indices = {1, 2, 3};
  const Status status = read_obj(missing, d);
  EXPECT_EQ(status.code(), StatusCode::IoError);
  EXPECT_TRUE(contains(status.message(), missing)) << status.message();
  EXPECT_TRUE(d.indices.empty());

  // A directory opens on some systems but cannot be read.
  const Status dir = read_obj(testing::TempDir(), d);
  EXPECT_EQ(dir.code(), StatusCode::IoError) << dir.message();
}

}  // namespace
}  // namespace prox::io
