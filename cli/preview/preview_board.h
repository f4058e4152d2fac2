// What the preview page is shown, kept as its current state rather than as a queue of
// updates: the latest picture (a coarse pass or a finished image), the tiles rendered
// since it, and the latest status. Each browser connection reads what changed since its
// own last read. A slow browser skips the states it was too slow to see, and the render
// never waits for it: the board holds one picture and at most one entry per tile, however
// many connections lag and however long.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace lucent::preview {

class PreviewBoard {
 public:
  // A picture of the whole image (`json`, the event's data), replacing the picture and
  // every tile.
  void publishImage(std::string json);
  // A tile (named by `key`) drawn over the picture; replaces an older entry of that key.
  void publishTile(const std::string& key, std::string json);
  // The status (progress, time, figures, messages), replacing the last one.
  void publishStatus(std::string json);
  // POV-Ray's render and the difference (--compare), replacing the last ones.
  void publishComparison(std::string json);

  // Server-sent events of every entry newer than `cursor`, oldest first, into `out`, and
  // `cursor` moved past them; waits up to `wait` for one (out is then empty). False once
  // the board is closed.
  bool collect(uint64_t& cursor, std::chrono::milliseconds wait, std::string& out);
  // Ends every collect (the server is stopping).
  void close();

  // The bytes of event data held (for the tests of its bound).
  size_t bytesHeld() const;

 private:
  struct Entry {
    uint64_t seq = 0;
    std::string event, data;
  };
  void changed();

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  uint64_t seq_ = 0;
  bool closed_ = false;
  std::optional<Entry> image_, status_, comparison_;
  std::map<std::string, Entry> tiles_;
};

}  // namespace lucent::preview
