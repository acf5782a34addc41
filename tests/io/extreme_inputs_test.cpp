// The text readers on inputs far past any real file, generated in memory: a
// line of 10^8 characters in an OBJ, a pose file of 10^7 lines. Each gives
// an answer or a clear error in bounded time and memory.
#include "io/obj.h"
#include "io/poses.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

namespace prox::io {
namespace {

constexpr std::size_t kLongLine = 100000000;  // 10^8 characters

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(ObjAtScale, ALineOfOneHundredMillionCharacters) {
  // A vertex whose x has 10^8 digits (1.000...0 then 5: rounds to 1), a
  // comment as long, then a triangle.
  std::string text = "v 1.";
  text.append(kLongLine - 8, '0');
  text += "5 0 0\n#";
  text.append(kLongLine, '#');
  text += "\nv 0 1 0\nv 0 0 1\nf 1 2 3\n";
  ObjData obj;
  const auto start = std::chrono::steady_clock::now();
  const Status status = parse_obj(text, "long.obj", obj);
  ASSERT_TRUE(status.is_ok()) << status.message();
  EXPECT_EQ(obj.positions.size(), 9u);
  EXPECT_EQ(obj.positions[0], 1.0);
  EXPECT_EQ(obj.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_LT(seconds_since(start), 30.0);  // linear: well under a second here

  // The same line, malformed at its end: the error names line 1 and quotes
  // the start of the 10^8-character token, not all of it.
  text = "v 1 2 ";
  text.append(kLongLine, '7');
  text += "x\n";
  const Status bad = parse_obj(text, "long.obj", obj);
  EXPECT_EQ(bad.code(), StatusCode::ParseError);
  EXPECT_EQ(bad.message(), "long.obj:1: malformed number '7777777777777777777777777777777777777777...' (" +
                               std::to_string(kLongLine + 1) + " characters)")
      << bad.message().substr(0, 200);
  EXPECT_TRUE(obj.positions.empty());
}

TEST(PosesAtScale, TenMillionLinesAreRefusedBeforeParsing) {
  // 10^7 valid poses: past kMaxPoses (10^6), refused by the counting pass
  // without parsing or storing any of them.
  const std::string line = "0 0 0 1 0 0 0\n";
  std::string text;
  text.reserve(line.size() * 10000000);
  for (int i = 0; i < 10000000; ++i) text += line;
  std::vector<PoseRecord> poses;
  const auto start = std::chrono::steady_clock::now();
  const Status status = parse_poses(text, "long.poses", poses);
  EXPECT_EQ(status.code(), StatusCode::ParseError);
  EXPECT_EQ(status.message(), "long.poses:1000001: more than 1000000 poses; split the path");
  EXPECT_TRUE(poses.empty());
  EXPECT_LT(seconds_since(start), 30.0);  // one pass over 140 MB
}

TEST(PosesAtScale, TheLimitItselfIsAcceptedAndCommentsDoNotCount) {
  std::string text = "# a path at the limit\n";
  for (std::size_t i = 0; i < kMaxPoses; ++i)
    text += i % 2 ? "1 0 0 1 0 0 0\n" : "0 0 0 1 0 0 0\n   # comment\n\n";
  std::vector<PoseRecord> poses;
  const Status status = parse_poses(text, "limit.poses", poses);
  ASSERT_TRUE(status.is_ok()) << status.message();
  EXPECT_EQ(poses.size(), kMaxPoses);
  EXPECT_EQ(poses[1].position[0], 1.0);
  text += "2 0 0 1 0 0 0\n";
  EXPECT_FALSE(parse_poses(text, "limit.poses", poses).is_ok());
}

}  // namespace
}  // namespace prox::io
