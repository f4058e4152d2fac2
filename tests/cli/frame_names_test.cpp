// The files an animation's frames are written to, and the --frames ranges a render takes.
#include "cli/frame_names.h"
#include "cli/exit_status.h"
#include "cli/frame_range.h"

#include <catch2/catch.hpp>

using namespace lucent::cli;

TEST_CASE("frame names: the number goes before the extension, at least 4 digits",
          "[cli][animation]") {
  CHECK(frameOutputPath("out.png", 1, 24) == "out0001.png");
  CHECK(frameOutputPath("out.png", 24, 24) == "out0024.png");
  CHECK(frameOutputPath("shots/take.v2.exr", 7, 10) == "shots/take.v20007.exr");
  CHECK(frameOutputPath("/abs/a.png", 3, 3) == "/abs/a0003.png");
}

TEST_CASE("frame names: a run of # is replaced by the padded number", "[cli][animation]") {
  CHECK(frameOutputPath("shots/f_###.exr", 1, 24) == "shots/f_001.exr");
  CHECK(frameOutputPath("f_#.png", 9, 9) == "f_9.png");
  CHECK(frameOutputPath("f_##_x.png", 5, 24) == "f_05_x.png");
  // Only the last run, and only in the file name, not its folders.
  CHECK(frameOutputPath("a#/b##c##.png", 3, 10) == "a#/b##c03.png");
}

TEST_CASE("frame names: the number is padded to the digits the last frame needs",
          "[cli][animation]") {
  CHECK(frameOutputPath("f_##.png", 7, 120) == "f_007.png");
  CHECK(frameOutputPath("f_##.png", 120, 120) == "f_120.png");
  CHECK(frameOutputPath("out.png", 1, 12345) == "out00001.png");
  CHECK(frameOutputPath("out.png", 12345, 12345) == "out12345.png");
}

TEST_CASE("frame ranges: F and A..B", "[cli][animation]") {
  FrameRange one = parseFrameRange("5");
  CHECK(one.first == 5);
  CHECK(one.last == 5);
  CHECK(one.count() == 1);
  FrameRange range = parseFrameRange("2..24");
  CHECK(range.first == 2);
  CHECK(range.last == 24);
  CHECK(range.count() == 23);
  CHECK_NOTHROW(checkFrameRange(range, "--frames 2..24", 24, true));
  CHECK_NOTHROW(checkFrameRange(parseFrameRange("1"), "--frames 1", 1, false));
  CHECK(singleFrame(3).first == 3);
  CHECK_THROWS_WITH(singleFrame(0), "--frame 0: frames are numbered from 1");
}

TEST_CASE("frame ranges: what is not a range is a usage error saying why", "[cli][animation]") {
  auto message = [](const std::string& text) {
    try {
      parseFrameRange(text);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string syntax =
      ": expected a frame F or a range A..B of whole numbers (as --frames 5 "
      "or --frames 1..24)";
  for (const char* bad :
       {"", "x", "1..", "..4", "1...4", "-3", "1.5", "1e2", " 2", "2..x", "1..2..3", "99999999999"})
    CHECK(message(bad) == std::string("--frames ") + bad + syntax);
  CHECK(message("0") == "--frames 0: frames are numbered from 1");
  CHECK(message("0..3") == "--frames 0..3: frames are numbered from 1");
  CHECK(message("5..3") == "--frames 5..3: the first frame 5 comes after the last 3");
}

TEST_CASE("frame ranges: beyond the scene's frames is a usage error", "[cli][animation]") {
  auto message = [](const std::string& text, int frames, bool animated) {
    try {
      checkFrameRange(parseFrameRange(text), "--frames " + text, frames, animated);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message("20..25", 24, true) == "--frames 20..25: the animation has 24 frames (1..24)");
  CHECK(message("2", 1, true) == "--frames 2: the animation has 1 frame (1..1)");
  CHECK(message("2", 1, false) == "--frames 2: the scene has no <animation>, so only frame 1");
  CHECK(message("1..1", 1, false) == "no error");
}
