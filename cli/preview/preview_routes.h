// What the preview's server answers: every request must carry the token (403 without it);
// "/" is the page, "/events" the stream of the board's events, POST "/save" writes the last
// finished image (last_image.h), POST "/set?name=N&value=V" sets a slider
// (preview_controls.h) and calls `changed`, POST "/region?region=X0,Y0,X1,Y1" renders only
// that rectangle from now on (without: the whole image again), anything else 404.
#pragma once

#include "http_server.h"
#include "last_image.h"
#include "preview_board.h"
#include "preview_controls.h"

#include <string>

namespace lucent::preview {

struct PreviewPlaces {
  PreviewBoard& board;
  const LastImage& last;
  PreviewControls& controls;
  std::function<void()> changed;
};
HttpHandler previewRoutes(const std::string& token, PreviewPlaces places);

// A stream of the board's events from the start (each connection gets the current state
// first, then what changes), with a comment line after a quiet second, so that a closed
// connection is noticed.
class BoardStream : public EventStream {
 public:
  explicit BoardStream(PreviewBoard& board) : board_(board) {}
  bool next(std::string& text) override;

 private:
  PreviewBoard& board_;
  uint64_t cursor_ = 0;
};

}  // namespace lucent::preview
