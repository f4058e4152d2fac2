// The file access rule's two hooks for a distributed render (lang/file_access.h): rank 0
// is told of each name as it is granted, and a worker's replay waits for names it lacks.
#include "lang/file_access.h"

#include "../temp_dir.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace lucent;
using lucent::test::TempDir;

TEST_CASE(
    "file access: the observer hears each new name once, as it is granted, and no refused one",
    "[lang][file-access]") {
  TempDir dir("access");
  dir.write("a.obj", "v 0 0 0\n");
  dir.write("sub/b.png", "png");
  std::vector<FileGrant> told;
  const FileAccess files(dir.path, {}, nullptr, [&](const FileGrant& g) { told.push_back(g); });
  const std::filesystem::path folder = canonicalPath(dir.path);

  REQUIRE(files.resolve("a.obj", dir.path).error.empty());
  REQUIRE(told.size() == 1);
  CHECK(told[0] == FileGrant{"a.obj", folder, folder / "a.obj"});
  REQUIRE(files.resolve("a.obj", dir.path).error.empty());  // the same name again
  CHECK(told.size() == 1);
  REQUIRE(files.resolve("./a.obj", dir.path).error.empty());  // another name of the same file
  CHECK(told.size() == 2);
  CHECK_FALSE(files.resolve("missing.obj", dir.path).error.empty());
  CHECK_FALSE(files.resolve("../outside.obj", dir.path).error.empty());
  CHECK(told.size() == 2);
  REQUIRE(files.resolve("b.png", dir.path / "sub").error.empty());
  REQUIRE(told.size() == 3);
  CHECK(told[2].base == folder / "sub");
  CHECK(told == files.grants());
}

TEST_CASE("file access: a replay asks for more names until it has the one asked, or no more come",
          "[lang][file-access]") {
  TempDir dir("replay");
  FileReplay replay;
  replay.root = canonicalPath(dir.path);
  // The names rank 0 granted, arriving one at a time as a worker asks.
  std::vector<FileGrant> stream = {{"inc.xml", "/scenes", "/scenes/inc.xml"},
                                   {"m.ply", "/scenes", "/scenes/meshes/m.ply"}};
  size_t arrived = 0;
  int asked = 0;
  replay.more = [&] {
    ++asked;
    if (arrived == stream.size()) return false;
    replay.grants.push_back(stream[arrived++]);
    return true;
  };
  const FileAccess files(replay.root / "scenes", {}, &replay);

  const FileAccess::Resolved m = files.resolve("m.ply", replay.root / "scenes");
  REQUIRE(m.error.empty());
  CHECK(m.path == replay.root / "scenes/meshes/m.ply");
  CHECK(arrived == 2);  // it waited past inc.xml for m.ply
  CHECK(asked == 2);
  const FileAccess::Resolved inc = files.resolve("inc.xml", replay.root / "scenes");
  REQUIRE(inc.error.empty());  // already there: not asked again
  CHECK(asked == 2);
  const FileAccess::Resolved none = files.resolve("none.png", replay.root / "scenes");
  CHECK(none.path.empty());
  CHECK(none.error == "'none.png' (from '/scenes') is not among the files the first process sent");
  CHECK(asked == 3);  // asked once more, and told none will come
  // Without `more`, a name not granted is refused at once.
  FileReplay fixed;
  fixed.root = replay.root;
  fixed.grants = stream;
  const FileAccess plain(fixed.root / "scenes", {}, &fixed);
  CHECK(plain.resolve("m.ply", fixed.root / "scenes").error.empty());
  CHECK_FALSE(plain.resolve("none.png", fixed.root / "scenes").error.empty());
}
