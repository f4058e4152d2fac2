// The checkpoint file: what is written reads back the same; a record cut short or damaged is
// dropped with what follows it, never the records before; what differs between two
// identities is said key by key.
#include "app/checkpoint.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace lucent;
namespace fs = std::filesystem;

namespace {

Image tileImage(int w, int h, float base) {
  Image image(w, h);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = Color(base + i, -base, 1e-30f * i);
  return image;
}

struct TempFolder {
  fs::path path =
      fs::temp_directory_path() / fs::path("lucent-checkpoint-test-" + std::to_string(::getpid()));
  TempFolder() { fs::create_directories(path); }
  ~TempFolder() { fs::remove_all(path); }
};

const Identity kRun = {{"scene", "a.xml"}, {"--samples", "16"}};

}  // namespace

TEST_CASE("a checkpoint reads back the tiles, frames and identities written",
          "[render][checkpoint]") {
  TempFolder tmp;
  const std::string path = (tmp.path / "out.png.checkpoint").string();
  CheckpointWriter w(path, kRun);
  CHECK_FALSE(fs::exists(path));  // nothing until the first save
  w.beginFrame(1, {{"frame", "1"}});
  w.addTile(1, {0, 0, 4, 3}, tileImage(4, 3, 1.0f));
  w.save();
  CHECK(fs::exists(path));
  w.addTile(1, {4, 0, 6, 3}, tileImage(2, 3, 7.0f));
  w.frameWritten(1);
  w.beginFrame(2, {{"frame", "2"}, {"digest of x.png", "00ff"}});
  w.save();

  const CheckpointContents c = readCheckpoint(path);
  CHECK(c.run == kRun);
  CHECK_FALSE(c.torn);
  REQUIRE(c.frames.size() == 2);
  const auto& f1 = c.frames.at(1);
  CHECK(f1.written);
  CHECK(f1.identity == Identity{{"frame", "1"}});
  REQUIRE(f1.tiles.size() == 2);
  CHECK(f1.tiles[1].first == PixelRect{4, 0, 6, 3});
  const Image expected = tileImage(2, 3, 7.0f);
  CHECK(std::memcmp(f1.tiles[1].second.pixels.data(), expected.pixels.data(),
                    expected.pixels.size() * sizeof(Color)) == 0);
  CHECK_FALSE(c.frames.at(2).written);
  CHECK(c.frames.at(2).identity.size() == 2);
  CHECK(c.validBytes == static_cast<long long>(fs::file_size(path)));

  w.remove();
  CHECK_FALSE(fs::exists(path));
}

TEST_CASE("a record cut short or damaged is dropped with what follows it", "[render][checkpoint]") {
  TempFolder tmp;
  const std::string path = (tmp.path / "c.checkpoint").string();
  CheckpointWriter w(path, kRun);
  w.beginFrame(1, {{"frame", "1"}});
  w.addTile(1, {0, 0, 8, 8}, tileImage(8, 8, 0.5f));
  w.save();
  const auto whole = static_cast<long long>(fs::file_size(path));
  w.addTile(1, {8, 0, 16, 8}, tileImage(8, 8, 2.5f));
  w.save();
  const auto two = static_cast<long long>(fs::file_size(path));

  SECTION("cut inside the last record") {
    fs::resize_file(path, static_cast<uintmax_t>(two - 10));
    const CheckpointContents c = readCheckpoint(path);
    CHECK(c.torn);
    CHECK(c.validBytes == whole);
    CHECK(c.frames.at(1).tiles.size() == 1);
    // Continuing cuts the torn end before appending, so the next record reads.
    CheckpointWriter again = CheckpointWriter::continuing(path, c);
    again.addTile(1, {16, 0, 24, 8}, tileImage(8, 8, 4.5f));
    again.save();
    const CheckpointContents d = readCheckpoint(path);
    CHECK_FALSE(d.torn);
    REQUIRE(d.frames.at(1).tiles.size() == 2);
    CHECK(d.frames.at(1).tiles[1].first == PixelRect{16, 0, 24, 8});
  }
  SECTION("a flipped byte inside the last record's pixels") {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(two - 40);
    f.put('\x5a');
    f.close();
    const CheckpointContents c = readCheckpoint(path);
    CHECK(c.torn);
    CHECK(c.frames.at(1).tiles.size() == 1);
  }
  SECTION("a record length beyond any tile is not allocated") {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(whole + 8);
    const uint64_t huge = ~uint64_t(0) >> 1;
    f.write(reinterpret_cast<const char*>(&huge), 8);
    f.close();
    const CheckpointContents c = readCheckpoint(path);
    CHECK(c.torn);
    CHECK(c.frames.at(1).tiles.size() == 1);
  }
}

TEST_CASE("a file that is not a checkpoint is refused by name", "[render][checkpoint]") {
  TempFolder tmp;
  const std::string path = (tmp.path / "x.checkpoint").string();
  std::ofstream(path) << "lucent checkpoint 1\nscene\ta.xml\n";  // the header never ends
  CHECK_THROWS_WITH(readCheckpoint(path), Catch::Contains("is not a Lucent checkpoint"));
  std::ofstream(path) << "PNG";
  CHECK_THROWS_WITH(readCheckpoint(path),
                    Catch::Contains("'" + path + "' is not a Lucent checkpoint"));
  CHECK_THROWS_WITH(readCheckpoint(path + ".missing"),
                    Catch::Contains("cannot read the checkpoint"));
}

TEST_CASE("identity differences name each key that changed, appeared or went",
          "[render][checkpoint]") {
  const Identity saved = {{"a", "1"}, {"b", "2"}, {"c", "3"}};
  const Identity current = {{"a", "1"}, {"b", "5"}, {"d", "4"}};
  const std::vector<std::string> d = identityDifferences(saved, current);
  REQUIRE(d.size() == 3);
  CHECK(d[0] == "b: '2' in the checkpoint, '5' in this render");
  CHECK(d[1] == "d: not in the checkpoint, '4' in this render");
  CHECK(d[2] == "c: '3' in the checkpoint, not in this render");
  CHECK(identityDifferences(saved, saved).empty());
}
