// The checkpoint of a render: the tiles finished so far and their pixels, beside the output
// (OUT.checkpoint), so that `lucent render --resume` continues an interrupted render to the
// same bytes an uninterrupted one writes.
//
// The file is a header (the run's identity: what the pixels depend on, as key/value lines)
// followed by records appended as the render goes: a frame's start (that frame's identity:
// its number and the digests of the files it reads), finished tiles (their rectangle and
// float pixels) and a frame's end (its image was written). Each record ends with a digest of
// itself, and is flushed to disk before the next is written; a record cut short by a crash
// or a full disk fails its digest and is dropped on reading, with everything after it, so a
// crash during a write leaves the records before it usable: every write is all or nothing.
// The header is written to a temporary file and renamed into place.
#pragma once

#include "render/image.h"
#include "render/pixel_rect.h"

#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lucent {

// Tiles are at most this many pixels a side (--tile-size).
constexpr int kMaxTileSize = 4096;

// A checkpoint that cannot be read or written; the message names the file and the reason.
struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Key/value lines compared on --resume, in the order they were given.
using Identity = std::vector<std::pair<std::string, std::string>>;

// The differences between what a checkpoint was made for (`saved`) and this render
// (`current`), one line each ("samples: the checkpoint's 16, this render's 4"); empty when
// they match.
std::vector<std::string> identityDifferences(const Identity& saved, const Identity& current);

// The checkpoint beside an output image.
std::string checkpointPathFor(const std::string& output);

// What a checkpoint file holds, as read.
struct CheckpointContents {
  Identity run;
  struct Frame {
    Identity identity;
    std::vector<std::pair<PixelRect, Image>> tiles;  // finished, in the order written
    bool written = false;                            // the frame's image was written
  };
  std::map<int, Frame> frames;
  long long validBytes = 0;  // the length up to the last whole record
  bool torn = false;         // a record after validBytes was cut short (and is dropped)
};

// Reads a checkpoint; throws CheckpointError when the file is not one (or unreadable).
CheckpointContents readCheckpoint(const std::string& path);

// Writes a checkpoint as a render goes. Nothing is written until the first save(): a render
// that ends before then leaves no file. Not thread-safe: callers serialise.
class CheckpointWriter {
 public:
  // A new checkpoint at `path`, replacing any there at the first save.
  CheckpointWriter(std::string path, Identity run);
  // Continues the checkpoint read from `path` (its valid part is kept; a torn end is cut).
  static CheckpointWriter continuing(std::string path, const CheckpointContents& contents);
  ~CheckpointWriter();
  CheckpointWriter(CheckpointWriter&&) noexcept;
  CheckpointWriter& operator=(CheckpointWriter&&) = delete;
  CheckpointWriter(const CheckpointWriter&) = delete;

  // Queued until the next save().
  void beginFrame(int frame, const Identity& identity);
  void addTile(int frame, const PixelRect& rect, const Image& pixels);
  void frameWritten(int frame);
  bool pending() const { return !queue_.empty(); }

  // Appends the queued records and flushes them to disk. Throws CheckpointError.
  void save();
  // Deletes the file (the image it was for is written).
  void remove();
  const std::string& path() const { return path_; }

 private:
  CheckpointWriter() = default;
  void open();
  std::string path_;
  Identity run_;
  std::string queue_;  // encoded records not yet written
  std::FILE* file_ = nullptr;
  bool started_ = false;      // the header is on disk
  long long keepBytes_ = -1;  // continuing: the valid length to cut the file to first
};

}  // namespace lucent
